#pragma once
// /api/video jobs through Redis Streams (gestura serve --broker URL): submit adds an entry to the
// stream for `gestura worker` processes; status, progress and the video are read back from Redis
// (layout: broker_keys.hpp). The server holds nothing a second server would need.
#include <memory>
#include <mutex>
#include <vector>

#include "gestura/serve/broker_url.hpp"
#include "gestura/serve/redis.hpp"
#include "gestura/serve/render_jobs.hpp"

namespace gestura::serve {

class RedisRenderJobs final : public RenderJobs {
 public:
  // Connects and creates the stream and its group when missing; throws BrokerUnavailable.
  RedisRenderJobs(BrokerUrl url, std::size_t capacity);

  std::optional<std::string> submit(const nlohmann::json& body, const VideoJob& job) override;
  std::optional<JobState> state(const std::string& id) override;
  bool cancel(const std::string& id) override;
  std::optional<JobResult> result(const std::string& id) override;
  std::size_t waiting() override;
  std::size_t running() override;
  std::string metrics() override;

 private:
  // A connection of the pool for one call (request threads and the WebSocket loop share them).
  class Lease {
   public:
    explicit Lease(RedisRenderJobs& owner);
    ~Lease();
    Redis* operator->() { return redis_.get(); }
    Redis& operator*() { return *redis_; }

   private:
    RedisRenderJobs& owner_;
    std::unique_ptr<Redis> redis_;
  };
  std::size_t pending(Redis& redis);

  BrokerUrl url_;
  std::size_t capacity_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Redis>> idle_;
};

// Creates the stream and the consumer group when missing (servers and workers both call it).
void ensure_job_stream(Redis& redis);

}  // namespace gestura::serve
