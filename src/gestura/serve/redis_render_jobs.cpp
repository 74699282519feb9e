#include "gestura/serve/redis_render_jobs.hpp"

#include <chrono>
#include <random>

#include "gestura/serve/broker_keys.hpp"
#include "gestura/serve/random_hex.hpp"

namespace gestura::serve {
namespace {


long long now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

JobStatus status_of(const std::string& text) {
  if (text == "running") return JobStatus::running;
  if (text == "done") return JobStatus::done;
  if (text == "failed") return JobStatus::failed;
  if (text == "cancelled") return JobStatus::cancelled;
  return JobStatus::queued;
}

int int_of(const std::string& text) {
  try {
    return text.empty() ? 0 : std::stoi(text);
  } catch (...) {
    return 0;
  }
}

// Ids are the server's 16 hex digits: anything else names no job (and no other key).
bool valid_id(const std::string& id) {
  return id.size() == 16 && id.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

void ensure_job_stream(Redis& redis) {
  try {
    redis.command({"XGROUP", "CREATE", broker::kStream, broker::kGroup, "0", "MKSTREAM"});
  } catch (const RedisReplyError& e) {
    if (std::string_view(e.what()).find("BUSYGROUP") == std::string_view::npos) throw;
  }
}

RedisRenderJobs::Lease::Lease(RedisRenderJobs& owner) : owner_(owner) {
  {
    std::lock_guard lock(owner_.mutex_);
    if (!owner_.idle_.empty()) {
      redis_ = std::move(owner_.idle_.back());
      owner_.idle_.pop_back();
    }
  }
  // Short timeouts: the WebSocket loop asks for a job's state on the network threads.
  if (!redis_) redis_ = std::make_unique<Redis>(owner_.url_, std::chrono::seconds(2));
}

RedisRenderJobs::Lease::~Lease() {
  std::lock_guard lock(owner_.mutex_);
  owner_.idle_.push_back(std::move(redis_));
}

RedisRenderJobs::RedisRenderJobs(BrokerUrl url, std::size_t capacity) : url_(std::move(url)), capacity_(capacity) {
  Lease redis(*this);
  ensure_job_stream(*redis);
}

std::size_t RedisRenderJobs::pending(Redis& redis) {
  const RedisReply summary = redis.command({"XPENDING", broker::kStream, broker::kGroup});
  return summary.elements.empty() ? 0 : static_cast<std::size_t>(summary.elements[0].integer);
}

std::optional<std::string> RedisRenderJobs::submit(const nlohmann::json& body, const VideoJob& job) {
  Lease redis(*this);
  // Acknowledged entries are deleted, so the stream holds the jobs waiting and running.
  const long long length = redis->command({"XLEN", broker::kStream}).integer;
  if (static_cast<std::size_t>(std::max(0ll, length)) >= capacity_ + pending(*redis)) return std::nullopt;
  const std::string id = random_hex();
  const std::string key = broker::job_key(id);
  redis->command({"HSET", key, "status", "queued", "format", job.format, "content_type", job.content_type(), "version", "1",
                  "attempts", "0", "created", std::to_string(now_ms())});
  redis->command({"EXPIRE", key, std::to_string(broker::kKeepSeconds)});
  redis->command({"XADD", broker::kStream, "*", "id", id, "payload", body.dump()});
  return id;
}

std::optional<JobState> RedisRenderJobs::state(const std::string& id) {
  if (!valid_id(id)) return std::nullopt;
  Lease redis(*this);
  const RedisReply h = redis->command({"HGETALL", broker::job_key(id)});
  if (h.elements.empty()) return std::nullopt;
  JobState s;
  s.id = id;
  s.status = status_of(h.field("status"));
  s.stage = h.field("stage");
  s.done = int_of(h.field("done"));
  s.total = int_of(h.field("total"));
  s.error_json = h.field("error");
  s.content_type = h.field("content_type");
  s.version = static_cast<std::uint64_t>(int_of(h.field("version")));
  return s;
}

bool RedisRenderJobs::cancel(const std::string& id) {
  if (!valid_id(id)) return false;
  Lease redis(*this);
  return redis->command({"EVAL", broker::kCancelScript, "1", broker::job_key(id)}).integer == 1;
}

std::optional<JobResult> RedisRenderJobs::result(const std::string& id) {
  if (!valid_id(id)) return std::nullopt;
  Lease redis(*this);
  const RedisReply type = redis->command({"HGET", broker::job_key(id), "content_type"});
  const RedisReply video = redis->command({"GET", broker::video_key(id)});
  if (video.is_nil()) return std::nullopt;
  return JobResult{{}, video.text, type.text};
}

std::size_t RedisRenderJobs::waiting() {
  Lease redis(*this);
  const long long length = redis->command({"XLEN", broker::kStream}).integer;
  const std::size_t held = pending(*redis);
  return length > 0 && static_cast<std::size_t>(length) > held ? static_cast<std::size_t>(length) - held : 0;
}

std::size_t RedisRenderJobs::running() {
  Lease redis(*this);
  return pending(*redis);
}

std::string RedisRenderJobs::metrics() {
  Lease redis(*this);
  const long long seen = redis->command({"ZCOUNT", broker::kWorkers, std::to_string(now_ms() - broker::kWorkerSeenMs), "+inf"}).integer;
  const long long dead = redis->command({"XLEN", broker::kDead}).integer;
  return "# HELP gestura_workers_seen Render workers seen by the broker in the last 30 s.\n"
         "# TYPE gestura_workers_seen gauge\n"
         "gestura_workers_seen " + std::to_string(seen) + "\n"
         "# HELP gestura_jobs_dead_letters Job entries the workers dead-lettered (gestura:dead).\n"
         "# TYPE gestura_jobs_dead_letters gauge\n"
         "gestura_jobs_dead_letters " + std::to_string(dead) + "\n";
}

}  // namespace gestura::serve
