// Shared rooms end to end: a server on an ephemeral port, clients speaking the room protocol over
// Beast WebSockets. Join, say and the broadcast clip, late join, reconnect by token, and bad input
// (malformed JSON, oversized messages, floods), after which the room and the server still answer.
#include <utility>

#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "gestura/serve/room.hpp"
#include "gestura/serve/room_host.hpp"
#include "gestura/serve/server.hpp"
#include "support/http_client.hpp"

namespace gestura {
namespace {

namespace fs = std::filesystem;
namespace beast = boost::beast;
namespace asio = boost::asio;
using nlohmann::json;
using namespace std::chrono_literals;

// A blocking room client: messages are read one at a time with a deadline.
class Client {
 public:
  Client(int port, const std::string& room) : ws_(io_) {
    asio::ip::tcp::resolver resolver(io_);
    beast::get_lowest_layer(ws_).connect(*resolver.resolve("127.0.0.1", std::to_string(port)).begin());
    ws_.handshake("127.0.0.1", "/ws/room/" + room);
  }
  void send(const json& message) { send_text(message.dump()); }
  void send_text(const std::string& text, bool binary = false) {
    ws_.binary(binary);
    ws_.write(asio::buffer(text));
  }
  // The next message, or null when none came within `timeout` or the connection closed.
  json next(std::chrono::milliseconds timeout = 60s) {
    beast::get_lowest_layer(ws_).expires_after(timeout);
    beast::flat_buffer buffer;
    beast::error_code ec;
    ws_.read(buffer, ec);
    if (ec) {
      closed_ = ec != beast::error::timeout;
      return nullptr;
    }
    return json::parse(beast::buffers_to_string(buffer.data()));
  }
  // The next message of this type (others are skipped), or null.
  json next_of(const std::string& type, std::chrono::milliseconds timeout = 60s) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      json m = next(std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now()));
      if (m.is_null()) return m;
      if (m["type"] == type) return m;
    }
    return nullptr;
  }
  json join(const std::string& name, const std::string& look = "default") {
    send({{"type", "join"}, {"name", name}, {"look", look}});
    return next_of("welcome");
  }
  bool closed() const { return closed_; }
  void close() {
    beast::error_code ec;
    beast::get_lowest_layer(ws_).socket().close(ec);  // dropped, as a lost network drops it
  }

 private:
  asio::io_context io_;
  beast::websocket::stream<beast::tcp_stream> ws_;
  bool closed_ = false;
};

class RoomTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(fs::temp_directory_path() / ("gestura-room-test-" + std::to_string(::getpid())));
    fs::remove_all(*root_);
    serve::ServeOptions options;
    options.port = 0;
    options.data = (*root_ / "data").string();
    server_ = new serve::Server(options);
    server_->start();
  }
  static void TearDownTestSuite() {
    delete server_;
    fs::remove_all(*root_);
    delete root_;
  }
  static int port() { return server_->port(); }
  static void still_up() { EXPECT_EQ(test::http(port(), "GET", "/health").status, 200); }

  static inline serve::Server* server_ = nullptr;
  static inline fs::path* root_ = nullptr;
};

TEST_F(RoomTest, JoinWelcomesAndTellsTheOthers) {
  Client a(port(), "join-test");
  const json welcome = a.join("Ana", "ana");
  ASSERT_FALSE(welcome.is_null());
  EXPECT_EQ(welcome["room"], "join-test");
  EXPECT_EQ(welcome["you"]["seat"], 0);
  EXPECT_EQ(welcome["you"]["token"].get<std::string>().size(), 32u);
  EXPECT_TRUE(welcome["time"].is_number());
  ASSERT_EQ(welcome["participants"].size(), 1u);
  EXPECT_EQ(welcome["participants"][0]["look"], "ana");
  Client b(port(), "join-test");
  const json wb = b.join("Ben", "ben");
  EXPECT_EQ(wb["you"]["seat"], 1);
  EXPECT_EQ(wb["participants"].size(), 2u);
  const json joined = a.next_of("joined");
  ASSERT_FALSE(joined.is_null());
  EXPECT_EQ(joined["participant"]["name"], "Ben");
  EXPECT_EQ(joined["participant"]["look"], "ben");
  // Seats differ in place: the two avatars do not stand in one another.
  const json pa = welcome["participants"][0]["position"], pb = joined["participant"]["position"];
  EXPECT_GT(std::abs(pa[0].get<double>() - pb[0].get<double>()), 0.5);
  // The state is the server's: GET /api/rooms/NAME shows it.
  const auto state = test::http(port(), "GET", "/api/rooms/join-test");
  ASSERT_EQ(state.status, 200);
  EXPECT_EQ(json::parse(state.body)["participants"].size(), 2u);
}

