#pragma once
// Analytic two-bone IK (shoulder–elbow–wrist, hip–knee–ankle) over plain model-space data.
//
// The mid joint is a hinge: turning it about `mid_axis` sets the distance start→end by the law of
// cosines; the start joint then swings the whole limb onto the target and turns it about the
// start→target line so the mid joint lies toward the pole point. Near full extension the reach is
// softened: past `soften · (l1 + l2)` the effective target distance approaches full extension
// exponentially instead of snapping straight, which removes the elbow "pop" of plain two-bone IK.
// Angles are carried as (cos, sin) pairs and turned into quaternions by half-angle formulas: the
// solve takes square roots but no trigonometry (only a nonzero `twist`, a weight below 1 and the
// softening band call libm).
#include "gestura/core/math.hpp"

namespace gestura {

struct TwoBoneInput {
  vec3 start, mid, end;              // model-space joint positions (shoulder, elbow, wrist)
  quat start_rotation, mid_rotation; // model-space rotations of start and mid joints
  quat start_parent_rotation{1.0f, 0.0f, 0.0f, 0.0f};  // model-space rotation of start's parent
  vec3 mid_axis{1.0f, 0.0f, 0.0f};   // hinge axis in the mid joint's frame; a positive turn about it
                                     // folds the limb. Should be perpendicular to both bones.
  vec3 target;                       // where `end` should go (model space)
  vec3 pole;                         // model-space point the mid joint bends toward
  float twist = 0.0f;                // extra turn about start→target after the pole (radians)
  float soften = 1.0f;               // in (0, 1]; 1 = no softening
  float weight = 1.0f;               // 0 keeps the input pose, 1 applies the full solution
};

struct TwoBoneResult {
  quat start_local, mid_local;       // new local rotations of start and mid
  bool reached = false;              // the target lies within [|l1 − l2|, l1 + l2] of start
};

// Contract: all inputs finite, bones of non-zero length, rotations normalised. Degenerate geometry
// (target on the start joint, pole on the start→target line) keeps the corresponding part of the input.
TwoBoneResult solve_two_bone(const TwoBoneInput& in);

}  // namespace gestura
