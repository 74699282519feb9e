#pragma once
// Body measures shared by the skeleton builder and the body volume, at 1.70 m and build 1: the
// skeleton needs them to open the A-pose far enough that the hands clear the hips, the volume to
// shape the trunk, thighs and forearms.
#include "gestura/body/avatar_params.hpp"

namespace gestura::proportions {

inline constexpr float kPelvisHalfWidth = 0.150f;   // pelvis ellipsoid semi-axis in x
inline constexpr float kThighRadius = 0.080f;       // thigh capsule radius at the hip
inline constexpr float kWristSleeveRadius = 0.029f; // forearm (sleeve) radius at the wrist
inline constexpr float kForearmBlend = 0.025f;      // smooth-blend width of the forearm

inline float by_sex(Sex sex, float female, float neutral, float male) {
  return sex == Sex::Female ? female : sex == Sex::Male ? male : neutral;
}
inline float hip_factor(Sex sex) { return by_sex(sex, 1.08f, 1.0f, 0.95f); }
inline float thigh_factor(Sex sex) { return by_sex(sex, 1.04f, 1.0f, 0.98f); }

// Margins of a hand's detail box at height 1.70 m: flesh beyond the hand's joints (thumb and
// thenar are the bulkiest), and around the sleeve axis where the box is cut above the wrist.
inline float hand_flesh_margin(const AvatarParams& p) { return 0.020f * p.hand_size * p.finger_thickness + 0.006f; }
inline float sleeve_margin(const AvatarParams& p) { return (kWristSleeveRadius + 0.4f * kForearmBlend) * p.build + 0.006f; }
// How far the hand's joints reach towards the body (the thumb, on the palm side), per hand_size.
inline constexpr float kThumbPalmReach = 0.034f;

}  // namespace gestura::proportions
