#pragma once
// Eye gaze to the signing hand (sign-language-interpreter.txt: the signer looks at the hand while
// fingerspelling, then back at the viewer). The clip's gaze_hands channel (face_channels.hpp) says
// how much: at weight w each eyeball joint turns w of the way from straight ahead to the dominant
// (right) hand's palm centre — the midpoint of r_wrist and r_middle1 — aimed on its own, so the
// two eyes converge on the hand. The channel's sinusoidal ramps make the turns smooth; the hand is
// followed frame by frame as it moves. Angles stay inside the eye joints' limits.
//
// Eye–head coordination: the eyes alone carry a gaze shift of up to kEyeOnlyDegrees (per axis);
// beyond that the head turns by the rest (split over vc4 and skullbase like head_motion.hpp, added
// to the head movements already in the clip), as people recruit the head for large gaze shifts
// (Freedman & Sparks 1997, from memory: the head's share grows with amplitude past ~20°). The
// spelling hand sits ~40° below and ~40° to the side of the eyes, so both turn about half of it.
//
// Contract with the skeleton: joints l_eyeball_joint and r_eyeball_joint look along their rest
// frame's +Z (the avatar's gaze direction at rest) and turn by yaw (y) and pitch (x); vc4 and
// skullbase turn like head_motion.hpp says (pitch = x, + nods forward; yaw = y).
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

inline constexpr float kEyeOnlyDegrees = 20.0f;

// Writes rotation keys for both eyeball joints, vc4 and skullbase every 1/fps over the clip
// (replacing their tracks; the head keeps the motion it had wherever the gaze channel is 0), after
// the body and the head's own movements are animated (the aim depends on where they are). Does nothing
// when the clip has no gaze_hands channel. Throws gestura::Error when the skeleton lacks the eye or
// hand joints, the clip has tracks for another skeleton, or fps is outside 1–240.
void write_eye_gaze(const Skeleton& skeleton, Clip& clip, float fps);

}  // namespace gestura::face
