// Render jobs through a real broker: a redis-server on a unix socket in a temporary folder, two
// `gestura worker` processes and one API server. One worker is killed with SIGKILL in the middle
// of a job; every video still arrives, byte for byte the video a one-process render writes (the
// MP4 and WebM gestura writes carry no wall-clock time, so equal frames mean equal bytes).
// Malformed entries in the stream are dead-lettered with a reason and the worker stays up.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <thread>

#include <utility>  // before Boost.Asio 1.74, which uses std::exchange without it

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gestura/app/say.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/serve/broker_keys.hpp"
#include "gestura/serve/broker_url.hpp"
#include "gestura/serve/redis.hpp"
#include "gestura/serve/server.hpp"
#include "gestura/serve/video_job.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/http_client.hpp"

extern char** environ;

namespace gestura {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;
using test::http;

TEST(BrokerUrl, ReadsRedisAndUnixUrls) {
  serve::BrokerUrl u = serve::parse_broker_url("redis://cache.local:6380/2");
  EXPECT_EQ(u.host, "cache.local");
  EXPECT_EQ(u.port, 6380);
  EXPECT_EQ(u.db, 2);
  EXPECT_TRUE(u.socket.empty());
  u = serve::parse_broker_url("redis://:s3cret@10.0.0.5");
  EXPECT_EQ(u.host, "10.0.0.5");
  EXPECT_EQ(u.port, 6379);
  EXPECT_EQ(u.password, "s3cret");
  EXPECT_EQ(u.shown.find("s3cret"), std::string::npos) << "logs never show the password";
  u = serve::parse_broker_url("redis://[::1]:7000");
  EXPECT_EQ(u.host, "::1");
  EXPECT_EQ(u.port, 7000);
  u = serve::parse_broker_url("unix:///run/redis/redis.sock?db=3");
  EXPECT_EQ(u.socket, "/run/redis/redis.sock");
  EXPECT_EQ(u.db, 3);
}

TEST(BrokerUrl, BadUrlsAreUsageErrorsAtBroker) {
  for (const char* bad : {"", "amqp://rabbit", "localhost:6379", "redis://host:99999", "redis://host:x", "redis://host/db",
                          "unix://relative.sock", "unix:///a.sock?timeout=3", "redis://user@host", "redis://ho st"}) {
    try {
      serve::parse_broker_url(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const app::AppError& e) {
      EXPECT_EQ(e.category(), app::ErrorCategory::usage) << bad;
      EXPECT_EQ(e.place().field, "broker") << bad;
    }
  }
}

TEST(BrokerCli, WorkerNeedsAGoodBrokerUrl) {
  test::CliRun r = test::run_cli("worker --broker amqp://localhost");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--broker"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("unsupported scheme 'amqp'"), std::string::npos) << r.output;
  r = test::run_cli("worker --broker redis://:hunter2@cache:0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("bad port '0'"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("hunter2"), std::string::npos) << "errors never show the password: " << r.output;
  r = test::run_cli("worker");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--broker"), std::string::npos) << r.output;
  // A server whose broker is not there says so at start.
  r = test::run_cli("serve --port 0 --broker unix:///nonexistent/gestura-test-redis.sock");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("cannot reach the broker at unix:///nonexistent/gestura-test-redis.sock"), std::string::npos) << r.output;
  r = test::run_cli("worker --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("--claim-after"), std::string::npos) << r.output;
}

// A child process whose output goes to a log file.
struct Child {
  pid_t pid = -1;
  std::string log;

  void start(const std::vector<std::string>& args, const fs::path& log_file) {
    log = log_file.string();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  bool running() const { return pid > 0 && waitpid(pid, nullptr, WNOHANG) == 0; }
  // Sends `signal` and waits up to `wait` for the exit; the exit status, or -1 (killed then).
  int stop(int signal, std::chrono::milliseconds wait = 20s) {
    if (pid <= 0) return -1;
    kill(pid, signal);
    int status = 0;
    for (auto left = wait; left > 0ms; left -= 20ms) {
      if (waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(20ms);
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    pid = -1;
    return -1;
  }
  std::string output() const {
    std::ifstream in(log);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

bool has_redis_server() { return test::run_command("command -v redis-server").status == 0; }

class BrokerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!has_redis_server()) GTEST_SKIP() << "redis-server is not installed (Debian package redis-server): the broker is not tested";
    root_ = fs::temp_directory_path() / ("gestura-broker-test-" + std::to_string(getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    socket_ = (root_ / "redis.sock").string();
    redis_.start({"redis-server", "--port", "0", "--unixsocket", socket_, "--unixsocketperm", "700", "--save", "", "--appendonly", "no",
                  "--dir", root_.string()},
                 root_ / "redis.log");
    ASSERT_GT(redis_.pid, 0);
    url_ = "unix://" + socket_;
    for (int i = 0; i < 250 && !broker_; ++i) {
      try {
        broker_ = std::make_unique<serve::Redis>(serve::parse_broker_url(url_), 2s);
        broker_->command({"PING"});
      } catch (const serve::BrokerUnavailable&) {
        broker_.reset();
        std::this_thread::sleep_for(20ms);
      }
    }
    ASSERT_TRUE(broker_) << "redis-server did not start: " << redis_.output();
    for (int i = 0; i < 2; ++i) {
      const std::string name = "w" + std::to_string(i + 1);
      workers_[i].start({test::cli_path(), "worker", "--broker", url_, "--data", (root_ / name).string(), "--name", name, "--claim-after", "2"},
                        root_ / (name + ".log"));
      ASSERT_GT(workers_[i].pid, 0);
    }
    serve::ServeOptions options;
    options.port = 0;
    options.data = (root_ / "serve").string();
    options.broker = url_;
    server_ = std::make_unique<serve::Server>(options);
    server_->start();
  }
  void TearDown() override {
    server_.reset();
    for (Child& w : workers_) w.stop(SIGKILL, 5s);
    broker_.reset();
    redis_.stop(SIGTERM, 5s);
    if (!root_.empty()) fs::remove_all(root_);
  }
  int port() const { return server_->port(); }
  json job(const std::string& id) { return json::parse(http(port(), "GET", "/api/jobs/" + id).body); }
  std::string job_field(const std::string& id, const std::string& field) {
    return broker_->command({"HGET", serve::broker::job_key(id), field}).text;
  }
  // Waits until every job has left queued/running; false on time out.
  bool wait_all(const std::vector<std::string>& ids, std::chrono::seconds limit) {
    for (auto left = std::chrono::milliseconds(limit); left > 0ms; left -= 100ms) {
      bool all = true;
      for (const std::string& id : ids) {
        const std::string s = job(id).value("status", "");
        all = all && s != "queued" && s != "running";
      }
      if (all) return true;
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }
  std::string logs() { return "w1:\n" + workers_[0].output() + "\nw2:\n" + workers_[1].output(); }

  fs::path root_;
  std::string socket_, url_;
  Child redis_;
  Child workers_[2];
  std::unique_ptr<serve::Redis> broker_;
  std::unique_ptr<serve::Server> server_;
};

// The video a one-process render writes for the same request.
std::string reference_video(const json& body, const fs::path& file, app::Workspace& workspace) {
  serve::VideoJob job = serve::parse_video_job(body, 2000);
  job.say.output.output = file.string() + job.extension();
  app::RunContext context;
  context.workspace = &workspace;
  app::run(job.say, context);
  std::ifstream in(job.say.output.output, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(BrokerTest, EveryVideoArrivesAfterAWorkerIsKilledMidJob) {
  const std::vector<json> bodies{
      {{"text", "hello, how are you? thank you, good morning"}, {"size", "160x90"}, {"fps", 10}},
      {{"text", "hello"}, {"size", "160x90"}, {"fps", 10}},
      {{"text", "thank you"}, {"size", "160x90"}, {"fps", 10}, {"format", "webm"}},
      {{"text", "good morning"}, {"size", "160x90"}, {"fps", 8}, {"camera", "side"}},
  };
  std::vector<std::string> ids;
  for (const json& body : bodies) {
    const test::HttpReply r = http(port(), "POST", "/api/video", body.dump());
    ASSERT_EQ(r.status, 202) << r.body;
    ids.push_back(json::parse(r.body)["id"]);
  }

  // Kill the worker rendering the first (longest) job while it is under way.
  const std::string victim_job = ids[0];
  std::string victim;
  for (int i = 0; i < 12000 && victim.empty(); ++i) {
    const std::string status = job_field(victim_job, "status");
    ASSERT_TRUE(status == "queued" || status == "running") << "the long job ended before a worker could be killed: " << status << "\n" << logs();
    if (status == "running") victim = job_field(victim_job, "worker");
    if (victim.empty()) std::this_thread::sleep_for(10ms);
  }
  ASSERT_FALSE(victim.empty()) << logs();
  Child& killed = victim == "w1" ? workers_[0] : workers_[1];
  Child& survivor = victim == "w1" ? workers_[1] : workers_[0];
  ASSERT_EQ(killed.stop(SIGKILL), -1);
  EXPECT_EQ(job_field(victim_job, "status"), "running") << "killed mid-job";

  ASSERT_TRUE(wait_all(ids, 180s)) << logs();
  for (const std::string& id : ids) EXPECT_EQ(job(id)["status"], "done") << id << "\n" << logs();
  EXPECT_GE(std::stoi(job_field(victim_job, "attempts")), 2) << "the killed worker's job was taken over";
  EXPECT_EQ(job_field(victim_job, "worker"), victim == "w1" ? "w2" : "w1");
  EXPECT_NE(survivor.output().find("taken over from a silent worker"), std::string::npos) << logs();

  // Byte for byte what one process renders.
  app::Workspace workspace;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const test::HttpReply video = http(port(), "GET", "/api/jobs/" + ids[i] + "/download");
    ASSERT_EQ(video.status, 200) << video.body;
    EXPECT_EQ(video.headers.at("content-type"), i == 2 ? "video/webm" : "video/mp4");
    const std::string expected = reference_video(bodies[i], root_ / ("reference-" + std::to_string(i)), workspace);
    ASSERT_GT(expected.size(), 1000u);
    EXPECT_TRUE(video.body == expected) << "job " << i << ": " << video.body.size() << " bytes, one-process render " << expected.size();
  }
  // Acknowledged and deleted: nothing waits or runs; the survivor is counted.
  EXPECT_EQ(broker_->command({"XLEN", serve::broker::kStream}).integer, 0);
  const std::string metrics = http(port(), "GET", "/metrics").body;
  EXPECT_NE(metrics.find("gestura_job_queue_length 0"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("gestura_workers_seen "), std::string::npos) << metrics;
  EXPECT_EQ(metrics.find("gestura_workers_seen 0"), std::string::npos) << metrics;

  // SIGTERM: the survivor stops cleanly.
  EXPECT_EQ(survivor.stop(SIGTERM), 0) << survivor.output();
  EXPECT_NE(survivor.output().find("stopped"), std::string::npos);
}

TEST_F(BrokerTest, MalformedEntriesAreDeadLetteredAndTheWorkerStaysUp) {
  // Entries no API server would write: no id, a payload that is not JSON, one naming a file.
  const std::string not_json = "00000000000000a1", names_file = "00000000000000a2";
  for (const std::string& id : {not_json, names_file})
    broker_->command({"HSET", serve::broker::job_key(id), "status", "queued", "format", "mp4", "content_type", "video/mp4", "version", "1"});
  broker_->command({"XADD", serve::broker::kStream, "*", "payload", "{}"});
  broker_->command({"XADD", serve::broker::kStream, "*", "id", not_json, "payload", std::string("\x00\xff\xfe garbage", 12)});
  broker_->command({"XADD", serve::broker::kStream, "*", "id", names_file, "payload", R"({"text": "hi", "output": "/etc/passwd.mp4"})"});
  // A good job after them is still rendered.
  const test::HttpReply r = http(port(), "POST", "/api/video", R"({"text": "hello", "size": "160x90", "fps": 10})");
  ASSERT_EQ(r.status, 202) << r.body;
  const std::string good = json::parse(r.body)["id"];
  // Its progress arrives over the WebSocket from the broker's record, until it is done.
  {
    namespace asio = boost::asio;
    namespace beast = boost::beast;
    asio::io_context io;
    beast::websocket::stream<beast::tcp_stream> ws(io);
    beast::get_lowest_layer(ws).connect({asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port())});
    ws.handshake("127.0.0.1", "/api/jobs/" + good + "/events");
    std::string status, ended;
    int messages = 0, with_frames = 0;
    for (; messages < 10000; ++messages) {
      beast::flat_buffer buffer;
      beast::error_code ec;
      ws.read(buffer, ec);
      if (ec) {
        ended = ec.message();
        break;
      }
      const json m = json::parse(beast::buffers_to_string(buffer.data()));
      status = m["status"];
      with_frames += m["total"].get<int>() > 0;
      if (status != "queued" && status != "running") {
        EXPECT_EQ(m["download"], "/api/jobs/" + good + "/download");
        EXPECT_EQ(m["done"], m["total"]);
        break;
      }
    }
    EXPECT_EQ(status, "done") << "after " << messages << " messages: " << ended;
    EXPECT_GE(with_frames, 1) << "frame counts came through";
  }
  ASSERT_TRUE(wait_all({not_json, names_file, good}, 120s)) << logs();
  EXPECT_EQ(job(good)["status"], "done");

  const json failed = job(not_json);
  EXPECT_EQ(failed["status"], "failed");
  EXPECT_EQ(failed["error"]["field"], "payload") << failed;
  const json refused = job(names_file);
  EXPECT_EQ(refused["status"], "failed");
  EXPECT_EQ(refused["error"]["field"], "output") << refused;

  const serve::RedisReply dead = broker_->command({"XRANGE", serve::broker::kDead, "-", "+"});
  ASSERT_EQ(dead.elements.size(), 3u) << logs();
  std::map<std::string, std::string> reasons;  // job id → reason (two workers: any order)
  for (const serve::RedisReply& e : dead.elements) reasons[e.elements[1].field("id")] = e.elements[1].field("reason");
  EXPECT_NE(reasons[""].find("no job id"), std::string::npos) << reasons[""];
  EXPECT_NE(reasons[not_json].find("not JSON"), std::string::npos) << reasons[not_json];
  EXPECT_NE(reasons[names_file].find("output"), std::string::npos) << reasons[names_file];
  EXPECT_EQ(broker_->command({"XLEN", serve::broker::kStream}).integer, 0);
  EXPECT_TRUE(workers_[0].running() && workers_[1].running()) << logs();
  EXPECT_NE(http(port(), "GET", "/metrics").body.find("gestura_jobs_dead_letters 3"), std::string::npos);
}

}  // namespace
}  // namespace gestura
