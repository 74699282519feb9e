#pragma once
// Head movements of non-manual markers (nods, tilts, the negation headshake) as angle actions that
// compose by adding, each entering and leaving with the same sinusoidal ramps as face actions
// (§5.2.5), optionally oscillating. The head angle is split over the neck (vc4, 40%) and skullbase
// (60%), in the avatar skeleton's axes: pitch = x (+ = nod forward), yaw = y (+ = turn to its left),
// roll = z.
#include <span>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

enum class HeadAxis { pitch, yaw, roll };

struct HeadAction {
  HeadAxis axis = HeadAxis::pitch;
  float start = 0.0f, end = 0.0f;  // seconds
  float amplitude = 0.0f;          // radians
  float frequency = 0.0f;          // Hz; 0 = hold the angle, > 0 = amplitude · sin(2πf(t − start))
};

inline constexpr float kNeckShare = 0.4f;  // of the head angle carried by vc4; skullbase takes the rest

// Summed head angles (pitch, yaw, roll) at time t, radians.
vec3 head_angles(std::span<const HeadAction> actions, float t);

// Writes rotation keys for vc4 and skullbase (rest rotation · Euler in each joint's order), sampled
// at every ramp step and 16 times per oscillation cycle, replacing their tracks. Sizes the clip's
// joint tracks to the skeleton when it has none. Nothing is written when `actions` is empty.
// Throws gestura::Error when the skeleton lacks vc4 or skullbase, the clip has tracks for another
// skeleton, or an action has non-finite values or ends before it starts.
void write_head_rotations(std::span<const HeadAction> actions, const Skeleton& skeleton, Clip& clip);

}  // namespace gestura::face