TEST_F(RoomTest, SayBroadcastsOneTimedClipAndLateJoinersSeeItPlaying) {
  Client a(port(), "say-test"), b(port(), "say-test");
  const json wa = a.join("Ana");
  ASSERT_FALSE(wa.is_null());
  ASSERT_FALSE(b.join("Ben").is_null());
  a.send({{"type", "say"}, {"text", "Hello, my name is Anna. My mother lives in a big house near the school."}});
  const json pa = a.next_of("play", 120s), pb = b.next_of("play", 120s);
  ASSERT_FALSE(pa.is_null());
  ASSERT_FALSE(pb.is_null());
  EXPECT_EQ(pa["clip"], pb["clip"]);
  EXPECT_EQ(pa["start"], pb["start"]);  // one moment for everyone
  EXPECT_GT(pa["start"].get<double>(), pa["time"].get<double>());  // in the future: time to fetch the clip
  EXPECT_EQ(pa["participant"], wa["you"]["id"]);
  EXPECT_GT(pa["duration"].get<double>(), 1.0);
  ASSERT_FALSE(pa["glosses"].empty());
  EXPECT_EQ(pa["glosses"][0]["gloss"], "HELLO");
  const auto clip = test::http(port(), "GET", pa["url"].get<std::string>());
  ASSERT_EQ(clip.status, 200);
  EXPECT_EQ(clip.body.substr(0, 4), "glTF");
  EXPECT_LT(clip.body.size(), 200u * 1024);
  // A late joiner: the welcome says what plays and since when.
  Client c(port(), "say-test");
  const json wc = c.join("Chidi");
  ASSERT_FALSE(wc.is_null());
  ASSERT_EQ(wc["participants"].size(), 3u);
  ASSERT_EQ(wc["playing"].size(), 1u);
  EXPECT_EQ(wc["playing"][0]["clip"], pa["clip"]);
  EXPECT_EQ(wc["playing"][0]["start"], pa["start"]);
  // While A signs, the host turns to A.
  bool watched = false;
  for (int i = 0; i < 20 && !watched; ++i) {
    const json h = b.next_of("host", 5s);
    if (h.is_null()) break;
    watched = h["look_at"] == pa["participant"] && h["why"] == "signer" && h["rotations"].contains("skullbase");
  }
  EXPECT_TRUE(watched);
}

TEST_F(RoomTest, AReconnectWithTheTokenTakesTheSeatBack) {
  Client b(port(), "reconnect-test");
  std::string token, id;
  int seat = -1;
  {
    auto a = std::make_unique<Client>(port(), "reconnect-test");
    const json w = a->join("Ana");
    token = w["you"]["token"], id = w["you"]["id"], seat = w["you"]["seat"];
    ASSERT_FALSE(b.join("Ben").is_null());
    a->close();
  }
  const json away = b.next_of("away");
  ASSERT_FALSE(away.is_null());
  EXPECT_EQ(away["participant"], id);
  Client a2(port(), "reconnect-test");
  a2.send({{"type", "join"}, {"token", token}});
  const json w2 = a2.next_of("welcome");
  ASSERT_FALSE(w2.is_null());
  EXPECT_EQ(w2["you"]["id"], id);
  EXPECT_EQ(w2["you"]["seat"], seat);
  const json back = b.next_of("back");
  ASSERT_FALSE(back.is_null());
  EXPECT_EQ(back["participant"]["id"], id);
  // A wrong token is refused with a JSON error naming it.
  Client x(port(), "reconnect-test");
  x.send({{"type", "join"}, {"token", "0123456789abcdef0123456789abcdef"}});
  const json e = x.next_of("error");
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["error"]["field"], "token");
  // Leaving frees the seat and tells the others.
  a2.send({{"type", "leave"}});
  const json left = b.next_of("left");
  ASSERT_FALSE(left.is_null());
  EXPECT_EQ(left["participant"], id);
}

