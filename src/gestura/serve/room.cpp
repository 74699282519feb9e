#include "gestura/serve/room.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>

#include "gestura/app/error.hpp"
#include "gestura/body/avatar_look.hpp"
#include "gestura/serve/api_error.hpp"
#include "gestura/serve/landmarks_json.hpp"
#include "gestura/serve/random_hex.hpp"

namespace gestura::serve {

using nlohmann::json;

namespace {

constexpr int kMaxJsonDepth = 16;
constexpr std::size_t kMaxNameBytes = 40;
constexpr float kArcRadius = 2.2f;
constexpr float kSeatStep = deg(25.0f);
constexpr double kPoseHold = 1.0;   // seconds a body-driven avatar counts as signing after its last pose
constexpr int kDropsBeforeClose = 500;


json rotations_json(const JointRotations& rotations) {
  json out = json::object();
  for (const auto& [name, q] : rotations) out[name] = {q[0], q[1], q[2], q[3]};
  return out;
}

json parse_message(std::string_view text) {
  try {
    return json::parse(text, [](int depth, json::parse_event_t, json&) {
      if (depth > kMaxJsonDepth) throw app::AppError(app::ErrorCategory::usage, app::Place{"message", {}}, "the JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      return true;
    });
  } catch (const json::parse_error& e) {
    std::string message = e.what();
    if (const std::size_t p = message.find("] "); p != std::string::npos) message = message.substr(p + 2);
    throw app::AppError(app::ErrorCategory::usage, app::Place{"message", {}}, "not valid JSON: " + message);
  }
}

const std::string& string_field(const json& message, const char* key, bool required) {
  static const std::string empty;
  const auto it = message.find(key);
  if (it == message.end() || it->is_null()) {
    if (required) app::usage_error(key, "is required");
    return empty;
  }
  if (!it->is_string()) app::usage_error(key, "expected a string");
  return it->get_ref<const std::string&>();
}

}  // namespace

Seat seat_place(int seat) {
  // The host at the arc's middle, facing +Z; seats alternate left and right of it, 25° apart, all
  // facing the arc's centre, so that everyone sees everyone's hands.
  const float theta = seat < 0 ? 0.0f : (seat % 2 == 0 ? -1.0f : 1.0f) * kSeatStep * static_cast<float>(seat / 2 + 1);
  Seat s;
  s.position = vec3(kArcRadius * std::sin(theta), 0.0f, -kArcRadius * std::cos(theta));
  s.yaw = -theta;
  return s;
}

bool valid_room_name(std::string_view name) {
  if (name.empty() || name.size() > 40) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; });
}

bool valid_look(std::string_view look) { return look == "default" || find_look(look) != nullptr; }

struct Rooms::Participant {
  std::string id, token, name, look;
  int seat = 0;
  std::uint64_t connection = 0;  // 0: away (the connection was lost; the seat waits for the token)
  double away_since = 0.0;
  bool preparing = false;        // a sentence is being signed for them
  std::uint64_t generation = 0;
  struct Playing {
    std::string clip, text;
    double start = 0.0, end = 0.0;
    json glosses;
  };
  std::optional<Playing> playing;
  bool solving = false;          // a body pose is being fitted
  double posed_until = -1.0;
  json pose;                     // the last body pose (rotations), for late joiners
};

struct Rooms::Connection {
  std::uint64_t id = 0;
  std::string room, participant;  // participant empty until joined
  Send send;
  Close close;
  double tokens = 0.0, pose_tokens = 0.0, refilled = 0.0;
  double last_error = -1e9;
  int dropped = 0;
  bool closing = false;
};

struct Rooms::Room {
  std::string name;
  std::map<std::string, std::unique_ptr<Participant>> participants;
  int next_participant = 1;
  int connections = 0;
  std::deque<std::pair<std::string, std::string>> clips;  // id, .glb: the newest last
  LookState host_state;
  HostLook host;
  int arrived = -1;
  bool host_sent = false;
  json host_rotations = json::object();
  // Where the host stands, where it goes (a seat it faces, or -1: its own place) and its walk there.
  HostStop host_at;
  int host_goal = -1;
  double signer_seen = -1e9;  // when the host last watched someone signing
  bool walk_pending = false;  // a walk is being planned and synthesised
  struct Walk {
    std::string clip;
    double start = 0.0, end = 0.0;
    HostStop from, to;
    std::vector<vec3> path;
  };
  std::optional<Walk> walk;
};

