#pragma once
// The default home of /api/video jobs: the in-process JobQueue, each job rendered with a
// workspace leased from the server's pool, its file under --data/jobs.
#include "gestura/serve/render_jobs.hpp"
#include "gestura/serve/workspace_pool.hpp"

namespace gestura::serve {

class LocalRenderJobs final : public RenderJobs {
 public:
  LocalRenderJobs(std::string folder, int workers, std::size_t capacity, WorkspacePool& workspaces);

  std::optional<std::string> submit(const nlohmann::json& body, const VideoJob& job) override;
  std::optional<JobState> state(const std::string& id) override { return queue_.state(id); }
  bool cancel(const std::string& id) override { return queue_.cancel(id); }
  std::optional<JobResult> result(const std::string& id) override;
  std::size_t waiting() override { return queue_.waiting(); }
  std::size_t running() override { return queue_.running(); }

 private:
  WorkspacePool& workspaces_;
  JobQueue queue_;  // last: its workers stop before the pool goes
};

}  // namespace gestura::serve