TEST_F(RoomTest, MalformedMessagesGetAJsonErrorAndTheConnectionStays) {
  Client a(port(), "bad-test");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"{not json", "message"},
      {"[1, 2]", "message"},
      {R"({"type": 5})", "type"},
      {R"({"type": "dance"})", "type"},
      {R"({"type": "say", "text": "hi"})", "type"},  // before joining
      {R"({"type": "join"})", "name"},
      {R"({"type": "join", "name": "A", "look": "/etc/passwd"})", "look"},
      {std::string(40, '[') + std::string(40, ']'), "message"},
  };
  for (const auto& [text, field] : cases) {
    a.send_text(text);
    const json e = a.next_of("error", 10s);
    ASSERT_FALSE(e.is_null()) << text;
    EXPECT_EQ(e["error"]["code"], field == "type" && text.find("say") != std::string::npos ? 409 : 400) << text;
    EXPECT_EQ(e["error"]["field"], field) << text;
  }
  // Binary bytes (a text frame must be UTF-8, or the WebSocket itself fails: RFC 6455 §8.1).
  a.send_text(std::string("\xff\xfe\x00\x01", 4), true);
  EXPECT_EQ(a.next_of("error", 10s)["error"]["field"], "message");
  ASSERT_FALSE(a.join("Ana").is_null());
  a.send({{"type", "say"}, {"text", std::string(5000, 'a')}});
  EXPECT_EQ(a.next_of("error", 10s)["error"]["code"], 413);
  a.send({{"type", "landmarks"}, {"pose", "no"}});
  EXPECT_EQ(a.next_of("error", 10s)["error"]["field"], "pose");
  a.send({{"type", "ping"}, {"t", 1.5}});
  const json pong = a.next_of("pong", 10s);
  ASSERT_FALSE(pong.is_null());
  EXPECT_EQ(pong["t"], 1.5);
  still_up();
}

TEST_F(RoomTest, OversizedMessagesAreRefusedAndHugeOnesCloseOnlyThatConnection) {
  Client a(port(), "big-test");
  ASSERT_FALSE(a.join("Ana").is_null());
  a.send_text(R"({"type": "say", "text": ")" + std::string(20000, 'a') + "\"}");
  const json e = a.next_of("error", 10s);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["error"]["code"], 413);
  EXPECT_EQ(e["error"]["field"], "message");
  a.send({{"type", "ping"}, {"t", 2}});
  EXPECT_FALSE(a.next_of("pong", 10s).is_null());
  // Past the hard limit the connection ends; the server and the room stay.
  Client big(port(), "big-test");
  ASSERT_FALSE(big.join("Big").is_null());
  try {
    big.send_text(std::string(3u << 20, ' '));
  } catch (const std::exception&) {
    // the server may close while we are still writing
  }
  EXPECT_TRUE(big.next(10s).is_null() || big.next(10s).is_null());
  still_up();
  a.send({{"type", "ping"}, {"t", 3}});
  EXPECT_FALSE(a.next_of("pong", 10s).is_null());
}

TEST_F(RoomTest, AFloodIsThrottledAndTheServerStaysUp) {
  Client flood(port(), "flood-test");
  ASSERT_FALSE(flood.join("Flood").is_null());
  int pongs = 0, busy = 0;
  try {
    for (int i = 0; i < 1000; ++i) flood.send({{"type", "ping"}, {"t", i}});
  } catch (const std::exception&) {
    // closed for flooding while we wrote: that is one of the answers allowed
  }
  for (;;) {
    const json m = flood.next(3s);
    if (m.is_null()) break;
    if (m["type"] == "pong") ++pongs;
    if (m["type"] == "error" && m["error"]["code"] == 429) ++busy;
  }
  EXPECT_LE(pongs, 100);  // the burst and what the rate refills, not a thousand
  EXPECT_GE(busy, 1);
  still_up();
  Client other(port(), "flood-test");
  EXPECT_FALSE(other.join("Other").is_null());
}

