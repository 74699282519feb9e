#pragma once
// A 7-DoF human left arm with anatomical limits, the test and benchmark subject of the IK solvers.
//
// Rest pose: arm hanging at the side, bones along −Y, every rest rotation identity (so joint angles
// are rotations about model axes at rest). Limits are Table 1 of sign-language-interpreter.txt:
//   l_shoulder  order XYZ  x: flexion 188° (negative: the arm swings forward, +Z) / extension 61°
//                          y: humeral rotation ±85° (not in Table 1; a typical passive range)
//                          z: abduction 134° (positive: out to +X) / adduction 48°
//   l_elbow     x only:    flexion 142° (negative), no hyperextension
//   l_wrist     order YZX  y: supination 113° (positive) / pronation 77° — the forearm twist, carried
//                             by the wrist joint so the arm keeps one joint per segment
//                          z: abduction (radial deviation) 47° (positive) / adduction 27°
//                          x: flexion 90° (negative, toward the palm at +Z) / extension 99°
// The middle Euler angle of each joint has a range inside ±90°, so Euler angles read back from a
// rotation (joint_angles) are unique and a pose inside the limits is always recognised as such.
// Segments: shoulder at (0.18, 1.40, 0), upper arm 0.30 m, forearm 0.26 m, hand 0.09 m to the
// effector site l_hand_site. Chain root "humanoid_root" (no DoF) sits at the origin.
#include <string_view>

#include "gestura/ik/chain.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

Skeleton reference_arm_skeleton();

// The IK chain <side>_shoulder → <side>_wrist (side "l" or "r") with the effector at the rest
// position of joint `effector`, a descendant of the wrist (default: <side>_hand_site when the
// skeleton has it, else <side>_middle1, the middle knuckle). Works on the reference arm and on any
// skeleton with H-Anim names. Throws gestura::Error naming a missing joint.
IkChain arm_chain(const Skeleton& skeleton, std::string_view side = "l", std::string_view effector = {});

// The signer's ready posture as a starting guess for the iterative solvers: upper arm 30° forward and
// 20° out, elbow bent 70°, wrist neutral. Starting from the straight rest arm instead puts the elbow
// on its limit, where a local solver can sit still (bending the other way is not allowed, and with
// the target on the arm's line neither bend looks better to a gradient).
// Assumes the H-Anim avatar convention of rest frames parallel to the model frame, flexion about −x
// and left abduction about +z (a right arm mirrors z).
Pose arm_ready_pose(const Skeleton& skeleton, std::string_view side = "l");

}  // namespace gestura
