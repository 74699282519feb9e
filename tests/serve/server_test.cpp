// gestura serve end to end: a server on an ephemeral port, spoken to over HTTP and WebSocket with
// Beast. Happy paths, the 4xx of bad requests, and that the server keeps answering after them.
#include <utility>

#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <boost/beast/websocket.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>

#include "gestura/serve/server.hpp"
#include "support/http_client.hpp"

namespace gestura {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::http;

class ServeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(fs::temp_directory_path() / ("gestura-serve-test-" + std::to_string(::getpid())));
    fs::remove_all(*root_);
    fs::create_directories(*root_ / "web" / "sub");
    std::ofstream(*root_ / "web" / "index.html") << "<!doctype html><title>gestura</title>";
    std::ofstream(*root_ / "web" / ".hidden") << "hidden";
    std::ofstream(*root_ / "secret.txt") << "SECRET";
    fs::create_symlink(*root_ / "secret.txt", *root_ / "web" / "sub" / "link.txt");
    serve::ServeOptions options;
    options.port = 0;
    options.data = (*root_ / "data").string();
    options.web = (*root_ / "web").string();
    options.max_body = 4096;
    options.max_text = 200;
    server_ = new serve::Server(options);
    server_->start();
  }
  static void TearDownTestSuite() {
    delete server_;
    fs::remove_all(*root_);
    delete root_;
  }
  static int port() { return server_->port(); }
  static json error_of(const test::HttpReply& r) { return json::parse(r.body).at("error"); }
  static void still_up() { EXPECT_EQ(http(port(), "GET", "/health").status, 200); }

  static inline serve::Server* server_ = nullptr;
  static inline fs::path* root_ = nullptr;
};

// The JSON chunk of a .glb.
json glb_json(const std::string& glb) {
  EXPECT_GE(glb.size(), 20u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return json::parse(glb.substr(20, length));
}

TEST_F(ServeTest, HealthAndMetrics) {
  const auto health = http(port(), "GET", "/health");
  ASSERT_EQ(health.status, 200);
  EXPECT_EQ(json::parse(health.body)["status"], "ok");
  const auto metrics = http(port(), "GET", "/metrics");
  ASSERT_EQ(metrics.status, 200);
  EXPECT_NE(metrics.body.find("gestura_requests_total{route=\"health\",status=\"200\"}"), std::string::npos);
  EXPECT_NE(metrics.body.find("gestura_job_queue_length"), std::string::npos);
}

TEST_F(ServeTest, SayAnswersGlossesAndASmallAnimation) {
  const auto reply = http(port(), "POST", "/api/say", R"({"text": "Hello, how are you?"})");
  ASSERT_EQ(reply.status, 200) << reply.body;
  const json timeline = json::parse(reply.body);
  ASSERT_FALSE(timeline["glosses"].empty());
  EXPECT_EQ(timeline["glosses"][0]["gloss"], "HELLO");
  EXPECT_GT(timeline["duration"].get<double>(), 1.0);

  const auto glb = http(port(), "POST", "/api/say?format=glb", R"({"text": "Hello, how are you?", "speed": 1.5})");
  ASSERT_EQ(glb.status, 200) << glb.body;
  EXPECT_EQ(glb.headers.at("content-type"), "model/gltf-binary");
  EXPECT_LT(glb.body.size(), 100u * 1024u) << "a short sentence stays under 100 KB";
  const json doc = glb_json(glb.body);
  ASSERT_EQ(doc["animations"].size(), 1u);
  const json& animation = doc["animations"][0];
  EXPECT_GT(animation["channels"].size(), 10u);
  EXPECT_EQ(animation["extras"]["glosses"][0]["gloss"], "HELLO");
  // Faster speech is shorter.
  EXPECT_LT(animation["extras"]["duration"].get<double>(), timeline["duration"].get<double>());
  // The joints are named as the avatar's, so a player binds them by name.
  bool wrist = false;
  for (const json& node : doc["nodes"]) wrist |= node.value("name", "") == "r_wrist";
  EXPECT_TRUE(wrist);
  // The face drives the avatar's morph targets by name.
  ASSERT_TRUE(doc.contains("meshes"));
  EXPECT_FALSE(doc["meshes"][0]["extras"]["targetNames"].empty());
}

TEST_F(ServeTest, BadSayRequestsAre4xxNamingThePlace) {
  auto r = http(port(), "POST", "/api/say", R"({"text": "hello")");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_of(r)["field"], "body");
  r = http(port(), "POST", "/api/say", R"({"text": "hello", "speed": 9})");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_of(r)["field"], "speed");
  EXPECT_EQ(error_of(r)["category"], "usage");
  // The server's files are not the client's to name.
  r = http(port(), "POST", "/api/say", R"({"text": "hello", "output": "/tmp/x.glb"})");
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_of(r)["field"], "output");
  r = http(port(), "POST", "/api/say", R"({"text": "hello", "avatar": "/etc/passwd.glb"})");
  EXPECT_EQ(r.status, 400);
  r = http(port(), "POST", "/api/say", R"({"text": "   "})");
  EXPECT_EQ(r.status, 400);
  r = http(port(), "POST", "/api/say", json{{"text", std::string(300, 'a')}}.dump());
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(error_of(r)["field"], "text");
  r = http(port(), "POST", "/api/say", R"({"text": "hello"})", {{"Content-Type", "text/plain"}});
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_of(r)["field"], "content-type");
  r = http(port(), "POST", "/api/say", R"(["hello"])");
  EXPECT_EQ(r.status, 400);
  r = http(port(), "POST", "/api/say", std::string(40, '[') + std::string(40, ']'));
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(error_of(r)["field"], "body");
  // A number past a double's range is the client's mistake too (was a 500: the JSON library's
  // out_of_range escaped the parse; found by fuzz_request_json).
  r = http(port(), "POST", "/api/say", R"({"text": "hello", "speed": 9e308})");
  EXPECT_EQ(r.status, 400) << r.body;
  EXPECT_EQ(error_of(r)["field"], "body");
  EXPECT_NE(error_of(r)["message"].get<std::string>().find("number overflow"), std::string::npos) << r.body;
  still_up();
}

