#include "gestura/sign/hand_geometry.hpp"

#include <algorithm>
#include <vector>

namespace gestura {

void hand_surface_points(const SigningRig& rig, Hand hand, std::span<const mat4> model, HandPoints& out) {
  const HandRig& h = rig.hand(hand);
  const mat4& wrist = model[joint_slot(h.wrist)];
  const vec3 centre = vec3(wrist * vec4(h.palm_centre_local, 1.0f));
  // The palm normal at bind pose, carried by the wrist.
  const vec3 rest_palm_in_wrist = glm::inverse(h.rest_wrist_rotation) * (h.rest_frame.rotation * vec3(0, 0, 1));
  const vec3 palm = glm::normalize(vec3(wrist * vec4(rest_palm_in_wrist, 0.0f)));
  out[kPalmFacePoints] = centre + palm * h.palm_half_thickness;
  out[kPalmFacePoints + 1] = centre - palm * h.palm_half_thickness;
  for (std::size_t f = 0; f < 5; ++f) out[kTipPoints + f] = joint_position(model, h.tips[f]);
  for (std::size_t f = 1; f < 5; ++f) out[kKnucklePoints + f - 1] = joint_position(model, h.fingers[f][0]);
  for (std::size_t f = 0; f < 5; ++f) out[kMiddleJointPoints + f] = joint_position(model, h.fingers[f][1]);
}

HandState rest_hand_state(const SigningRig& rig, Hand hand) {
  const HandRig& h = rig.hand(hand);
  HandState s;
  s.position = vec3(rig.bind_model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
  s.orientation = h.rest_frame.rotation;
  s.shape = make_handshape(BasicHandshape::Flat);
  for (auto& f : s.shape.fingers) f = FingerFlexion{deg(8), deg(10), deg(5)};  // relaxed, not rigid
  s.active = false;
  return s;
}

HandState relaxed_hand_state(const SigningRig& rig, Hand hand) {
  std::vector<mat4> model(rig.skeleton().size());
  local_to_model(rig.skeleton(), rig.neutral, model);
  const HandRig& h = rig.hand(hand);
  const mat4& wrist = model[joint_slot(h.wrist)];
  HandState s = rest_hand_state(rig, hand);
  s.position = vec3(wrist * vec4(h.palm_centre_local, 1.0f));
  // The hand frame turns with the wrist from its bind-pose relation.
  s.orientation = glm::normalize(glm::quat_cast(mat3(wrist)) * glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation);
  s.active = true;
  return s;
}

quat planned_wrist_rotation(const SigningRig& rig, Hand hand, const HandState& state) {
  const HandRig& h = rig.hand(hand);
  return wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation}, h.rest_frame.rotation,
                            h.rest_wrist_rotation);
}

HandPoints planned_hand_points(const SigningRig& rig, Hand hand, const HandState& state, Pose& scratch) {
  const HandRig& h = rig.hand(hand);
  apply_hand_posture(rig, hand, state.shape, scratch);
  clamp_to_limits(rig.skeleton(), scratch);  // as the performer will
  // FK of the posed fingers; only their place relative to the wrist matters.
  thread_local std::vector<mat4> model;
  model.resize(rig.skeleton().size());
  local_to_model(rig.skeleton(), scratch, model);
  HandPoints points;
  hand_surface_points(rig, hand, model, points);
  const mat4 to_wrist = glm::inverse(model[joint_slot(h.wrist)]);
  const quat turn = planned_wrist_rotation(rig, hand, state);
  for (vec3& p : points) p = turn * (vec3(to_wrist * vec4(p, 1.0f)) - h.palm_centre_local);
  return points;
}

float hand_penetration(const SigningRig& rig, Hand hand, std::span<const mat4> model, HandPoints& points) {
  hand_surface_points(rig, hand, model, points);
  float deepest = -1e9f;
  for (const vec3& p : points) deepest = std::max(deepest, -body_signed_distance(rig, model, p));
  return deepest;
}

}  // namespace gestura
