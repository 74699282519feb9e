#include "gestura/serve/job_queue.hpp"

#include <filesystem>
#include <random>

#include "gestura/serve/api_error.hpp"
#include "gestura/serve/random_hex.hpp"

namespace gestura::serve {

std::string to_string(JobStatus status) {
  switch (status) {
    case JobStatus::queued: return "queued";
    case JobStatus::running: return "running";
    case JobStatus::done: return "done";
    case JobStatus::failed: return "failed";
    case JobStatus::cancelled: return "cancelled";
  }
  return "unknown";
}

JobQueue::JobQueue(std::string folder, int workers, std::size_t capacity, std::size_t keep)
    : folder_(std::move(folder)), capacity_(capacity), keep_(keep) {
  std::filesystem::create_directories(folder_);
  for (int i = 0; i < workers; ++i) workers_.emplace_back([this](std::stop_token stop) { work_loop(stop); });
}

JobQueue::~JobQueue() {
  {
    std::lock_guard lock(mutex_);
    for (auto& [id, job] : jobs_) job->stop.request_stop();
  }
  for (auto& w : workers_) w.request_stop();
  wake_.notify_all();
  workers_.clear();  // joins
}

std::optional<std::string> JobQueue::submit(JobWork work, const std::string& extension, const std::string& content_type) {
  std::lock_guard lock(mutex_);
  if (waiting_.size() >= capacity_) return std::nullopt;
  auto job = std::make_shared<Job>();
  job->state.id = random_hex();
  job->state.file = (std::filesystem::path(folder_) / (job->state.id + extension)).string();
  job->state.content_type = content_type;
  job->work = std::move(work);
  jobs_[job->state.id] = job;
  waiting_.push_back(job);
  wake_.notify_one();
  return job->state.id;
}

std::optional<JobState> JobQueue::state(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  return it->second->state;
}

bool JobQueue::cancel(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return false;
  Job& job = *it->second;
  if (job.state.status == JobStatus::queued) {
    std::erase(waiting_, it->second);
    job.state.status = JobStatus::cancelled;
    ++job.state.version;
    finished_.push_back(id);
    forget_old_locked();
    return true;
  }
  if (job.state.status != JobStatus::running) return false;
  job.stop.request_stop();
  return true;
}

std::size_t JobQueue::waiting() const {
  std::lock_guard lock(mutex_);
  return waiting_.size();
}
std::size_t JobQueue::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

void JobQueue::forget_old_locked() {
  while (finished_.size() > keep_) {
    const auto it = jobs_.find(finished_.front());
    if (it != jobs_.end()) {
      std::error_code ec;
      std::filesystem::remove(it->second->state.file, ec);
      jobs_.erase(it);
    }
    finished_.pop_front();
  }
}

void JobQueue::work_loop(std::stop_token stop) {
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, stop, [&] { return !waiting_.empty(); });
      if (stop.stop_requested()) return;
      job = waiting_.front();
      waiting_.pop_front();
      job->state.status = JobStatus::running;
      ++job->state.version;
      ++running_;
    }
    app::RunContext context;
    context.stop = job->stop.get_token();
    context.progress = [this, job](const app::ProgressUpdate& p) {
      std::lock_guard lock(mutex_);
      job->state.stage = p.stage;
      job->state.done = p.done;
      job->state.total = p.total;
      ++job->state.version;
    };
    JobStatus status = JobStatus::done;
    std::string error;
    try {
      job->work(job->state.file, context);
    } catch (...) {
      const app::ErrorReport report = app::classify_current();
      status = report.category == app::ErrorCategory::cancelled ? JobStatus::cancelled : JobStatus::failed;
      error = error_response(report).body;
      std::error_code ec;
      std::filesystem::remove(job->state.file, ec);
    }
    std::lock_guard lock(mutex_);
    job->state.status = status;
    job->state.error_json = error;
    job->work = nullptr;
    ++job->state.version;
    --running_;
    finished_.push_back(job->state.id);
    forget_old_locked();
  }
}

}  // namespace gestura::serve
