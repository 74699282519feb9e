#include "gestura/sign/hand_part.hpp"

#include <vector>

namespace gestura {

namespace {

// Half the thickness of a finger and of the palm's edge (metres): the surface lies this far from
// the bones the skeleton gives.
constexpr float kFingerHalfThickness = 0.007f;
constexpr float kPalmHalfWidth = 0.042f;
constexpr float kExtended = 1.2f;  // radians of summed flexion below which a finger counts as extended

}  // namespace

std::optional<SurfacePoint> hand_part_site(const SigningRig& rig, Hand hand, const Pose& pose, const HandPosture& shape,
                                           const sign::SitePoint& part) {
  using S = sign::Site;
  const HandRig& h = rig.hand(hand);
  const Skeleton& s = rig.skeleton();
  thread_local std::vector<mat4> model;
  model.resize(s.size());
  local_to_model(s, pose, model);
  const mat4 to_wrist = glm::inverse(model[joint_slot(h.wrist)]);
  const quat wrist_from_rest = glm::inverse(h.rest_wrist_rotation);
  // The hand's axes at rest, in the wrist's frame (the rest pose keeps finger frames parallel).
  const vec3 palm = wrist_from_rest * (h.rest_frame.rotation * vec3(0, 0, 1));
  const vec3 along = wrist_from_rest * h.rest_frame.finger;
  const vec3 radial = wrist_from_rest * h.rest_frame.thumb_side;
  auto at = [&](int joint) { return vec3(to_wrist * model[joint_slot(joint)][3]); };
  // A phalanx's palmar direction: the palm normal carried by the phalanx's own rotation.
  auto palmar = [&](int joint) { return glm::normalize(vec3(to_wrist * model[joint_slot(joint)] * vec4(palm, 0.0f))); };

  const vec3 centre = h.palm_centre_local;
  const float t = h.palm_half_thickness;
  switch (part.site) {
    case S::palm: return SurfacePoint{centre + palm * t, palm};
    case S::hand_back: return SurfacePoint{centre - palm * t, -palm};
    case S::thumb_side: return SurfacePoint{centre + radial * kPalmHalfWidth, radial};
    case S::pinky_side: return SurfacePoint{centre - radial * kPalmHalfWidth, -radial};
    case S::thumb_ball: return SurfacePoint{centre + palm * t - along * 0.03f + radial * 0.02f, palm};
    case S::wrist_back: return SurfacePoint{-palm * t, -palm};
    case S::wrist_pulse: return SurfacePoint{palm * t, palm};
    case S::fingers: break;
    default: return std::nullopt;
  }

  // Finger parts, averaged over the named (or extended) fingers.
  std::uint8_t fingers = part.fingers.bits;
  if (fingers == 0) {
    for (Finger f : {Finger::Index, Finger::Middle, Finger::Ring, Finger::Pinky}) {
      const FingerFlexion& x = shape.finger(f);
      if (x.mcp + x.pip + x.dip < kExtended) fingers = static_cast<std::uint8_t>(fingers | finger_bit(f));
    }
    if (fingers == 0) fingers = 1u << 1;  // a closed hand: the index
  }
  SurfacePoint sum{vec3(0.0f), vec3(0.0f)};
  int count = 0;
  for (std::size_t f = 0; f < 5; ++f) {
    if (!((fingers >> f) & 1u)) continue;
    const auto& j = h.fingers[f];
    const vec3 tip = at(h.tips[f]), last = at(j[2]), middle = at(j[1]), base = at(j[0]);
    const vec3 pad_dir = palmar(j[2]);
    const vec3 side = (f == 4 ? -1.0f : 1.0f) * radial;  // the little finger's free side is ulnar
    SurfacePoint p;
    switch (part.finger_part.value_or(sign::FingerPart::pad)) {
      case sign::FingerPart::tip: p = {tip, glm::normalize(tip - last)}; break;
      case sign::FingerPart::pad: p = {0.35f * last + 0.65f * tip + pad_dir * kFingerHalfThickness, pad_dir}; break;
      case sign::FingerPart::nail: p = {0.35f * last + 0.65f * tip - pad_dir * kFingerHalfThickness, -pad_dir}; break;
      case sign::FingerPart::mid_joint: p = {middle - palmar(j[1]) * kFingerHalfThickness, -palmar(j[1])}; break;
      case sign::FingerPart::base: p = {base - palmar(j[0]) * kFingerHalfThickness, -palmar(j[0])}; break;
      case sign::FingerPart::side: p = {0.5f * (middle + last) + side * kFingerHalfThickness, side}; break;
    }
    sum.point += p.point;
    sum.normal += p.normal;
    ++count;
  }
  sum.point /= static_cast<float>(count);
  sum.normal = glm::length(sum.normal) > 1e-6f ? glm::normalize(sum.normal) : palm;
  return sum;
}

}  // namespace gestura
