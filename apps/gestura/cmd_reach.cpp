// gestura reach: an arm of the default avatar reaches for a point (app/reach.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/reach.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::ReachRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::ReachResult r = app::run(*request, context);
    const vec3 t = *request->target;
    const bool two_bone = request->solver == app::IkSolver::two_bone;
    if (r.clamped) std::printf("two-bone: the analytic solution was clamped to the joint limits\n");
    std::printf("avatar %s arm, solver %s, target (%.3f, %.3f, %.3f)\n", request->arm == app::ArmSide::left ? "left" : "right",
                app::TextCodec<app::IkSolver>::format(request->solver).c_str(), t.x, t.y, t.z);
    std::printf("solve: %d iterations, residual %.6f m, %.1f us%s\n", r.solve.iterations, r.residual, r.seconds * 1e6,
                r.residual < 1e-4f ? ""
                : two_bone         ? " (two-bone aims the wrist with the ready hand offset; the turned forearm moves the hand)"
                                   : " (out of reach or blocked by joint limits: closest reach)");
    if (r.written)
      std::printf("wrote %s: %d frames, ready posture to reach on a minimum-jerk profile\n", r.written->path.c_str(),
                  request->frames + 1);
    return 0;
  };
  return invocation;
}

const Registration reg{{"reach", "the avatar reaches for a point with one arm (IK: ccd, dls, combined or two-bone)",
                        "The default avatar (metres, +Y up, facing +Z, its left is +X) puts the middle knuckle of\n"
                        "its left (default) or right hand on the target: one IK solve (default: combined) from the\n"
                        "ready posture, within the joints' limits (two-bone: shoulder and elbow only, the hand kept\n"
                        "as in the ready posture, so it lands near, not on, the target). -o writes N+1 frames at\n"
                        "--fps moving from the ready posture to the reach on a minimum-jerk profile; a single .png\n"
                        "shows the reach. A negative coordinate first needs no quoting: --target -0.2,1.2,0.3.\n" +
                            std::string(app::kMotionOutputHelp),
                        prepare}};

}  // namespace
}  // namespace gestura::cli
