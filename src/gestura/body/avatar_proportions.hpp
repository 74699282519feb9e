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
inline constexpr float kThumbPalmReach = 0.050f;

// The face at 1.70 m (model space, metres), shared by the volume (sockets, lips, oral cavity), the
// rigid face parts (eyeballs, teeth, tongue) and the facial morphs.
inline constexpr float kEyeballRadius = 0.0130f;
inline constexpr float kLidThickness = 0.0028f;  // the lid skin ball over the eyeball is this much larger
// The almond of the eye opening: an ellipsoid (relative to the eyeball centre) carved out of the lid
// ball; where it reaches below the eyeball's surface, the eyeball shows.
inline constexpr float kEyeOpeningCentre[3] = {0.0f, -0.0005f, 0.0060f};
inline constexpr float kEyeOpeningRadii[3] = {0.0145f, 0.0052f, 0.0120f};
inline constexpr float kMouthLineY = 1.5255f;  // where the lips meet
// The jaw is open by this much while the surface is polygonised, so the lips come out as two
// separate sheets with the oral cavity behind them; the rest mesh then closes it by skinning.
inline constexpr float kBindJawOpenDegrees = 6.5f;
// … and closes it by this much more, so the lips press into each other and no slit shows at rest.
inline constexpr float kLipPressDegrees = 1.5f;

// A row of teeth along a parabolic dental arch: its mid-line runs from (0, front_z) at the incisors
// to (±half_width, back_z) at the last tooth shown; crowns between edge_y (biting edge) and root_y
// (hidden in the gum).
struct DentalArch {
  float front_z, back_z, half_width;
  float edge_y, root_y;
  float thickness;  // labial to lingual
};
// The upper incisors close just in front of and over the lower ones (overjet, overbite).
inline constexpr DentalArch kUpperTeeth{0.0755f, 0.0565f, 0.0200f, 1.5238f, 1.5380f, 0.0048f};
inline constexpr DentalArch kLowerTeeth{0.0710f, 0.0540f, 0.0180f, 1.5262f, 1.5125f, 0.0044f};

// The tongue at rest: an ellipsoid on the floor of the mouth, its tip behind the lower incisors.
inline constexpr float kTongueCentre[3] = {0.0f, 1.5195f, 0.0490f};
inline constexpr float kTongueRadii[3] = {0.0155f, 0.0050f, 0.0170f};

}  // namespace gestura::proportions
