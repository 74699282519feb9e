#pragma once
// What a caller hands every run() besides the request: where long jobs report progress, how they
// are stopped, and the workspace of built avatars and lexicons to reuse between requests.
//
//   RunContext ctx;
//   ctx.progress = [](const ProgressUpdate& p) { draw(p.stage, p.done, p.total); };
//   ctx.stop = source.get_token();                   // source.request_stop() cancels the job
//   SayResult r = run(request, ctx);                 // throws AppError{cancelled} when stopped
//
// The CLI draws progress on a terminal and stops on nothing; the server reports progress over its
// WebSocket and stops a job whose client left; the studio does both from its UI thread.
#include <functional>
#include <stop_token>
#include <string>

namespace gestura::app {

class Workspace;

struct ProgressUpdate {
  std::string stage;  // "rendering out.mp4", "signing cue 12"
  int done = 0;
  int total = 0;      // 0 when unknown
};

struct RunContext {
  std::function<void(const ProgressUpdate&)> progress;  // may be empty
  std::stop_token stop;                                 // default: never stops
  Workspace* workspace = nullptr;                       // null: each run builds what it needs
  std::string citation_store;  // for the run's own workspace: where solved signs are kept (app/workspace.hpp)

  void report(const std::string& stage, int done, int total) const {
    if (progress) progress({stage, done, total});
  }
  // Throws gestura::Cancelled when a stop was requested; long jobs call it between steps.
  void check_stop() const;
};

}  // namespace gestura::app