TEST_F(ServeTest, BinaryAndOversizedBodiesAreRefused) {
  std::mt19937 random(7);
  std::string binary(2000, '\0');
  for (char& c : binary) c = static_cast<char>(random());
  auto r = http(port(), "POST", "/api/say", binary);
  EXPECT_EQ(r.status, 400);
  r = http(port(), "POST", "/api/say", "{\"text\": \"caf\xC3\x28\"}");  // invalid UTF-8 inside JSON
  EXPECT_EQ(r.status, 400);
  r = http(port(), "POST", "/api/say", json{{"text", std::string(10000, 'a')}}.dump());
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(error_of(r)["field"], "body");
  still_up();
}

TEST_F(ServeTest, MalformedHttpGetsAnAnswerAndTheServerStaysUp) {
  std::string reply = test::http_raw(port(), "THIS IS NOT HTTP\r\n\r\n");
  EXPECT_NE(reply.find("400"), std::string::npos) << reply;
  reply = test::http_raw(port(), "GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(20000, 'a') + "\r\n\r\n");
  EXPECT_NE(reply.find("431"), std::string::npos) << reply.substr(0, 200);
  reply = test::http_raw(port(), "GET /api/lexicon?q=%zz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_NE(reply.find("400"), std::string::npos) << reply;
  still_up();
}

TEST_F(ServeTest, RoutesAnswer404And405) {
  auto r = http(port(), "GET", "/api/nothing");
  EXPECT_EQ(r.status, 404);
  r = http(port(), "GET", "/api/say");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(r.headers.at("allow"), "POST");
}

TEST_F(ServeTest, StaticFilesStayInsideTheWebRoot) {
  auto r = http(port(), "GET", "/");
  ASSERT_EQ(r.status, 200);
  EXPECT_NE(r.body.find("<title>gestura"), std::string::npos);
  EXPECT_EQ(r.headers.at("content-type"), "text/html; charset=utf-8");
  const auto again = http(port(), "GET", "/index.html", {}, {{"If-None-Match", r.headers.at("etag")}});
  EXPECT_EQ(again.status, 304);
  for (const char* path : {"/../secret.txt", "/%2e%2e/secret.txt", "/sub/../../secret.txt", "/.hidden", "/sub/link.txt", "/%00"}) {
    r = http(port(), "GET", path);
    EXPECT_TRUE(r.status == 404 || r.status == 400) << path << " → " << r.status;
    EXPECT_EQ(r.body.find("SECRET"), std::string::npos) << path;
  }
  const std::string raw = test::http_raw(port(), "GET /../secret.txt HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(raw.find("SECRET"), std::string::npos);
}

TEST_F(ServeTest, AvatarIsCachedByETag) {
  const auto r = http(port(), "GET", "/api/avatar.glb");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.body.substr(0, 4), "glTF");
  EXPECT_LT(r.body.size(), 3u * 1024u * 1024u);
  ASSERT_TRUE(r.headers.count("etag"));
  EXPECT_NE(r.headers.at("cache-control").find("max-age"), std::string::npos);
  EXPECT_EQ(http(port(), "GET", "/api/avatar.glb", {}, {{"If-None-Match", r.headers.at("etag")}}).status, 304);
  // Compressed for browsers.
  const auto gz = http(port(), "GET", "/api/avatar.glb", {}, {{"Accept-Encoding", "gzip"}});
  EXPECT_EQ(gz.headers.at("content-encoding"), "gzip");
  EXPECT_LT(gz.body.size(), r.body.size());
}

TEST_F(ServeTest, SignPerformsNotationAndNamesTheBadSymbol) {
  auto r = http(port(), "POST", "/api/sign?format=glb", R"({"names": "hamflathand,hamextfingeru,hampalml,hamshoulders"})");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_FALSE(glb_json(r.body)["animations"][0]["channels"].empty());
  r = http(port(), "POST", "/api/sign", R"({"names": "hamflathand,nosuchsymbol"})");
  EXPECT_EQ(r.status, 422) << r.body;
  EXPECT_EQ(error_of(r)["field"], "names");
  r = http(port(), "POST", "/api/sign", R"({"sigml": "<sigml><hns_sign gloss=\"x\"><hamnosys_manual><hamflathand/>"})");
  EXPECT_EQ(r.status, 422) << r.body;
  r = http(port(), "POST", "/api/sign", R"({"speed": 1})");
  EXPECT_EQ(r.status, 400);
  still_up();
}

TEST_F(ServeTest, ASigmlDocumentOfSeveralSignsPlaysThemAllInOrder) {
  const auto sign = [](const char* gloss, std::initializer_list<const char*> symbols) {
    std::string out = std::string("<hns_sign gloss=\\\"") + gloss + "\\\"><hamnosys_manual>";
    for (const char* s : symbols) out += std::string("<") + s + "/>";
    return out + "</hamnosys_manual></hns_sign>";
  };
  const std::string one = sign("ONE", {"hamflathand", "hamextfingeru", "hampalml", "hamshoulders"});
  const std::string two = sign("TWO", {"hamfist", "hamextfingerol", "hampalmd", "hamchest", "hammoveo"});
  const std::string three = sign("THREE", {"hamfinger2", "hamextfingeru", "hampalml", "hamchin"});
  const auto timeline = [&](const std::string& signs) {
    const auto r = http(port(), "POST", "/api/sign", "{\"sigml\": \"<sigml>" + signs + "</sigml>\"}");
    EXPECT_EQ(r.status, 200) << r.body;
    const json body = json::parse(r.body, nullptr, false);
    return body.contains("timeline") ? body["timeline"] : body;
  };
  const json all = timeline(one + two + three), first = timeline(one);
  ASSERT_TRUE(all.contains("glosses")) << all.dump();
  ASSERT_EQ(all["glosses"].size(), 3u) << all.dump();
  const char* names[3] = {"ONE", "TWO", "THREE"};
  double previous_end = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const json& g = all["glosses"][i];
    EXPECT_EQ(g["gloss"], names[i]);
    EXPECT_GE(g["start"].get<double>(), previous_end - 1e-6) << "in order, not overlapping";
    EXPECT_GT(g["end"].get<double>(), g["start"].get<double>());
    previous_end = g["end"].get<double>();
  }
  EXPECT_LT(previous_end, all["duration"].get<double>()) << "the hands return to rest after the last sign";
  // Each sign takes its own time on the one timeline; a one-sign document still plays as one sign.
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_GT(all["glosses"][i]["end"].get<double>() - all["glosses"][i]["start"].get<double>(), 0.1) << all.dump();
  EXPECT_GT(first["duration"].get<double>(), 0.5) << first.dump();
  EXPECT_FALSE(first.contains("glosses")) << first.dump();
  still_up();
}

