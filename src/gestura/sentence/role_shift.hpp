#pragma once
// Role shift (docs/grammar.md): quoted speech is signed as the person quoted. Over the quote the
// signer's shoulders and head turn toward that person's place in the signing space and the eyes
// leave the addressee for it; they turn back after. The turn enters and leaves with sinusoidal
// ramps like the face's actions.
//
// Sizes: the upper spine turns kRoleShiftTorsoDegrees (shared by vt12, vt6 and vt1, inside their
// ±12° each), the head kRoleShiftHeadDegrees more, the eyes look at the place.
#include <span>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/face/head_motion.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/text/gloss.hpp"

namespace gestura {

inline constexpr float kRoleShiftTorsoDegrees = 18.0f;
inline constexpr float kRoleShiftHeadDegrees = 12.0f;
inline constexpr float kRoleShiftRamp = 0.25f;  // seconds in and out (at most a third of the span)

// One quote as performed: seconds, and the place turned toward.
struct TimedRoleShift {
  float start = 0.0f, end = 0.0f;
  Locus toward;
};

// How far the shift is in at time t, 0..1, and its signed yaw direction (+1 toward the avatar's left).
float role_shift_weight(std::span<const TimedRoleShift> shifts, float t, float* direction = nullptr);

// The head's share of the turn, as head actions (face/head_motion.hpp) to add to the non-manual ones.
std::vector<face::HeadAction> role_shift_head_actions(std::span<const TimedRoleShift> shifts);

// Turns the upper spine (vt12, vt6, vt1) toward each shift's place, keyed on the ramps and composed
// onto the keys those joints already have. Joints the skeleton lacks are skipped.
void write_role_shift_torso(std::span<const TimedRoleShift> shifts, const Skeleton& skeleton, Clip& clip);

// The eyes: on the spelling hand where the clip's gaze_hands channel says so (face/eye_gaze.hpp), on
// the quoted person's place during a shift, straight ahead otherwise. Without shifts this is
// face::write_eye_gaze.
void write_gaze_with_role_shift(std::span<const TimedRoleShift> shifts, const SigningRig& rig, Clip& clip, float fps);

}  // namespace gestura
