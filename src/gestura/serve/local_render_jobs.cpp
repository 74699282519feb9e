#include "gestura/serve/local_render_jobs.hpp"

namespace gestura::serve {

LocalRenderJobs::LocalRenderJobs(std::string folder, int workers, std::size_t capacity, WorkspacePool& workspaces)
    : workspaces_(workspaces), queue_(std::move(folder), workers, capacity) {}

std::optional<std::string> LocalRenderJobs::submit(const nlohmann::json&, const VideoJob& job) {
  return queue_.submit(
      [this, say = job.say](const std::string& file, const app::RunContext& context) {
        app::SayRequest r = say;
        r.output.output = file;
        const WorkspacePool::Lease workspace = workspaces_.acquire();
        app::RunContext c = context;
        c.workspace = workspace.get();
        app::run(r, c);
      },
      job.extension(), job.content_type());
}

std::optional<JobResult> LocalRenderJobs::result(const std::string& id) {
  const std::optional<JobState> s = queue_.state(id);
  if (!s || s->status != JobStatus::done) return std::nullopt;
  return JobResult{s->file, {}, s->content_type};
}

}  // namespace gestura::serve
