#include "gestura/sign/sign_performer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gestura/core/error.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/hand_solver.hpp"

namespace gestura {

Clip perform_plan(const SignPlan& plan, const SigningRig& rig, const PerformOptions& options, PerformanceStats* stats) {
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("fps must be between 1 and 240");
  const Skeleton& s = rig.skeleton();
  const float duration = plan.duration();
  const std::size_t frames = std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(duration * options.fps)) + 1);

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
    QuatTrack& tr = clip.rotations[joint_slot(j)];
    tr.interpolation = Interpolation::Linear;
    tr.times.reserve(frames);
    tr.values.reserve(frames);
  }

  Pose pose = rig.neutral;
  std::vector<mat4> model(s.size());
  ByHand<HandSolverState> solver{{HandSolverState(rig.hand(Hand::Right).arm), HandSolverState(rig.hand(Hand::Left).arm)}};
  HandPoints points;
  PerformanceStats st;
  st.frames = static_cast<int>(frames);
  // The key frame of each segment that leaves a hand signing: the frame nearest its end.
  enum class Key : std::uint8_t { None, InSpace, AtBody };
  auto frame_of = [&](float t) {
    return std::min(static_cast<std::size_t>(std::max(0L, std::lround(t * options.fps))), frames - 1);
  };
  ByHand<std::vector<Key>> key;
  for (Hand hand : kBothHands) {
    key[hand].assign(frames, Key::None);
    for (const HandSegment& seg : plan.hand(hand).segments)
      if (seg.to.active) key[hand][frame_of(seg.end)] = seg.to.at_body ? Key::AtBody : Key::InSpace;
  }
  ByHand<HandState> planned;

  for (std::size_t f = 0; f < frames; ++f) {
    const float t = static_cast<float>(f) / options.fps;
    for (Hand hand : kBothHands) {
      const HandTimeline& timeline = plan.hand(hand);
      planned[hand] = timeline.segments.empty() ? rest_hand_state(rig, hand) : sample_hand(timeline, t);
      const HandSolveResult r =
          pose_hand(rig, hand, planned[hand], options.body_margin, f % 3 == 0, solver[hand], pose, model, points);
      st.max_position_error = std::max(st.max_position_error, r.position_error);
      st.max_orientation_error = std::max(st.max_orientation_error, r.orientation_error);
    }
    clamp_to_limits(s, pose);
    local_to_model(s, pose, model);
    for (Hand hand : kBothHands) st.max_penetration = std::max(st.max_penetration, hand_penetration(rig, hand, model, points));
    for (Hand hand : kBothHands)
      if (planned[hand].active)
        st.max_elbow_rise = std::max(st.max_elbow_rise, joint_position(model, rig.hand(hand).elbow).y -
                                                            joint_position(model, rig.hand(hand).shoulder).y);
    for (Hand hand : kBothHands) {
      const Key k = key[hand][f];
      if (k == Key::None || !planned[hand].active) continue;
      const HandRig& h = rig.hand(hand);
      const mat4& w = model[joint_slot(h.wrist)];
      // At the body, the hand's place is where it meets the body (its contact point); in space, the palm centre.
      float dp = glm::distance(vec3(w * vec4(h.palm_centre_local, 1.0f)), planned[hand].position);
      if (k == Key::AtBody) {
        hand_surface_points(rig, hand, model, points);
        std::size_t contact = 0;
        const vec3 planned_point = planned_contact(rig, hand, planned[hand], model, points, contact);
        dp = glm::distance(planned_point, points[contact]);
      }
      const float da =
          glm::length(rotation_error(glm::normalize(glm::quat_cast(mat3(w))), planned_wrist_rotation(rig, hand, planned[hand])));
      if (k == Key::AtBody && dp > st.key_position_error) st.key_position_error = dp, st.key_position_time = t;
      if (k == Key::InSpace && dp > st.key_space_position_error)
        st.key_space_position_error = dp, st.key_space_position_time = t;
      if (da > st.key_orientation_error) st.key_orientation_error = da, st.key_orientation_time = t;
    }
    for (int j : driven) clip.rotations[joint_slot(j)].add(t, pose.rotations[joint_slot(j)]);
  }
  for (int j : driven) make_continuous(clip.rotations[joint_slot(j)]);
  if (stats) *stats = st;
  return clip;
}

}  // namespace gestura
