#include "gestura/app/reach.hpp"

#include <chrono>

#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/ik/reference_arm.hpp"

namespace gestura::app {
namespace {

// Minimum jerk: position fraction at time fraction τ for a point-to-point move from rest to rest.
float minimum_jerk(float tau) { return tau * tau * tau * (10.0f + tau * (-15.0f + 6.0f * tau)); }

// The motion as a clip with one key per frame on every joint (and the root's translation).
Clip interpolate_motion(const Skeleton& skeleton, const Pose& from, const Pose& to, int frames, float frame_time) {
  Clip clip;
  clip.name = "reach";
  clip.resize_joints(skeleton.size());
  clip.duration = static_cast<float>(frames) * frame_time;
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    const RotationOrder order = skeleton.dofs[j].order;
    const vec3 a = quat_to_euler(from.rotations[j], order);
    const vec3 b = quat_to_euler_near(to.rotations[j], order, a);
    for (int f = 0; f <= frames; ++f) {
      const float t = static_cast<float>(f) * frame_time;
      clip.rotations[j].add(t, euler_to_quat(glm::mix(a, b, minimum_jerk(static_cast<float>(f) / static_cast<float>(frames))), order));
    }
  }
  clip.translations[0].add(0.0f, from.translations[0]);
  return clip;
}

}  // namespace

IkSolver TextCodec<IkSolver>::parse(std::string_view text) {
  if (text == "ccd") return IkSolver::ccd;
  if (text == "dls") return IkSolver::dls;
  if (text == "combined") return IkSolver::combined;
  if (text == "two-bone") return IkSolver::two_bone;
  throw Error("'" + std::string(text.substr(0, 40)) + "' is not ccd, dls, combined or two-bone");
}

std::string TextCodec<IkSolver>::format(IkSolver solver) {
  switch (solver) {
    case IkSolver::ccd: return "ccd";
    case IkSolver::dls: return "dls";
    case IkSolver::two_bone: return "two-bone";
    case IkSolver::combined: break;
  }
  return "combined";
}

ArmSide TextCodec<ArmSide>::parse(std::string_view text) {
  if (text == "l" || text == "left") return ArmSide::left;
  if (text == "r" || text == "right") return ArmSide::right;
  throw Error("'" + std::string(text.substr(0, 40)) + "' is not l or r");
}

void validate(const ReachRequest& request) {
  check_fields(request);
  validate(request.output, false);
}

ReachResult run(const ReachRequest& request, const RunContext& context) {
  validate(request);
  const vec3 target = *request.target;
  const std::string side = request.arm == ArmSide::left ? "l" : "r";
  const Skeleton skeleton = build_avatar_skeleton();
  const IkChain chain = arm_chain(skeleton, side);
  IkWorkspace ws(chain);
  const int shoulder = chain.joints.front(), wrist = chain.joints.back();
  const Pose ready = arm_ready_pose(skeleton, side);
  Pose pose = ready;
  std::vector<mat4> model(skeleton.size());
  const mat4 base = parent_model_matrix(skeleton, pose, shoulder);
  const auto effector = [&] {
    local_to_model(skeleton, pose, model);
    return vec3(model[static_cast<std::size_t>(wrist)] * vec4(chain.effector_offset, 1.0f));
  };

  ReachResult result;
  const auto t0 = std::chrono::steady_clock::now();
  if (request.solver == IkSolver::two_bone) {
    // The two-bone solver places the wrist: aim it a hand's length short of the goal along the
    // ready posture's wrist → effector direction. Right arm: the pole point mirrors in X.
    const vec3 effector_at_ready = effector();
    const vec3 hand = effector_at_ready - vec3(model[static_cast<std::size_t>(wrist)][3]);
    const vec3 shoulder_at = vec3(model[static_cast<std::size_t>(shoulder)][3]);
    const vec3 pole = shoulder_at + vec3(side == "l" ? 0.4f : -0.4f, -0.5f, -0.6f);  // out, down, behind
    const int elbow = skeleton.parents[static_cast<std::size_t>(wrist)];
    const LimbIkResult r = solve_limb(skeleton, pose, shoulder, elbow, wrist, vec3(-1, 0, 0), target - hand, pole);
    result.solve = IkResult{1, r.position_error, 0.0f, r.position_error < 1e-4f};
    result.clamped = r.clamped;
  } else {
    result.solve = request.solver == IkSolver::ccd ? solve_ccd(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose)
                   : request.solver == IkSolver::dls
                       ? solve_dls(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose)
                       : solve_combined(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.residual = glm::length(effector() - target);
  if (!request.output.output.empty()) {
    const int fps = request.output.picture.rate();
    result.clip = interpolate_motion(skeleton, ready, pose, request.frames, 1.0f / static_cast<float>(fps));
    std::optional<Avatar> avatar;  // its skeleton is build_avatar_skeleton()'s, so the clip fits its body
    if (output_shows_body(request.output)) avatar = build_avatar();
    context.check_stop();
    result.written = write_motion(request.output, skeleton, result.clip, avatar ? &avatar->mesh : nullptr,
                                  result.clip.duration, context);
  }
  return result;
}

nlohmann::json to_json(const ReachResult& result) {
  nlohmann::json out{{"iterations", result.solve.iterations},
                     {"residual", result.residual},
                     {"seconds", result.seconds},
                     {"clamped", result.clamped}};
  if (result.written) out["written"] = {{"path", result.written->path}, {"frames", result.written->frames}};
  return out;
}

}  // namespace gestura::app