// A plausible Holistic frame: a person facing the camera, the right arm raised in front with the
// elbow bent, the left arm hanging (picture coordinates: x right, y down; the person's left is on
// the picture's right).
json landmarks_frame() {
  json pose = json::array();
  for (int i = 0; i < 33; ++i) pose.push_back({0.5, 0.5, 0.0, 0.9});
  const auto set = [&](int i, double x, double y, double z) { pose[static_cast<std::size_t>(i)] = {x, y, z, 0.95}; };
  set(7, 0.54, 0.2, 0.0), set(8, 0.46, 0.2, 0.0);      // ears
  set(11, 0.6, 0.35, 0.0), set(12, 0.4, 0.35, 0.0);    // shoulders
  set(13, 0.63, 0.55, 0.0), set(15, 0.64, 0.75, 0.0);  // left elbow, wrist: hanging
  set(14, 0.33, 0.5, -0.1), set(16, 0.36, 0.3, -0.2);  // right elbow out and down, wrist up in front
  set(23, 0.56, 0.8, 0.0), set(24, 0.44, 0.8, 0.0);    // hips
  return {{"type", "landmarks"}, {"pose", pose}, {"aspect", 1.0}};
}

TEST_F(RoomTest, LandmarksDriveTheAvatarForEveryoneAndMalformedOnesAreLocatedErrors) {
  Client a(port(), "capture-test"), b(port(), "capture-test");
  ASSERT_FALSE(a.join("Ana").is_null());
  ASSERT_FALSE(b.join("Ben").is_null());
  a.send(landmarks_frame());
  const json pose = b.next_of("pose", 120s);
  ASSERT_FALSE(pose.is_null());
  EXPECT_EQ(pose["participant"], "p1");
  for (const char* joint : {"r_shoulder", "r_elbow", "r_wrist", "l_shoulder", "vc4", "skullbase"}) {
    ASSERT_TRUE(pose["rotations"].contains(joint)) << joint;
    EXPECT_EQ(pose["rotations"][joint].size(), 4u) << joint;
  }
  // The raised right arm turned the shoulder far from rest; the hanging left one hardly.
  const auto turn = [&](const char* joint) { return 2.0 * std::acos(std::min(1.0, std::abs(pose["rotations"][joint][3].get<double>()))); };
  EXPECT_GT(turn("r_shoulder"), 0.6);
  EXPECT_GT(turn("r_elbow"), 0.6);
  EXPECT_LT(turn("l_shoulder"), 0.35);
  // A late joiner's welcome carries the pose.
  Client c(port(), "capture-test");
  EXPECT_TRUE(c.join("Chidi")["poses"].contains("p1"));
  // Malformed frames: an error naming the place; nothing is fitted.
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases{
      {[](json& m) { m["pose"].erase(m["pose"].size() - 1); }, "pose"},
      {[](json& m) { m["pose"][3][1] = "x"; }, "pose[3][1]"},
      {[](json& m) { m["pose"][5][0] = 1e300; }, "pose[5][0]"},
      {[](json& m) { m["pose"][6][3] = 7; }, "pose[6][3]"},
      {[](json& m) { m["pose"][2] = {1, 2}; }, "pose[2]"},
      {[](json& m) { m["right"] = json::array({{0.1, 0.2, 0.3}}); }, "right"},
      {[](json& m) { m["aspect"] = -1; }, "aspect"},
      {[](json& m) { m["colour"] = "red"; }, "colour"},
  };
  for (const auto& [spoil, field] : cases) {
    json m = landmarks_frame();
    spoil(m);
    a.send(m);
    const json e = a.next_of("error", 10s);
    ASSERT_FALSE(e.is_null()) << field;
    EXPECT_EQ(e["error"]["code"], 400) << field;
    EXPECT_EQ(e["error"]["field"], field) << e.dump();
  }
  // A text of 1e400 is infinity to a parser: still no crash, an error.
  a.send_text(R"({"type":"landmarks","pose":[[1e400,0,0]]})");
  EXPECT_FALSE(a.next_of("error", 10s).is_null());
  still_up();
}