namespace {

json stop_json(const HostStop& s) { return {{"position", {s.position.x, s.position.y, s.position.z}}, {"yaw", s.yaw}}; }

// A walk of the host as clients play it: the clip (its root moves in world space) from `start`
// (server seconds), where it starts and ends, and the planned path.
json walk_json(const std::string& room, const std::string& clip, double start, double end, const HostStop& from, const HostStop& to,
               const std::vector<vec3>& path) {
  json points = json::array();
  for (const vec3& p : path) points.push_back({p.x, p.y, p.z});
  return {{"clip", clip}, {"url", "/api/rooms/" + room + "/clips/" + clip}, {"start", start}, {"duration", end - start},
          {"from", stop_json(from)}, {"to", stop_json(to)}, {"path", points}};
}

}  // namespace

Rooms::Rooms(RoomServices services, RoomLimits limits)
    : services_(std::move(services)), limits_(limits), epoch_(std::chrono::steady_clock::now()), alive_(std::make_shared<bool>(true)) {
  if (!services_.post) services_.post = [](std::function<void()> f) { f(); };
  std::vector<vec3> seats;
  for (int k = 0; k < limits_.seats; ++k) seats.push_back(seat_place(k).position);
  world_ = std::make_shared<RoomWorld>(seats);
}

Rooms::~Rooms() {
  std::lock_guard lock(mutex_);
  *alive_ = false;
}

double Rooms::now() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count(); }

std::optional<std::uint64_t> Rooms::connect(const std::string& room, Send send, Close close) {
  if (!valid_room_name(room)) return std::nullopt;
  std::lock_guard lock(mutex_);
  auto it = rooms_.find(room);
  if (it == rooms_.end()) {
    if (static_cast<int>(rooms_.size()) >= limits_.max_rooms) return std::nullopt;
    it = rooms_.emplace(room, std::make_unique<Room>()).first;
    it->second->name = room;
    const Seat home = seat_place(-1);
    it->second->host_at = HostStop{home.position, home.yaw};
  }
  ++it->second->connections;
  auto c = std::make_unique<Connection>();
  c->id = next_connection_++;
  c->room = room;
  c->send = std::move(send);
  c->close = std::move(close);
  c->tokens = 2.0 * limits_.messages_per_second;
  c->pose_tokens = limits_.poses_per_second;
  c->refilled = now();
  const std::uint64_t id = c->id;
  connections_.emplace(id, std::move(c));
  return id;
}

Rooms::Room* Rooms::room_of(const Connection& c) {
  const auto it = rooms_.find(c.room);
  return it == rooms_.end() ? nullptr : it->second.get();
}

Rooms::Participant* Rooms::participant_of(const Connection& c) {
  Room* room = room_of(c);
  if (!room || c.participant.empty()) return nullptr;
  const auto it = room->participants.find(c.participant);
  return it == room->participants.end() || it->second->connection != c.id ? nullptr : it->second.get();
}