TEST_F(ServeTest, GlossAndLexicon) {
  auto r = http(port(), "GET", "/api/gloss?text=I+like+coffee");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_FALSE(json::parse(r.body)["glosses"].empty());
  r = http(port(), "GET", "/api/gloss?txt=hello");
  EXPECT_EQ(r.status, 400);
  r = http(port(), "GET", "/api/lexicon?q=hel&limit=5");
  ASSERT_EQ(r.status, 200) << r.body;
  const json found = json::parse(r.body);
  ASSERT_FALSE(found["entries"].empty());
  EXPECT_LE(found["entries"].size(), 5u);
  r = http(port(), "GET", "/api/lexicon/HELLO");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(json::parse(r.body)["entries"][0]["gloss"], "HELLO");
  r = http(port(), "GET", "/api/lexicon/NO-SUCH-SIGN-ANYWHERE");
  EXPECT_EQ(r.status, 404) << r.body;
  r = http(port(), "GET", "/api/lexicon?limit=0");
  EXPECT_EQ(r.status, 400);
}

TEST_F(ServeTest, VideoJobRendersWithProgressOverWebSocket) {
  auto r = http(port(), "POST", "/api/video", R"({"text": "hello", "size": "160x90", "fps": 10})");
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string id = json::parse(r.body)["id"];
  EXPECT_EQ(r.headers.at("location"), "/api/jobs/" + id);

  // Progress messages until the job ends.
  namespace asio = boost::asio;
  namespace beast = boost::beast;
  asio::io_context io;
  beast::websocket::stream<beast::tcp_stream> ws(io);
  beast::get_lowest_layer(ws).connect({asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port())});
  ws.handshake("127.0.0.1", "/api/jobs/" + id + "/events");
  std::string status;
  int messages = 0;
  for (; messages < 10000; ++messages) {
    beast::flat_buffer buffer;
    beast::error_code ec;
    ws.read(buffer, ec);
    if (ec) break;
    const json m = json::parse(beast::buffers_to_string(buffer.data()));
    status = m["status"];
    if (status != "queued" && status != "running") break;
  }
  EXPECT_EQ(status, "done");
  EXPECT_GE(messages, 1);

  const auto state = http(port(), "GET", "/api/jobs/" + id);
  ASSERT_EQ(state.status, 200);
  EXPECT_EQ(json::parse(state.body)["status"], "done");
  const auto video = http(port(), "GET", "/api/jobs/" + id + "/download");
  ASSERT_EQ(video.status, 200);
  EXPECT_EQ(video.headers.at("content-type"), "video/mp4");
  ASSERT_GT(video.body.size(), 1000u);
  EXPECT_EQ(video.body.substr(4, 4), "ftyp");
  // Written under --data only.
  EXPECT_TRUE(fs::exists(*root_ / "data" / "jobs" / (id + ".mp4")));

  EXPECT_EQ(http(port(), "GET", "/api/jobs/0000000000000000").status, 404);
  EXPECT_EQ(http(port(), "DELETE", "/api/jobs/" + id).status, 409);
  r = http(port(), "POST", "/api/video", R"({"text": "hello", "size": "4096x2304"})");
  EXPECT_EQ(r.status, 413);
  r = http(port(), "POST", "/api/video", R"({"text": "hello", "format": "avi"})");
  EXPECT_EQ(r.status, 400);
}

}  // namespace
}  // namespace gestura