TEST_F(RoomTest, ARoomHasSeatsAndANameOfItsOwnKind) {
  std::vector<std::unique_ptr<Client>> clients;
  for (int i = 0; i < 8; ++i) {
    clients.push_back(std::make_unique<Client>(port(), "full-test"));
    ASSERT_FALSE(clients.back()->join("P" + std::to_string(i)).is_null());
  }
  Client ninth(port(), "full-test");
  ninth.send({{"type", "join"}, {"name", "Ninth"}});
  const json e = ninth.next_of("error", 10s);
  ASSERT_FALSE(e.is_null());
  EXPECT_EQ(e["error"]["code"], 409);
  // A name with other characters is no room: the upgrade is refused with 400.
  EXPECT_THROW(Client(port(), "a%20b"), std::exception);
  EXPECT_EQ(test::http(port(), "GET", "/api/rooms/nobody-here").status, 404);
  EXPECT_EQ(test::http(port(), "GET", "/ws/room/x").status, 426);
}

TEST(RoomHost, WatchesWhoeverSignsAndKeepsToThem) {
  std::vector<serve::SeatView> seats(4);
  for (int k = 0; k < 4; ++k) seats[static_cast<std::size_t>(k)].position = serve::seat_place(k).position;
  serve::SeatView host;
  host.position = serve::seat_place(-1).position;
  LookState state;
  EXPECT_EQ(serve::choose_host_look(host, seats, -1, 0.0f, state).seat, -1);  // nobody signs: ahead
  seats[2].signing = true;
  const serve::HostLook first = serve::choose_host_look(host, seats, -1, 1.0f, state);
  EXPECT_EQ(first.seat, 2);
  EXPECT_EQ(first.why, "signer");
  EXPECT_NEAR(first.point.x, seats[2].position.x, 1e-4);
  seats[1].signing = true;  // a second signer nearer the middle: the host stays with the first
  EXPECT_EQ(serve::choose_host_look(host, seats, -1, 2.0f, state).seat, 2);
  seats[2].signing = false;
  EXPECT_EQ(serve::choose_host_look(host, seats, -1, 3.0f, state).seat, 1);
}

// The host walks (issue 17 item 4): its root follows a path planned on the room's floor among the
// seats, comes nearer the signer, keeps its radius from every seat, and ends facing the signer.
TEST(RoomHost, WalksAroundTheSeatsToFaceWhoeverSigns) {
  std::vector<vec3> places;
  for (int k = 0; k < 8; ++k) places.push_back(serve::seat_place(k).position);
  serve::RoomWorld world(places);
  const serve::Seat home = serve::seat_place(-1);
  for (const int signer : {0, 5, 6}) {  // the seats beside the host, further round, the furthest on the left
    const serve::Seat s = serve::seat_place(signer);
    serve::SeatView seat;
    seat.position = s.position;
    seat.yaw = s.yaw;
    const serve::HostStop to = serve::stop_facing(seat);
    const std::optional<serve::HostWalkPlan> plan = world.plan({home.position, home.yaw}, to);
    ASSERT_TRUE(plan) << signer;
    const RootTrajectory& body = plan->body;
    ASSERT_GT(body.size(), 30u);
    float nearest = 1e9f;  // from the root's centre to any seat's centre, all along the walk
    for (const vec3& p : body.positions)
      for (const vec3& q : places) nearest = std::min(nearest, glm::length(vec2(p.x - q.x, p.z - q.z)));
    for (const vec3& p : plan->path)
      for (const vec3& q : places) nearest = std::min(nearest, glm::length(vec2(p.x - q.x, p.z - q.z)));
    EXPECT_GE(nearest, serve::RoomWorld::kHostRadius + serve::RoomWorld::kSeatRadius - 0.01f) << signer;
    const vec3 start = body.positions.front(), end = body.positions.back();
    EXPECT_LT(glm::length(vec2(start.x - home.position.x, start.z - home.position.z)), 0.02f);
    EXPECT_LT(glm::length(vec2(end.x - to.position.x, end.z - to.position.z)), 0.05f) << signer;
    // 1.2 m from the signer, toward the middle: nearer than the host's place for every seat but its neighbours.
    EXPECT_NEAR(glm::length(end - s.position), 1.2f, 0.05f) << signer;
    EXPECT_GT(glm::dot(heading(s.yaw), glm::normalize(end - s.position)), std::cos(deg(36.0f))) << signer;
    if (glm::length(start - s.position) > 1.5f) {
      EXPECT_LT(glm::length(end - s.position), glm::length(start - s.position) - 0.3f) << signer;
    }
    EXPECT_GT(plan->length, 0.5f);
    // Ends facing the signer (their seat within 5°), and the middle of the walk moved the root.
    const vec3 to_signer = s.position - end;
    EXPECT_LT(std::abs(angle_difference(body.yaws.back(), std::atan2(to_signer.x, to_signer.z))), deg(5.0f)) << signer;
    EXPECT_GT(glm::length(body.position_at(body.duration() * 0.5f) - start), 0.2f);
  }
}

