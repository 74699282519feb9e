#include "gestura/sign/sign_performer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gestura/core/error.hpp"
#include "gestura/sign/hand_solver.hpp"

namespace gestura {

void hand_surface_points(const SigningRig& rig, Hand hand, std::span<const mat4> model, std::vector<vec3>& out) {
  const HandRig& h = rig.hand(hand);
  const mat4& w = model[static_cast<std::size_t>(h.wrist)];
  const vec3 centre = vec3(w * vec4(h.palm_centre_local, 1.0f));
  // The palm normal at bind pose, carried by the wrist.
  const vec3 rest_palm_in_wrist = glm::inverse(h.rest_wrist_rotation) * (h.rest_frame.rotation * vec3(0, 0, 1));
  const vec3 palm = glm::normalize(vec3(w * vec4(rest_palm_in_wrist, 0.0f)));
  out.clear();
  out.push_back(centre + palm * h.palm_half_thickness);
  out.push_back(centre - palm * h.palm_half_thickness);
  for (int f = 0; f < 5; ++f) out.push_back(vec3(model[static_cast<std::size_t>(h.tips[static_cast<std::size_t>(f)])][3]));
  for (int f = 1; f < 5; ++f) out.push_back(vec3(model[static_cast<std::size_t>(h.fingers[static_cast<std::size_t>(f)][0])][3]));
  for (int f = 0; f < 5; ++f) out.push_back(vec3(model[static_cast<std::size_t>(h.fingers[static_cast<std::size_t>(f)][1])][3]));
}

float hand_penetration(const SigningRig& rig, Hand hand, std::span<const mat4> model, std::vector<vec3>& points) {
  hand_surface_points(rig, hand, model, points);
  float deepest = -1e9f;
  for (const vec3& p : points) deepest = std::max(deepest, -body_signed_distance(rig, model, p));
  return deepest;
}

Clip perform_plan(const SignPlan& plan, const SigningRig& rig, const PerformOptions& options, PerformanceStats* stats) {
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("fps must be between 1 and 240");
  const Skeleton& s = rig.skeleton();
  const float duration = plan.duration();
  const int frames = std::max(2, static_cast<int>(std::ceil(duration * options.fps)) + 1);

  // Joints this clip drives: both arms from the clavicle down, and the fingers.
  std::vector<int> driven;
  for (const HandRig& h : rig.hands) {
    driven.insert(driven.end(), h.arm.joints.begin(), h.arm.joints.end());
    for (const auto& f : h.fingers) driven.insert(driven.end(), f.begin(), f.end());
  }

  Clip clip;
  clip.name = "sign";
  clip.duration = static_cast<float>(frames - 1) / options.fps;
  clip.resize_joints(s.size());
  for (int j : driven) {
    QuatTrack& tr = clip.rotations[static_cast<std::size_t>(j)];
    tr.interpolation = Interpolation::Linear;
    tr.times.reserve(static_cast<std::size_t>(frames));
    tr.values.reserve(static_cast<std::size_t>(frames));
  }

  Pose pose = rig.neutral;
  std::vector<mat4> model(s.size());
  HandSolverState solver[2] = {HandSolverState(rig.hands[0].arm), HandSolverState(rig.hands[1].arm)};
  std::vector<vec3> points;
  PerformanceStats st;
  st.frames = frames;
  // Key frames per hand: the frame nearest the end of each segment that leaves the hand signing.
  std::vector<std::uint8_t> key[2];
  for (int side = 0; side < 2; ++side) {
    key[side].assign(static_cast<std::size_t>(frames), 0);
    for (const HandSegment& seg : (side == 0 ? plan.right : plan.left).segments)
      if (seg.to.active)  // 2: a posture at the body, 1: out in space
        key[side][static_cast<std::size_t>(std::clamp(static_cast<int>(std::lround(seg.end * options.fps)), 0, frames - 1))] =
            seg.to.at_body ? 2 : 1;
  }
  HandState planned[2];
  quat planned_wrist[2];

  for (int f = 0; f < frames; ++f) {
    const float t = static_cast<float>(f) / options.fps;
    for (int side = 0; side < 2; ++side) {
      const HandRig& h = rig.hands[static_cast<std::size_t>(side)];
      const HandTimeline& tl = side == 0 ? plan.right : plan.left;
      const HandState state = tl.segments.empty() ? rest_hand_state(rig, h.hand) : sample_hand(tl, t);
      apply_hand_posture(rig, h.hand, state.shape, pose);
      const quat wrist_rotation = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation},
                                                     h.rest_frame.rotation, h.rest_wrist_rotation);
      planned[side] = state;
      planned_wrist[side] = wrist_rotation;
      if (!state.active) {
        // At rest: the arm hangs exactly in its rest pose (a stretched arm at its limits is a
        // singular target for the iterative solvers).
        for (int j : h.arm.joints) pose.rotations[static_cast<std::size_t>(j)] = rig.rest.rotations[static_cast<std::size_t>(j)];
        solver[side].swivel.reset();
        continue;
      }
      const HandSolveResult r = solve_hand(rig, h.hand, state, options.body_margin, f % 3 == 0, solver[side], pose,
                                           model, points);
      st.max_position_error = std::max(st.max_position_error, r.position_error);
      st.max_orientation_error = std::max(st.max_orientation_error, r.orientation_error);
    }
    clamp_to_limits(s, pose);
    local_to_model(s, pose, model);
    for (const HandRig& h : rig.hands)
      st.max_penetration = std::max(st.max_penetration, hand_penetration(rig, h.hand, model, points));
    for (int side = 0; side < 2; ++side) {
      if (!key[side][static_cast<std::size_t>(f)] || !planned[side].active) continue;
      const HandRig& h = rig.hands[static_cast<std::size_t>(side)];
      const mat4& w = model[static_cast<std::size_t>(h.wrist)];
      // At the body, the hand's place is where it meets the body (its contact point); in space, the palm centre.
      float dp = glm::distance(vec3(w * vec4(h.palm_centre_local, 1.0f)), planned[side].position);
      const bool at_body = key[side][static_cast<std::size_t>(f)] == 2;
      if (at_body) {
        hand_surface_points(rig, h.hand, model, points);
        std::size_t contact = 0;
        const vec3 planned_point = planned_contact(rig, h.hand, planned[side], model, points, contact);
        dp = glm::distance(planned_point, points[contact]);
      }
      const float da = glm::length(rotation_error(glm::normalize(glm::quat_cast(mat3(w))), planned_wrist[side]));
      if (at_body && dp > st.key_position_error) st.key_position_error = dp, st.key_position_time = t;
      if (!at_body && dp > st.key_space_position_error)
        st.key_space_position_error = dp, st.key_space_position_time = t;
      if (da > st.key_orientation_error) st.key_orientation_error = da, st.key_orientation_time = t;
    }
    for (int j : driven) clip.rotations[static_cast<std::size_t>(j)].add(t, pose.rotations[static_cast<std::size_t>(j)]);
  }
  for (int j : driven) make_continuous(clip.rotations[static_cast<std::size_t>(j)]);
  if (stats) *stats = st;
  return clip;
}

}  // namespace gestura
