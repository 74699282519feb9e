#pragma once
// Render jobs run in the background by a fixed number of workers (the in-process queue). A job is
// a function that writes one file and reports progress; the queue keeps its status for the API:
//
//   queued → running → done (the file) | failed (an error JSON) | cancelled
//
// At most `capacity` jobs wait; submit() refuses more (the API answers 503). Finished jobs are
// kept until `keep` newer ones finished, then forgotten and their files removed.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "gestura/app/context.hpp"

namespace gestura::serve {

enum class JobStatus { queued, running, done, failed, cancelled };
std::string to_string(JobStatus status);

// What a job does: writes `file` (the queue chose its path), reporting to and stopping by context.
using JobWork = std::function<void(const std::string& file, const app::RunContext& context)>;

struct JobState {
  std::string id;
  JobStatus status = JobStatus::queued;
  std::string stage;
  int done = 0, total = 0;
  std::string file;        // where the result is (done)
  std::string error_json;  // failed: the error object of the API
  std::string content_type;
  std::uint64_t version = 0;  // grows with every change (progress listeners poll it)
};

class JobQueue {
 public:
  // `folder` receives the files (created when missing).
  JobQueue(std::string folder, int workers, std::size_t capacity, std::size_t keep = 64);
  ~JobQueue();  // cancels running jobs, waits for the workers
  JobQueue(const JobQueue&) = delete;
  JobQueue& operator=(const JobQueue&) = delete;

  // The job's id, or nothing when the queue is full. `extension` is the file's (".mp4").
  std::optional<std::string> submit(JobWork work, const std::string& extension, const std::string& content_type);
  std::optional<JobState> state(const std::string& id) const;
  // Stops a queued or running job; false when there is no such job or it has finished.
  bool cancel(const std::string& id);

  std::size_t waiting() const;
  std::size_t running() const;

 private:
  struct Job {
    JobState state;
    JobWork work;
    std::stop_source stop;
  };
  void work_loop(std::stop_token stop);
  void forget_old_locked();

  std::string folder_;
  std::size_t capacity_, keep_;
  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  std::map<std::string, std::shared_ptr<Job>> jobs_;
  std::deque<std::shared_ptr<Job>> waiting_;
  std::deque<std::string> finished_;
  std::size_t running_ = 0;
  std::vector<std::jthread> workers_;
};

}  // namespace gestura::serve
