#pragma once
// Where /api/video jobs go: an interface with two homes.
//   - LocalRenderJobs (default): the in-process queue, rendered by --jobs threads of this server.
//   - RedisRenderJobs (--broker URL): a Redis stream that `gestura worker` processes on any machine
//     take jobs from; status, progress and the finished video live in Redis, so any API server
//     answers for any job and keeps no state of its own.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "gestura/serve/job_queue.hpp"
#include "gestura/serve/video_job.hpp"

namespace gestura::serve {

// A done job's video: a local file, or its bytes.
struct JobResult {
  std::string file;
  std::string bytes;
  std::string content_type;
};

class RenderJobs {
 public:
  virtual ~RenderJobs() = default;
  // Queues a checked job (`body` is the request JSON it was parsed from). The job's id, or
  // nothing when the queue is full. Broker failures throw BrokerUnavailable (503).
  virtual std::optional<std::string> submit(const nlohmann::json& body, const VideoJob& job) = 0;
  virtual std::optional<JobState> state(const std::string& id) = 0;
  // Stops a queued or running job; false when there is no such job or it has finished.
  virtual bool cancel(const std::string& id) = 0;
  // The video of a done job; nothing when it is not (or no longer) there.
  virtual std::optional<JobResult> result(const std::string& id) = 0;
  virtual std::size_t waiting() = 0;
  virtual std::size_t running() = 0;
  // Further lines of /metrics in the Prometheus text format (the broker's: workers seen, ...).
  virtual std::string metrics() { return {}; }
};

}  // namespace gestura::serve
