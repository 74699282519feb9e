#pragma once
// Aiming the eyes at a point: the one geometry behind every "look at" of the avatar — the gaze on
// the spelling hand (face/eye_gaze.hpp) and SiGML's eye gaze at the hands HI/HC/HD
// (sign/sign_nonmanual.hpp) — so both look alike: same frame, same limits, same eye/head split.
//
// The head frame: the eyes' parent (skullbase) turned from its bind pose. In it, as in the model at
// bind pose, +Z is straight ahead, +Y up and +X the avatar's left. A direction there has a pitch
// (+ down) and a yaw (+ to the avatar's left). Each eye turns by yaw about the head's vertical, then
// by pitch (a Fick gimbal: no roll about the line of sight), converted into its own joint frame and
// clamped per axis to its limits. Each eye aims from its own centre, so the two converge on a near
// target.
//
// Eye–head coordination: the eyes alone carry a gaze shift of up to kEyeOnlyDegrees per axis; beyond
// that the head turns by the rest (split over vc4 and skullbase as head_motion.hpp splits head
// angles), as people recruit the head for large gaze shifts (Freedman & Sparks 1997, from memory:
// the head's share grows with amplitude past ~20°).
#include <array>
#include <functional>
#include <span>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

inline constexpr float kEyeOnlyDegrees = 20.0f;

// Pitch (x, + looks down) and yaw (y, + to the avatar's left) of a direction in the head frame, radians.
vec2 gaze_angles(vec3 direction);

// The part of gaze angles beyond the eyes' own range (kEyeOnlyDegrees per axis), with its sign:
// what the head turns when it joins the eyes.
vec2 beyond_eyes(vec2 gaze);

// The local rotation of eye joint `eye` looking at `target` (model space) `weight` (0..1) of the way
// from rest, within the joint's limits. `model` is the current pose (the eye's and its parent's
// entries are read), `bind` the bind pose's model matrices.
quat eye_rotation(const Skeleton& skeleton, int eye, std::span<const mat4> model, std::span<const mat4> bind,
                  vec3 target, float weight);

// What the eyes look at at one time: a point (model space), how far the eyes turn to it and how far
// the head joins them (both 0..1 of the full aim; 0 eyes = straight ahead at rest).
struct GazeTarget {
  vec3 point{0.0f};
  float eyes = 0.0f;
  float head = 0.0f;
};
// Called with each time and the body's pose there (model matrices, before any gaze turn).
using GazeAt = std::function<GazeTarget(float time, std::span<const mat4> model)>;

// Aims l_eyeball_joint and r_eyeball_joint at gaze(t) for every t in `times` (ascending; repeats are
// skipped), after the body and the head's own movements are animated (the aim depends on where they
// are), replacing the eyes' tracks. Where the head joins (GazeTarget::head > 0 at some time), vc4 and
// skullbase are keyed at every time too, their turn added to the head movements already in the clip.
// Sizes the clip's joint tracks to the skeleton when it has none. Throws gestura::Error when the
// skeleton lacks the eye joints (or vc4/skullbase where the head joins) or the clip has tracks for
// another skeleton.
// `reads`: the joints whose model matrices `gaze` reads (the others in `model` are then left
// unset, which spares computing the whole body each frame); empty: all.
void write_gaze(const Skeleton& skeleton, std::span<const float> times, const GazeAt& gaze, Clip& clip,
                std::span<const int> reads = {});

}  // namespace gestura::face
