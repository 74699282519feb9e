#pragma once
// The API: every route of `gestura serve` and the state the handlers share (the workspace of built
// avatars and lexicons, the render job queue, the metrics). Handlers are thin: JSON in, a request
// of the command layer (src/gestura/app) run, JSON or a binary out; errors by the app error model.
#include <filesystem>
#include <memory>
#include <map>
#include <mutex>
#include <string>

#include "gestura/app/workspace.hpp"
#include "gestura/serve/deadline.hpp"
#include "gestura/serve/render_jobs.hpp"
#include "gestura/serve/message.hpp"
#include "gestura/serve/metrics.hpp"
#include "gestura/serve/room.hpp"
#include "gestura/serve/router.hpp"
#include "gestura/serve/serve_options.hpp"
#include "gestura/serve/workspace_pool.hpp"

namespace gestura::serve {

class Api {
 public:
  // Checks the options (usage errors naming the field), creates --data when missing.
  explicit Api(ServeOptions options);
  ~Api();

  // Builds what the first requests need (the avatar, its signer, the avatar's .glb) so that the
  // first sentence does not wait for them; safe to call beside requests. Never throws.
  void warm_up();

  // Answers one request; never throws (every failure is an error response).
  ApiResponse handle(ApiRequest& request);
  // The route label of a request for /metrics, and whether it is a job's progress WebSocket
  // (then `job_id` is set).
  bool job_events(const ApiRequest& request, std::string& job_id) const;
  // Whether a request is a room's WebSocket (/ws/room/NAME); then `room` is set.
  bool room_socket(const ApiRequest& request, std::string& room) const;

  const ServeOptions& options() const { return options_; }
  Metrics& metrics() { return *metrics_; }
  // Shared, for what may outlive the Api: a connection's coroutine frame is destroyed with the
  // io_context, after the server has already let the Api go (its rooms' streams need the
  // io_context), and its "connection closed" count must not touch freed memory.
  std::shared_ptr<Metrics> shared_metrics() const { return metrics_; }
  RenderJobs& jobs() { return *jobs_; }
  Rooms& rooms() { return *rooms_; }
  // Whether a request only reads state (health, metrics, job status, static files): the server
  // answers those at once instead of queueing them behind signing.
  bool quick(ApiRequest& request) const;

  // The route label handle() used for the last match (for the access log and metrics).
  std::string route_name(ApiRequest& request) const;

 private:
  void add_routes();
  ApiResponse say(ApiRequest& request, const app::RunContext& context);
  ApiResponse sign(ApiRequest& request, const app::RunContext& context);
  ApiResponse gloss(ApiRequest& request, const app::RunContext& context);
  ApiResponse lexicon_search(ApiRequest& request, const app::RunContext& context);
  ApiResponse lexicon_entry(ApiRequest& request, const app::RunContext& context);
  ApiResponse avatar(ApiRequest& request);
  void avatar_bytes(app::Workspace& workspace, const std::string& look);  // builds a look's .glb once
  ApiResponse video(ApiRequest& request);
  ApiResponse job(ApiRequest& request);
  ApiResponse job_download(ApiRequest& request);
  ApiResponse job_cancel(ApiRequest& request);
  ApiResponse health();
  RoomServices room_services();
  std::shared_ptr<const HostGaze> host_gaze();
  std::shared_ptr<const HolisticFit> holistic_fit(const std::string& look);  // one per look, built once

  ServeOptions options_;
  std::filesystem::path data_, web_;
  std::unique_ptr<WorkspacePool> workspaces_;  // one per request thread and render job
  std::shared_ptr<Metrics> metrics_ = std::make_shared<Metrics>();
  Deadlines deadlines_;
  std::unique_ptr<RenderJobs> jobs_;  // the in-process queue or the broker (--broker)
  Router router_;
  std::mutex avatar_mutex_;
  struct AvatarBytes {
    std::string glb, etag;
  };
  std::map<std::string, AvatarBytes> avatar_glb_;  // by look
  std::unique_ptr<Rooms> rooms_;
  std::mutex host_mutex_;
  std::shared_ptr<const HostGaze> host_gaze_;
  std::mutex fit_mutex_;
  std::map<std::string, std::shared_ptr<const HolisticFit>> fits_;  // by look
};

}  // namespace gestura::serve