void Rooms::send(Connection& c, json message) {
  if (c.closing) return;
  message["time"] = now();
  c.send(message.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Rooms::broadcast(Room& room, json message, std::uint64_t except) {
  message["time"] = now();
  const std::string text = message.dump(-1, ' ', false, json::error_handler_t::replace);
  for (const auto& [id, p] : room.participants) {
    if (p->connection == 0 || p->connection == except) continue;
    const auto it = connections_.find(p->connection);
    if (it != connections_.end() && !it->second->closing) it->second->send(text);
  }
}

void Rooms::fail(Connection& c, int status, const std::string& category, const std::string& message, const std::string& field) {
  json out = json::parse(error_response(status, category, message, field).body);
  out["type"] = "error";
  send(c, std::move(out));
}

void Rooms::fail_current(Connection& c) {
  json out = json::parse(current_error_response().body);
  out["type"] = "error";
  send(c, std::move(out));
}

void Rooms::oversized(std::uint64_t connection, std::size_t size) {
  std::lock_guard lock(mutex_);
  const auto it = connections_.find(connection);
  if (it == connections_.end()) return;
  fail(*it->second, 413, "too_large",
       "a message of " + std::to_string(size) + " bytes; a room takes messages of at most " + std::to_string(limits_.max_message) + " bytes",
       "message");
}

void Rooms::receive(std::uint64_t connection, std::string_view text) {
  receive_locked(connection, text);
  run_deferred();
}

void Rooms::defer(std::function<void()> job) { deferred_.push_back(std::move(job)); }

void Rooms::run_deferred() {
  std::vector<std::function<void()>> jobs;
  {
    std::lock_guard lock(mutex_);
    jobs.swap(deferred_);
  }
  for (auto& job : jobs) services_.post(std::move(job));
}

void Rooms::receive_locked(std::uint64_t connection, std::string_view text) {
  std::lock_guard lock(mutex_);
  const auto it = connections_.find(connection);
  if (it == connections_.end() || it->second->closing) return;
  Connection& c = *it->second;
  const double t = now();
  // Token buckets: general messages and body poses, each refilled with time.
  const double elapsed = std::max(0.0, t - c.refilled);
  c.refilled = t;
  c.tokens = std::min(2.0 * limits_.messages_per_second, c.tokens + elapsed * limits_.messages_per_second);
  c.pose_tokens = std::min(limits_.poses_per_second, c.pose_tokens + elapsed * limits_.poses_per_second);
  if (text.size() > limits_.max_message) {
    fail(c, 413, "too_large",
         "a message of " + std::to_string(text.size()) + " bytes; a room takes messages of at most " + std::to_string(limits_.max_message) + " bytes",
         "message");
    return;
  }
  try {
    const json message = parse_message(text);
    if (!message.is_object()) app::usage_error("message", "expected a JSON object with a \"type\"");
    const bool pose = message.contains("type") && message["type"] == "landmarks";
    double& bucket = pose ? c.pose_tokens : c.tokens;
    if (bucket < 1.0) {
      // Flooding: the message is dropped; the sender hears of it once a second, and a connection
      // that keeps on is closed (the room and the server carry on).
      if (++c.dropped > kDropsBeforeClose) {
        c.closing = true;
        if (c.close) c.close();
        return;
      }
      if (t - c.last_error >= 1.0) {
        c.last_error = t;
        fail(c, 429, "busy", pose ? "too many landmarks messages: at most " + std::to_string(static_cast<int>(limits_.poses_per_second)) + " a second"
                                  : "too many messages: at most " + std::to_string(static_cast<int>(limits_.messages_per_second)) + " a second",
             "type");
      }
      return;
    }
    bucket -= 1.0;
    handle(c, message);
  } catch (...) {
    fail_current(c);
  }
}

void Rooms::handle(Connection& c, const json& message) {
  const std::string& type = string_field(message, "type", true);
  if (type == "ping") {
    json pong{{"type", "pong"}};
    if (message.contains("t")) {
      if (!message["t"].is_number()) app::usage_error("t", "expected the client's clock as a number");
      pong["t"] = message["t"];
    }
    send(c, std::move(pong));
    return;
  }
  if (type == "join") return join(c, message);
  Participant* p = participant_of(c);
  if (!p) {
    if (type == "say" || type == "landmarks" || type == "leave")
      throw app::AppError(app::ErrorCategory::conflict, app::Place{"type", {}}, "join the room first ({\"type\": \"join\", \"name\": …})");
    app::usage_error("type", "unknown message type '" + type + "' (known: join, say, landmarks, ping, leave)");
  }
  if (type == "say") return say(c, *p, message);
  if (type == "landmarks") return landmarks(c, *p, message);
  if (type == "leave") return leave(c);
  app::usage_error("type", "unknown message type '" + type + "' (known: join, say, landmarks, ping, leave)");
}

json Rooms::participant_json(const Participant& p) const {
  const Seat s = seat_place(p.seat);
  return {{"id", p.id}, {"name", p.name}, {"look", p.look}, {"seat", p.seat},
          {"position", {s.position.x, s.position.y, s.position.z}}, {"yaw", s.yaw}, {"connected", p.connection != 0}};
}

json Rooms::state_locked(const Room& room) const {
  json participants = json::array(), playing = json::array(), poses = json::object();
  const double t = now();
  for (const auto& [id, p] : room.participants) {
    participants.push_back(participant_json(*p));
    if (p->playing && p->playing->end > t)
      playing.push_back({{"participant", p->id}, {"clip", p->playing->clip}, {"url", "/api/rooms/" + room.name + "/clips/" + p->playing->clip},
                         {"start", p->playing->start}, {"duration", p->playing->end - p->playing->start},
                         {"text", p->playing->text}, {"glosses", p->playing->glosses}});
    if (p->posed_until > t && !p->pose.is_null()) poses[p->id] = p->pose;
  }
  const HostStop& host = room.host_at;
  json host_json{{"name", "Host"}, {"look", "default"}, {"position", {host.position.x, host.position.y, host.position.z}}, {"yaw", host.yaw},
                 {"why", room.host.why}, {"rotations", room.host_rotations}};
  host_json["walk"] = room.walk ? walk_json(room.name, room.walk->clip, room.walk->start, room.walk->end, room.walk->from, room.walk->to, room.walk->path)
                                : json(nullptr);
  host_json["look_at"] = nullptr;
  if (room.host.seat >= 0)
    for (const auto& [id, p] : room.participants)
      if (p->seat == room.host.seat) host_json["look_at"] = p->id;
  // The room's floor plan: where the seats stand (the host walks around them).
  json seat_places = json::array();
  for (const vec3& p : world_->seats()) seat_places.push_back({{"position", {p.x, p.y, p.z}}, {"radius", RoomWorld::kSeatRadius}});
  return {{"room", room.name}, {"participants", participants}, {"playing", playing}, {"poses", poses}, {"host", host_json},
          {"seats", limits_.seats}, {"seat_places", seat_places}, {"time", t}};
}

void Rooms::join(Connection& c, const json& message) {
  Room* room = room_of(c);
  if (!room) throw app::AppError(app::ErrorCategory::not_found, app::Place{"room", {}}, "the room is gone");
  if (participant_of(c)) throw app::AppError(app::ErrorCategory::conflict, app::Place{"type", {}}, "this connection has joined already");
  const std::string& token = string_field(message, "token", false);
  Participant* p = nullptr;
  if (!token.empty()) {
    for (auto& [id, q] : room->participants)
      if (q->token == token) p = q.get();
    if (!p) throw app::AppError(app::ErrorCategory::not_found, app::Place{"token", {}}, "no seat in this room holds that token (it expired or was never here)");
    // The seat is taken back: a connection still holding it (a half-open one) is closed.
    if (p->connection != 0 && p->connection != c.id) {
      const auto old = connections_.find(p->connection);
      if (old != connections_.end()) {
        send(*old->second, {{"type", "replaced"}, {"message", "this seat was taken back by a new connection with its token"}});
        old->second->participant.clear();
        old->second->closing = true;
        if (old->second->close) old->second->close();
      }
    }
    p->connection = c.id;
    c.participant = p->id;
  } else {
    std::string name = string_field(message, "name", true);
    if (name.empty() || name.size() > kMaxNameBytes) app::usage_error("name", "is 1 to " + std::to_string(kMaxNameBytes) + " bytes");
    if (std::any_of(name.begin(), name.end(), [](char ch) { return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f; }))
      app::usage_error("name", "has control characters");
    std::string look = string_field(message, "look", false);
    if (look.empty()) look = "default";
    if (!valid_look(look)) app::usage_error("look", "is one of " + look_names() + ", not '" + look + "'");
    if (static_cast<int>(room->participants.size()) >= limits_.seats)
      throw app::AppError(app::ErrorCategory::conflict, app::Place{"room", {}}, "the room is full (" + std::to_string(limits_.seats) + " seats)");
    std::vector<bool> taken(static_cast<std::size_t>(limits_.seats), false);
    for (const auto& [id, q] : room->participants) taken[static_cast<std::size_t>(q->seat)] = true;
    auto np = std::make_unique<Participant>();
    np->id = "p" + std::to_string(room->next_participant++);
    np->token = random_hex(2);
    np->name = std::move(name);
    np->look = std::move(look);
    np->seat = static_cast<int>(std::find(taken.begin(), taken.end(), false) - taken.begin());
    np->connection = c.id;
    p = np.get();
    c.participant = p->id;
    room->participants.emplace(p->id, std::move(np));
    room->arrived = p->seat;
  }
  json welcome = state_locked(*room);
  welcome["type"] = "welcome";
  welcome["you"] = {{"id", p->id}, {"token", p->token}, {"seat", p->seat}};
  welcome["limits"] = {{"max_message", limits_.max_message}, {"max_text", limits_.max_text},
                       {"messages_per_second", limits_.messages_per_second}, {"poses_per_second", limits_.poses_per_second},
                       {"reconnect_grace", limits_.reconnect_grace}};
  send(c, std::move(welcome));
  broadcast(*room, {{"type", token.empty() ? "joined" : "back"}, {"participant", participant_json(*p)}}, c.id);
  update_host(*room);
}

void Rooms::say(Connection& c, Participant& p, const json& message) {
  const std::string& text = string_field(message, "text", true);
  if (text.size() > limits_.max_text)
    throw app::AppError(app::ErrorCategory::too_large, app::Place{"text", {}},
                        std::to_string(text.size()) + " bytes of text; a room signs at most " + std::to_string(limits_.max_text) + " bytes at a time");
  if (std::all_of(text.begin(), text.end(), [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); })) app::usage_error("text", "is empty");
  float speed = 1.0f;
  if (message.contains("speed")) {
    if (!message["speed"].is_number()) app::usage_error("speed", "expected a number");
    speed = message["speed"].get<float>();
    if (!(speed >= 0.25f && speed <= 2.0f)) app::usage_error("speed", "is between 0.25 and 2");
  }
  if (p.preparing) throw app::AppError(app::ErrorCategory::conflict, app::Place{"text", {}}, "your last sentence is still being prepared; send the next when it plays");
  p.preparing = true;
  const std::uint64_t generation = ++p.generation;
  send(c, {{"type", "preparing"}, {"participant", p.id}, {"text", text}});
  std::weak_ptr<bool> alive = alive_;
  defer([this, alive, room = c.room, id = p.id, generation, text, speed, look = p.look] {
    std::optional<RoomClip> clip;
    std::string error_body;
    try {
      clip = services_.say(text, speed, look);
    } catch (...) {
      error_body = current_error_response().body;
    }
    const auto still = alive.lock();
    if (!still || !*still) return;
    if (clip) return finish_say(room, id, generation, text, std::move(*clip));
    std::lock_guard lock(mutex_);
    const auto r = rooms_.find(room);
    if (r == rooms_.end()) return;
    const auto q = r->second->participants.find(id);
    if (q == r->second->participants.end() || q->second->generation != generation) return;
    q->second->preparing = false;
    const auto conn = connections_.find(q->second->connection);
    if (conn == connections_.end()) return;
    json out = json::parse(error_body);
    out["type"] = "error";
    send(*conn->second, std::move(out));
  });
}

void Rooms::finish_say(const std::string& room_name, const std::string& id, std::uint64_t generation, const std::string& text, RoomClip clip) {
  std::lock_guard lock(mutex_);
  const auto r = rooms_.find(room_name);
  if (r == rooms_.end()) return;
  Room& room = *r->second;
  const auto q = room.participants.find(id);
  if (q == room.participants.end() || q->second->generation != generation) return;
  Participant& p = *q->second;
  p.preparing = false;
  const std::string clip_id = "c" + std::to_string(next_clip_++);
  room.clips.emplace_back(clip_id, std::move(clip.glb));
  while (static_cast<int>(room.clips.size()) > limits_.clips_kept) room.clips.pop_front();
  const double t = now();
  // Sentences of one participant follow each other; everyone starts a clip at the same moment.
  double start = t + limits_.lead;
  if (p.playing && p.playing->end > start) start = p.playing->end;
  Participant::Playing playing;
  playing.clip = clip_id;
  playing.text = text;
  playing.start = start;
  playing.end = start + clip.duration;
  playing.glosses = clip.timeline.contains("glosses") ? clip.timeline["glosses"] : json::array();
  p.playing = playing;
  broadcast(room, {{"type", "play"}, {"participant", p.id}, {"clip", clip_id}, {"url", "/api/rooms/" + room.name + "/clips/" + clip_id},
                   {"start", start}, {"duration", clip.duration}, {"text", playing.text}, {"glosses", playing.glosses}});
}

void Rooms::landmarks(Connection& c, Participant& p, const json& message) {
  HolisticFrame frame = landmarks_from_json(message);  // every number checked before any work is queued
  if (!services_.capture) throw app::AppError(app::ErrorCategory::conflict, app::Place{"type", {}}, "this server does not fit bodies to landmarks");
  if (p.solving) return;  // one frame is being fitted: this one is dropped, the next one will be newer
  p.solving = true;
  std::weak_ptr<bool> alive = alive_;
  defer([this, alive, room = c.room, id = p.id, connection = c.id, frame = std::move(frame), look = p.look] {
    std::optional<JointRotations> rotations;
    std::string error_body;
    try {
      rotations = services_.capture(frame, look);
    } catch (...) {
      error_body = current_error_response().body;
    }
    const auto still = alive.lock();
    if (!still || !*still) return;
    std::lock_guard lock(mutex_);
    const auto r = rooms_.find(room);
    if (r == rooms_.end()) return;
    const auto q = r->second->participants.find(id);
    if (q == r->second->participants.end()) return;
    Participant& pp = *q->second;
    pp.solving = false;
    if (!rotations) {
      const auto conn = connections_.find(connection);
      if (conn == connections_.end()) return;
      Connection& cc = *conn->second;
      if (now() - cc.last_error < 1.0) return;
      cc.last_error = now();
      json out = json::parse(error_body);
      out["type"] = "error";
      send(cc, std::move(out));
      return;
    }
    pp.pose = rotations_json(*rotations);
    pp.posed_until = now() + kPoseHold;
    broadcast(*r->second, {{"type", "pose"}, {"participant", pp.id}, {"rotations", pp.pose}});
  });
}

void Rooms::leave(Connection& c) {
  Room* room = room_of(c);
  const std::string id = c.participant;
  c.participant.clear();
  if (room) remove_participant(*room, id, "left");
  send(c, {{"type", "left"}, {"participant", id}, {"why", "left"}});
}

void Rooms::remove_participant(Room& room, const std::string& id, const std::string& why) {
  if (room.participants.erase(id) == 0) return;
  broadcast(room, {{"type", "left"}, {"participant", id}, {"why", why}});
  update_host(room);
}

void Rooms::disconnect(std::uint64_t connection) {
  {
    std::lock_guard lock(mutex_);
    disconnect_locked(connection);
  }
  run_deferred();
}

void Rooms::disconnect_locked(std::uint64_t connection) {
  const auto it = connections_.find(connection);
  if (it == connections_.end()) return;
  Connection& c = *it->second;
  if (Room* room = room_of(c)) {
    --room->connections;
    if (Participant* p = participant_of(c)) {
      p->connection = 0;
      p->away_since = now();
      broadcast(*room, {{"type", "away"}, {"participant", p->id}});
    }
  }
  connections_.erase(it);
}

void Rooms::tick() {
  {
    std::lock_guard lock(mutex_);
    tick_locked();
  }
  run_deferred();
}

void Rooms::tick_locked() {
  const double t = now();
  for (auto it = rooms_.begin(); it != rooms_.end();) {
    Room& room = *it->second;
    std::vector<std::string> expired;
    for (const auto& [id, p] : room.participants) {
      if (p->connection == 0 && t - p->away_since > limits_.reconnect_grace) expired.push_back(id);
      if (p->playing && p->playing->end < t) p->playing.reset();
    }
    for (const std::string& id : expired) remove_participant(room, id, "timeout");
    update_host(room);
    if (room.participants.empty() && room.connections == 0) it = rooms_.erase(it);
    else ++it;
  }
}

void Rooms::update_host(Room& room) {
  const double t = now();
  if (room.walk && t >= room.walk->end) {
    // Arrived: the host stands at the walk's end; its gaze is sent again from there.
    room.host_at = room.walk->to;
    room.walk.reset();
    room.host_sent = false;
  }
  std::vector<SeatView> seats(static_cast<std::size_t>(limits_.seats));
  for (int k = 0; k < limits_.seats; ++k) {
    const Seat s = seat_place(k);
    seats[static_cast<std::size_t>(k)].position = s.position;
    seats[static_cast<std::size_t>(k)].yaw = s.yaw;
    seats[static_cast<std::size_t>(k)].present = false;
  }
  for (const auto& [id, p] : room.participants) {
    SeatView& v = seats[static_cast<std::size_t>(p->seat)];
    v.present = true;
    v.signing = (p->playing && p->playing->start <= t && t < p->playing->end) || p->posed_until > t;
  }
  SeatView host;
  host.position = room.host_at.position;
  host.yaw = room.host_at.yaw;
  const HostLook look = choose_host_look(host, seats, room.arrived, static_cast<float>(t), room.host_state);
  room.arrived = -1;
  // Where the host goes: in front of whoever it watches sign, and back to its place when nobody has
  // signed for a while. One walk at a time; the next goal is chosen when it has arrived.
  const bool signer = look.why == "signer" && look.seat >= 0;
  if (signer) room.signer_seen = t;
  int goal = room.host_goal;
  if (signer) goal = look.seat;
  else if (t - room.signer_seen > limits_.host_home_after) goal = -1;
  if (goal != room.host_goal && !room.walk && !room.walk_pending && services_.walk) start_walk(room, goal);
  if (room.walk || room.walk_pending) return;  // walking: the head follows the walk, the gaze comes on arrival
  if (look.seat == room.host.seat && look.why == room.host.why && room.host_sent) return;
  const std::optional<JointRotations> rotations = services_.gaze ? services_.gaze(host, look.point) : std::nullopt;
  if (!rotations) {
    // The host's body is still being built: build it once, and look again on a later tick.
    prepare_host_once();
    return;
  }
  room.host = look;
  room.host_sent = true;
  room.host_rotations = rotations_json(*rotations);
  json look_at = nullptr;
  for (const auto& [id, p] : room.participants)
    if (p->seat == room.host.seat) look_at = p->id;
  json message{{"type", "host"}, {"look_at", look_at}, {"why", room.host.why}, {"rotations", room.host_rotations}};
  message.update(stop_json(room.host_at));
  broadcast(room, std::move(message));
}

// Builds the host's body once, off the rooms' lock (mutex_ held by the caller); until it exists the
// host keeps looking ahead and does not walk.
void Rooms::prepare_host_once() {
  if (host_preparing_ || !services_.prepare_host) return;
  host_preparing_ = true;
  defer([prepare = services_.prepare_host] {
    try {
      prepare();
    } catch (...) {
      // no host body: the host keeps looking ahead
    }
  });
}

void Rooms::start_walk(Room& room, int goal) {
  const int previous = room.host_goal;
  room.host_goal = goal;
  room.walk_pending = true;
  const Seat home = seat_place(-1);
  SeatView seat;
  if (goal >= 0) seat.position = seat_place(goal).position, seat.yaw = seat_place(goal).yaw;
  const HostStop from = room.host_at;
  const HostStop to = goal < 0 ? HostStop{home.position, home.yaw} : stop_facing(seat);
  std::weak_ptr<bool> alive = alive_;
  defer([this, alive, world = world_, name = room.name, previous, from, to] {
    std::optional<HostWalkPlan> plan;
    std::optional<std::string> glb;
    try {
      if (glm::length(to.position - from.position) > 0.05f) plan = world->plan(from, to);
      if (plan) glb = services_.walk(plan->body);
    } catch (...) {
      plan.reset();  // no walk: the host stays where it is and only turns its head
    }
    const auto still = alive.lock();
    if (!still || !*still) return;
    std::lock_guard lock(mutex_);
    const auto r = rooms_.find(name);
    if (r == rooms_.end()) return;
    Room& room = *r->second;
    room.walk_pending = false;
    if (plan && !glb) {
      // The host's body is not built yet: build it, and walk on a later tick.
      room.host_goal = previous;
      prepare_host_once();
      return;
    }
    if (!plan) {
      room.host_at.yaw = to.yaw;  // too near to walk, or no way there: turn where it stands
      room.host_sent = false;
      return;
    }
    const std::string clip_id = "c" + std::to_string(next_clip_++);
    room.clips.emplace_back(clip_id, std::move(*glb));
    while (static_cast<int>(room.clips.size()) > limits_.clips_kept) room.clips.pop_front();
    Room::Walk walk;
    walk.clip = clip_id;
    walk.start = now() + limits_.lead;
    walk.end = walk.start + plan->body.duration();
    walk.from = from;
    walk.to = to;
    walk.path = plan->path;
    room.walk = walk;
    broadcast(room, {{"type", "host"}, {"walk", walk_json(room.name, walk.clip, walk.start, walk.end, from, to, walk.path)},
                     {"look_at", nullptr}, {"why", "walk"}, {"rotations", json::object()}});
  });
}

std::optional<std::string> Rooms::clip(const std::string& room, const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto r = rooms_.find(room);
  if (r == rooms_.end()) return std::nullopt;
  for (const auto& [cid, glb] : r->second->clips)
    if (cid == id) return glb;
  return std::nullopt;
}

json Rooms::state(const std::string& room) const {
  std::lock_guard lock(mutex_);
  const auto r = rooms_.find(room);
  return r == rooms_.end() ? json() : state_locked(*r->second);
}

json Rooms::list() const {
  std::lock_guard lock(mutex_);
  json out = json::array();
  for (const auto& [name, room] : rooms_) out.push_back({{"room", name}, {"participants", room->participants.size()}, {"seats", limits_.seats}});
  return {{"rooms", out}};
}

}  // namespace gestura::serve
