// gestura reach: an arm of the default avatar reaches for a point (alias-movement-through-environments.txt
// §6.2). One IK solve from the signer's ready posture finds the reaching posture (printed: iterations,
// residual, time); the motion then moves every joint from the ready posture to it on a minimum-jerk
// profile (Flash & Hogan: s = 10τ³ − 15τ⁴ + 6τ⁵, zero velocity and acceleration at both ends), Euler
// angles interpolated per joint, so every frame stays inside the joints' limit boxes.
#include <chrono>
#include <optional>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/ik/reference_arm.hpp"
#include "motion_output.hpp"

namespace {

using namespace gestura;

vec3 parse_point(const std::string& text) {
  vec3 v(0.0f);
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x >> comma1 >> v.y >> comma2 >> v.z) || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !is_finite(v))
    throw Error("--target: expected x,y,z in metres, got '" + text + "'");
  return v;
}

// Minimum jerk: position fraction at time fraction τ for a point-to-point move from rest to rest.
float minimum_jerk(float tau) { return tau * tau * tau * (10.0f + tau * (-15.0f + 6.0f * tau)); }

// The motion as a clip with one key per frame on every joint that moves (and the root's translation).
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

int run_reach(const std::vector<std::string>& args) {
  std::string solver = "combined", side = "l";
  cli::MotionOutput out;
  vec3 target(0.0f);
  bool has_target = false;
  int frames = 30;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--target") target = parse_point(cli::flag_value(args, i)), has_target = true;
    else if (args[i] == "--solver") solver = cli::flag_value(args, i);
    else if (args[i] == "--arm") side = cli::flag_value(args, i);
    else if (cli::parse_motion_output_flag(args, i, out)) continue;
    else if (args[i] == "--frames") {
      const std::string v = cli::flag_value(args, i);
      try {
        std::size_t used = 0;
        frames = std::stoi(v, &used);
        if (used != v.size() || frames < 1 || frames > 100000) throw std::invalid_argument(v);
      } catch (const std::exception&) {
        throw Error("--frames: expected a whole number in 1..100000, got '" + v + "'");
      }
    } else throw Error("unknown argument '" + args[i] + "' (see gestura reach --help)");
  }
  if (!has_target) throw Error("--target x,y,z is required");
  if (solver != "ccd" && solver != "dls" && solver != "combined" && solver != "two-bone")
    throw Error("--solver: expected ccd, dls, combined or two-bone, got '" + solver + "'");
  if (side != "l" && side != "r") throw Error("--arm: expected l or r, got '" + side + "'");
  if (!out.path.empty()) cli::check_motion_output(out);

  const Skeleton skeleton = build_avatar_skeleton();
  const IkChain chain = arm_chain(skeleton, side);
  IkWorkspace ws(chain);
  const int shoulder = chain.joints.front(), wrist = chain.joints.back();
  const Pose ready = arm_ready_pose(skeleton, side);
  Pose pose = ready;
  std::vector<mat4> model(skeleton.size());
  const mat4 base = parent_model_matrix(skeleton, pose, shoulder);
  auto effector = [&] {
    local_to_model(skeleton, pose, model);
    return vec3(model[static_cast<std::size_t>(wrist)] * vec4(chain.effector_offset, 1.0f));
  };

  IkResult result;
  const auto t0 = std::chrono::steady_clock::now();
  if (solver == "two-bone") {
    // The two-bone solver places the wrist: aim it a hand's length short of the goal along the
    // ready posture's wrist → effector direction. Right arm: the pole point mirrors in X.
    const vec3 effector_at_ready = effector();
    const vec3 hand = effector_at_ready - vec3(model[static_cast<std::size_t>(wrist)][3]);
    const vec3 shoulder_at = vec3(model[static_cast<std::size_t>(shoulder)][3]);
    const vec3 pole = shoulder_at + vec3(side == "l" ? 0.4f : -0.4f, -0.5f, -0.6f);  // out, down, behind
    const int elbow = skeleton.parents[static_cast<std::size_t>(wrist)];
    const LimbIkResult r = solve_limb(skeleton, pose, shoulder, elbow, wrist, vec3(-1, 0, 0), target - hand, pole);
    result = IkResult{1, r.position_error, 0.0f, r.position_error < 1e-4f};
    if (r.clamped) std::printf("two-bone: the analytic solution was clamped to the joint limits\n");
  } else {
    result = solver == "ccd"   ? solve_ccd(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose)
             : solver == "dls" ? solve_dls(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose)
                               : solve_combined(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const float residual = glm::length(effector() - target);
  std::printf("avatar %s arm, solver %s, target (%.3f, %.3f, %.3f)\n", side == "l" ? "left" : "right", solver.c_str(),
              target.x, target.y, target.z);
  std::printf("solve: %d iterations, residual %.6f m, %.1f us%s\n", result.iterations, residual, seconds * 1e6,
              residual < 1e-4f      ? ""
              : solver == "two-bone" ? " (two-bone aims the wrist with the ready hand offset; the turned forearm moves the hand)"
                                     : " (out of reach or blocked by joint limits: closest reach)");
  if (!out.path.empty()) {
    const Clip clip = interpolate_motion(skeleton, ready, pose, frames, 1.0f / static_cast<float>(out.fps));
    std::optional<Avatar> avatar;  // its skeleton is build_avatar_skeleton()'s, so the clip fits its body
    if (cli::output_shows_body(out)) avatar = build_avatar();
    cli::write_motion(out, skeleton, clip, avatar ? &avatar->mesh : nullptr, clip.duration);
    std::printf("wrote %s: %d frames, ready posture to reach on a minimum-jerk profile\n", out.path.c_str(), frames + 1);
  }
  return 0;
}

const cli::Registration reg{{"reach", "the avatar reaches for a point with one arm (IK: ccd, dls, combined or two-bone)",
                             "usage: gestura reach --target x,y,z [--arm l|r] [--solver ccd|dls|combined|two-bone]\n"
                             "                     [--frames N] [-o OUT [--fps N] [--size WxH] [--camera LIST] [--sheet]]\n"
                             "  The default avatar (metres, +Y up, facing +Z, its left is +X) puts the middle knuckle\n"
                             "  of its left (default) or right hand on the target: one IK solve (default: combined)\n"
                             "  from the ready posture, within the joints' limits (two-bone: shoulder\n"
                             "  and elbow only, the hand kept as in the ready posture, so it lands near, not on, the\n"
                             "  target). -o writes N+1 frames at --fps (default N = 30, 30 fps) moving from the ready\n"
                             "  posture to the reach on a minimum-jerk profile; a single .png shows the reach.\n" +
                                 std::string(cli::kMotionOutputUsage),
                             run_reach}};

}  // namespace
