#pragma once
// Eye gaze to the signing hand (sign-language-interpreter.txt: the signer looks at the hand while
// fingerspelling, then back at the viewer). The clip's gaze_hands channel (face_channels.hpp) says
// how much: at weight w the eyes, and the head for the part beyond the eyes' own range, turn w of the
// way from straight ahead to the dominant (right) hand's palm centre — the midpoint of r_wrist and
// r_middle1 (eye_aim.hpp does the aiming). The channel's sinusoidal ramps make the turns smooth; the
// hand is followed frame by frame as it moves. The spelling hand sits ~40° below and ~40° to the side
// of the eyes, so eyes and head turn about half of it each.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

// Writes rotation keys for both eyeball joints, vc4 and skullbase every 1/fps over the clip
// (replacing their tracks; the head keeps the motion it had wherever the gaze channel is 0), after
// the body and the head's own movements are animated (the aim depends on where they are). Does nothing
// when the clip has no gaze_hands channel. Throws gestura::Error when the skeleton lacks the eye,
// head or hand joints, the clip has tracks for another skeleton, or fps is outside 1–240.
void write_eye_gaze(const Skeleton& skeleton, Clip& clip, float fps);

}  // namespace gestura::face
