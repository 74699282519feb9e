#pragma once
// Two-bone IK applied to a skeleton pose and kept inside the joints' anatomical limits.
#include "gestura/ik/two_bone.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// The rotation nearest (per Euler angle) to `local_rotation` that lies within `joint`'s limits.
quat clamp_joint_rotation(const Skeleton& skeleton, int joint, const quat& local_rotation);

struct LimbIkResult {
  bool reached = false;          // geometrically within reach (see TwoBoneResult)
  bool clamped = false;          // a limit changed the analytic solution
  float position_error = 0.0f;   // metres from `end` to the target after clamping
};

// Solves start–mid–end (e.g. l_shoulder, l_elbow, l_wrist) toward `target`, bending toward `pole`,
// writes the two local rotations into `pose` and clamps them to the limits. mid_axis as in
// TwoBoneInput. Contract: mid is a child of start, end a child of mid. Never allocates.
LimbIkResult solve_limb(const Skeleton& skeleton, Pose& pose, int start, int mid, int end, const vec3& mid_axis,
                        const vec3& target, const vec3& pole, float soften = 1.0f);

}  // namespace gestura
