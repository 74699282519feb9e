#include "gestura/serve/render_worker.hpp"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <stop_token>
#include <thread>

#include <nlohmann/json.hpp>

#include "gestura/app/error.hpp"
#include "gestura/serve/api_error.hpp"
#include "gestura/serve/broker_keys.hpp"
#include "gestura/serve/redis.hpp"
#include "gestura/serve/redis_render_jobs.hpp"
#include "gestura/serve/video_job.hpp"

namespace gestura::serve {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

long long now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

bool valid_id(const std::string& id) {
  return id.size() == 16 && id.find_first_not_of("0123456789abcdef") == std::string::npos;
}

std::string default_name() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0 || !host[0]) std::snprintf(host, sizeof host, "worker");
  return std::string(host) + "-" + std::to_string(getpid());
}

// Sleeps up to `total`, returning early when a stop is raised.
void nap(std::chrono::milliseconds total, const std::atomic<int>& stop) {
  for (auto left = total; left > 0ms && stop.load() == 0; left -= 100ms) std::this_thread::sleep_for(std::min(left, std::chrono::milliseconds(100)));
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw app::AppError(app::ErrorCategory::output, app::Place{"data", {}}, "cannot read the rendered " + path.string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The API's error JSON for a job that cannot run.
std::string error_json(app::ErrorCategory category, const std::string& message) {
  return error_response(app::ErrorReport{category, {}, message}).body;
}

}  // namespace

// One entry of the stream: its id there and its fields (nil when the entry was deleted).
struct RenderWorker::Entry {
  std::string stream_id;
  RedisReply fields;
  std::string job_id() const { return fields.field("id"); }
};

RenderWorker::RenderWorker(WorkerOptions options, Log log) : options_(std::move(options)), log_(std::move(log)) {
  app::check_fields(options_);
  url_ = parse_broker_url(options_.broker);
  if (options_.name.empty()) options_.name = default_name();
  if (options_.name.size() > 200 || options_.name.find_first_of(" \t\r\n") != std::string::npos)
    app::usage_error("name", "is at most 200 characters without blanks");
  if (options_.data.empty()) {
    std::string templ = (fs::temp_directory_path() / "gestura-worker-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw app::AppError(app::ErrorCategory::output, app::Place{"data", {}}, "cannot create a temporary folder");
    options_.data = templ;
  }
  std::error_code ec;
  fs::create_directories(options_.data, ec);
  if (ec || !fs::is_directory(options_.data))
    throw app::AppError(app::ErrorCategory::output, app::Place{"data", {}}, "cannot create folder " + options_.data + ": " + ec.message());
  if (!options_.lexicon.empty()) setenv("GESTURA_LEXICON", options_.lexicon.c_str(), 1);  // the workspace's user lexicon
  workspace_ = std::make_unique<app::Workspace>(app::user_citation_store());
}

RenderWorker::~RenderWorker() = default;

void RenderWorker::run(const std::atomic<int>& stop) {
  const std::string me = "gestura worker " + options_.name + ": ";
  std::unique_ptr<Redis> redis;
  bool lost = false;
  auto backoff = 500ms;
  long long last_seen = 0;
  // Built before the first job is taken, so that a job's time is its render (and a worker that
  // joins the group is ready); a failure here is met again by the first job and reported there.
  try {
    workspace_->signer(app::AvatarChoice{});
  } catch (const std::exception& e) {
    log_(me + "could not prepare the default avatar: " + e.what());
  }
  while (stop.load() == 0) {
    try {
      if (!redis) {
        redis = std::make_unique<Redis>(url_, 5s);
        ensure_job_stream(*redis);
        log_(me + (lost ? "reconnected to the broker at " : "taking jobs from ") + url_.shown);
        lost = false;
        backoff = 500ms;
      }
      if (now_ms() - last_seen > 5000) {
        redis->command({"ZADD", broker::kWorkers, std::to_string(now_ms()), options_.name});
        last_seen = now_ms();
      }
      Entry entry;
      if (next_entry(*redis, entry)) process(*redis, entry, stop);
    } catch (const BrokerUnavailable& e) {
      redis.reset();
      log_(me + e.what() + "; reconnecting in " + std::to_string(backoff.count()) + " ms");
      lost = true;
      nap(backoff, stop);
      backoff = std::min(backoff * 2, std::chrono::milliseconds(5000));
    } catch (const RedisReplyError& e) {
      // The stream or group was removed under us, or the server refuses a command: start over.
      log_(me + "the broker refused a command: " + e.what());
      redis.reset();
      nap(1000ms, stop);
    } catch (const std::exception& e) {
      // Not the job's fault nor the broker's (memory, a full disk): the entry stays pending and
      // is claimed again; after kMaxDeliveries it is dead-lettered.
      log_(me + "unexpected failure: " + e.what());
      nap(1000ms, stop);
    }
  }
  try {
    if (redis) redis->command({"ZREM", broker::kWorkers, options_.name});
  } catch (...) {
  }
  log_(me + "stopped");
}

bool RenderWorker::next_entry(Redis& redis, Entry& entry) {
  // First a job whose holder went silent (killed, lost its network): its claim is stale.
  const RedisReply claimed = redis.command({"XAUTOCLAIM", broker::kStream, broker::kGroup, options_.name,
                                            std::to_string(options_.claim_after * 1000LL), "0-0", "COUNT", "1"});
  if (claimed.elements.size() >= 2) {
    for (const RedisReply& e : claimed.elements[1].elements) {
      if (e.elements.empty()) continue;
      entry.stream_id = e.elements[0].text;
      if (e.elements.size() > 1) entry.fields = e.elements[1];
      return true;
    }
  }
  // Then a new one, waiting a second at most so that a stop is seen.
  const RedisReply read = redis.command({"XREADGROUP", "GROUP", broker::kGroup, options_.name, "COUNT", "1", "BLOCK", "1000", "STREAMS",
                                         broker::kStream, ">"});
  if (read.is_nil() || read.elements.empty() || read.elements[0].elements.size() < 2) return false;
  const RedisReply& entries = read.elements[0].elements[1];
  if (entries.elements.empty() || entries.elements[0].elements.empty()) return false;
  entry.stream_id = entries.elements[0].elements[0].text;
  if (entries.elements[0].elements.size() > 1) entry.fields = entries.elements[0].elements[1];
  return true;
}

void RenderWorker::finish(Redis& redis, const Entry& entry) {
  redis.command({"XACK", broker::kStream, broker::kGroup, entry.stream_id});
  redis.command({"XDEL", broker::kStream, entry.stream_id});
}

void RenderWorker::fail(Redis& redis, const std::string& id, const std::string& error_json) {
  const std::string key = broker::job_key(id);
  if (redis.command({"EXISTS", key}).integer == 0) return;
  redis.command({"HSET", key, "status", "failed", "error", error_json, "worker", options_.name});
  redis.command({"HINCRBY", key, "version", "1"});
  redis.command({"EXPIRE", key, std::to_string(broker::kKeepSeconds)});
}

void RenderWorker::dead_letter(Redis& redis, const Entry& entry, const std::string& reason) {
  std::string payload = entry.fields.field("payload");
  if (payload.size() > 65536) payload.resize(65536);
  redis.command({"XADD", broker::kDead, "MAXLEN", "~", "10000", "*", "entry", entry.stream_id, "id", entry.job_id(), "reason", reason,
                 "payload", payload, "worker", options_.name, "time", std::to_string(now_ms())});
  log_("gestura worker " + options_.name + ": dead-lettered entry " + entry.stream_id + ": " + reason);
  finish(redis, entry);
}

void RenderWorker::process(Redis& redis, const Entry& entry, const std::atomic<int>& stop) {
  const std::string me = "gestura worker " + options_.name + ": ";
  const std::string id = entry.job_id();
  if (entry.fields.elements.empty()) return dead_letter(redis, entry, "the entry has no fields");
  if (!valid_id(id)) return dead_letter(redis, entry, "the entry has no job id (16 hex digits), got '" + id.substr(0, 64) + "'");

  // A job delivered again and again takes its workers down: stop passing it on.
  const RedisReply pending = redis.command({"XPENDING", broker::kStream, broker::kGroup, entry.stream_id, entry.stream_id, "1"});
  long long deliveries = 1;
  if (!pending.elements.empty() && pending.elements[0].elements.size() >= 4) deliveries = pending.elements[0].elements[3].integer;
  if (deliveries > broker::kMaxDeliveries) {
    const std::string reason = "delivered " + std::to_string(deliveries) + " times; every worker that took it stopped before finishing";
    fail(redis, id, error_json(app::ErrorCategory::internal, "the job could not be rendered: " + reason));
    return dead_letter(redis, entry, reason);
  }

  const std::string before = redis.command({"EVAL", broker::kStartScript, "1", broker::job_key(id), options_.name}).text;
  if (before == "missing") return dead_letter(redis, entry, "no record " + broker::job_key(id) + " (expired, or not made by an API server)");
  if (before != "queued" && before != "running") {
    finish(redis, entry);  // cancelled before it started, or finished by a worker thought dead
    return;
  }

  // The payload, checked by the API's own rules.
  const std::string payload = entry.fields.field("payload");
  const nlohmann::json body = nlohmann::json::parse(payload, nullptr, false);
  VideoJob job;
  try {
    if (body.is_discarded()) throw app::AppError(app::ErrorCategory::usage, app::Place{"payload", {}}, "the payload is not JSON");
    if (!body.is_object()) throw app::AppError(app::ErrorCategory::usage, app::Place{"payload", {}}, "the payload is not a JSON object");
    job = parse_video_job(body, options_.max_text);
  } catch (...) {
    const app::ErrorReport report = app::classify_current();
    fail(redis, id, error_response(report).body);
    return dead_letter(redis, entry, "malformed payload: " + (report.place.field.empty() ? "" : report.place.field + ": ") + report.message);
  }
  log_(me + "rendering job " + id + (before == "running" ? " (taken over from a silent worker)" : ""));

  // Beside the render: progress out, claim renewed, a cancel or a release (second stop) in.
  struct Shared {
    std::mutex mutex;
    app::ProgressUpdate progress;
    bool changed = false;
  } shared;
  enum class Stopped { no, cancelled, released };
  std::atomic<Stopped> stopped{Stopped::no};
  std::stop_source stop_render;
  const auto renew_every = std::chrono::milliseconds(std::max(200, options_.claim_after * 1000 / 3));
  std::jthread beside([&](std::stop_token done) {
    std::unique_ptr<Redis> side;
    auto last_renew = std::chrono::steady_clock::now();
    std::mutex m;
    std::condition_variable_any wake;
    while (!done.stop_requested()) {
      {
        std::unique_lock lock(m);
        wake.wait_for(lock, done, 200ms, [] { return false; });
      }
      if (done.stop_requested()) break;
      if (stop.load() >= 2 && stopped.load() == Stopped::no) {
        stopped = Stopped::released;
        stop_render.request_stop();
      }
      try {
        if (!side) side = std::make_unique<Redis>(url_, 2s);
        app::ProgressUpdate p;
        bool changed = false;
        {
          std::lock_guard lock(shared.mutex);
          std::swap(changed, shared.changed);
          p = shared.progress;
        }
        const std::string key = broker::job_key(id);
        if (changed) {
          side->command({"HSET", key, "stage", p.stage, "done", std::to_string(p.done), "total", std::to_string(p.total)});
          side->command({"HINCRBY", key, "version", "1"});
        }
        if (std::chrono::steady_clock::now() - last_renew >= renew_every) {
          // Claiming our own entry again resets its idle time: the claim stays fresh.
          side->command({"XCLAIM", broker::kStream, broker::kGroup, options_.name, "0", entry.stream_id, "JUSTID"});
          last_renew = std::chrono::steady_clock::now();
        }
        if (side->command({"HGET", key, "cancel"}).text == "1" && stopped.load() == Stopped::no) {
          stopped = Stopped::cancelled;
          stop_render.request_stop();
        }
      } catch (const std::exception&) {
        side.reset();  // the main loop reports a lost broker; the render goes on
      }
    }
  });

  const fs::path file = fs::path(options_.data) / (id + "-" + std::to_string(getpid()) + job.extension());
  struct Remove {
    fs::path path;
    ~Remove() {
      std::error_code ec;
      fs::remove(path, ec);
    }
  } remove{file};
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  bool cancelled = false;
  try {
    app::SayRequest say = job.say;
    say.output.output = file.string();
    app::RunContext context;
    context.workspace = workspace_.get();
    context.stop = stop_render.get_token();
    // Stages name the file being written: clients see its name, not this machine's folders.
    context.progress = [&shared, path = file.string(), shown = id + job.extension()](const app::ProgressUpdate& p) {
      std::lock_guard lock(shared.mutex);
      shared.progress = p;
      for (std::size_t at; (at = shared.progress.stage.find(path)) != std::string::npos;) shared.progress.stage.replace(at, path.size(), shown);
      shared.changed = true;
    };
    app::run(say, context);
  } catch (...) {
    const app::ErrorReport report = app::classify_current();
    cancelled = report.category == app::ErrorCategory::cancelled;
    error = error_response(report).body;
  }
  beside.request_stop();
  beside.join();

  const std::string key = broker::job_key(id);
  if (cancelled && stopped.load() == Stopped::released) {
    // Back to the queue, claimable at once: its idle time is set past any --claim-after.
    redis.command({"HSET", key, "status", "queued", "stage", "released by " + options_.name, "done", "0", "total", "0"});
    redis.command({"HINCRBY", key, "version", "1"});
    redis.command({"XCLAIM", broker::kStream, broker::kGroup, options_.name, "0", entry.stream_id, "IDLE", "100000000", "JUSTID"});
    log_(me + "released job " + id + " (stopping)");
    return;
  }
  if (cancelled) {
    redis.command({"HSET", key, "status", "cancelled", "stage", ""});
    redis.command({"HINCRBY", key, "version", "1"});
    log_(me + "cancelled job " + id);
    return finish(redis, entry);
  }
  if (!error.empty()) {
    fail(redis, id, error);
    log_(me + "job " + id + " failed: " + error);
    return finish(redis, entry);
  }
  // Stored first, acknowledged after: a worker dying in between leaves the job to be rendered again.
  std::string video;
  try {
    video = read_file(file);
  } catch (...) {
    fail(redis, id, current_error_response().body);
    log_(me + "job " + id + " failed: its video cannot be read back from " + file.string());
    return finish(redis, entry);
  }
  redis.command({"SET", broker::video_key(id), video, "EX", std::to_string(broker::kKeepSeconds)});
  const std::string frames = std::to_string(shared.progress.total);
  redis.command({"HSET", key, "status", "done", "stage", "", "done", frames, "total", frames, "worker", options_.name});
  redis.command({"HINCRBY", key, "version", "1"});
  redis.command({"EXPIRE", key, std::to_string(broker::kKeepSeconds)});
  finish(redis, entry);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char line[160];
  std::snprintf(line, sizeof line, "finished job %s (%zu bytes, %.2f s)", id.c_str(), video.size(), seconds);
  log_(me + line);
}

}  // namespace gestura::serve