// The rooms start the walk when someone signs and tell every client: the walk clip's url, when it
// starts, where it goes; a late joiner sees it in the room's state.
TEST(RoomHost, SomeoneSigningSendsTheHostWalkingToThem) {
  serve::RoomServices services;
  services.say = [](const std::string&, float, const std::string&) {
    serve::RoomClip clip;
    clip.glb = "glb";
    clip.duration = 30.0;  // signing all through the test
    clip.timeline = json{{"glosses", json::array()}};
    return clip;
  };
  services.gaze = [](const serve::SeatView&, const vec3&) { return std::optional<serve::JointRotations>(serve::JointRotations{}); };
  std::vector<float> walked;
  services.walk = [&walked](const RootTrajectory& body) {
    walked.push_back(body.duration());
    return std::optional<std::string>("walk-glb");
  };
  serve::RoomLimits limits;
  limits.lead = 0.0;  // the sentence starts at once
  serve::Rooms rooms(services, limits);
  std::vector<json> got;
  const auto c = rooms.connect("walk", [&got](const std::string& text) { got.push_back(json::parse(text)); }, [] {});
  ASSERT_TRUE(c);
  rooms.receive(*c, R"({"type":"join","name":"Ana"})");
  rooms.receive(*c, R"({"type":"say","text":"hello"})");
  rooms.tick();
  ASSERT_EQ(walked.size(), 1u);
  EXPECT_GT(walked[0], 1.0f);
  const auto walk = std::find_if(got.begin(), got.end(), [](const json& m) { return m["type"] == "host" && m.contains("walk"); });
  ASSERT_NE(walk, got.end());
  const json& w = (*walk)["walk"];
  const serve::HostStop to = serve::stop_facing({serve::seat_place(0).position, serve::seat_place(0).yaw});
  EXPECT_NEAR(w["to"]["position"][0].get<float>(), to.position.x, 1e-4);
  EXPECT_NEAR(w["to"]["yaw"].get<float>(), to.yaw, 1e-4);
  EXPECT_NEAR(w["duration"].get<double>(), walked[0], 1e-3);
  EXPECT_GE(w["path"].size(), 2u);
  EXPECT_EQ(rooms.clip("walk", w["clip"]).value_or(""), "walk-glb");
  const json state = rooms.state("walk");
  EXPECT_EQ(state["host"]["walk"]["clip"], w["clip"]);
  EXPECT_EQ(state["seat_places"].size(), 8u);
  rooms.tick();  // one walk at a time
  EXPECT_EQ(walked.size(), 1u);
}

TEST(RoomSeats, StandOnAnArcFacingItsMiddle) {
  for (int k = 0; k < 8; ++k) {
    const serve::Seat s = serve::seat_place(k);
    const vec3 facing(std::sin(s.yaw), 0.0f, std::cos(s.yaw));
    const vec3 to_centre = glm::normalize(vec3(0.0f) - s.position);
    EXPECT_GT(glm::dot(facing, to_centre), 0.99f) << k;
    for (int j = 0; j < k; ++j) EXPECT_GT(glm::length(serve::seat_place(j).position - s.position), 0.8f) << j << " " << k;
  }
  EXPECT_TRUE(serve::valid_room_name("lobby_2-b"));
  EXPECT_FALSE(serve::valid_room_name("../x"));
  EXPECT_FALSE(serve::valid_room_name(std::string(41, 'a')));
  EXPECT_TRUE(serve::valid_look("ana"));
  EXPECT_FALSE(serve::valid_look("makehuman:/tmp"));
}

}  // namespace
}  // namespace gestura
