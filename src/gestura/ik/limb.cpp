#include "gestura/ik/limb.hpp"

#include <algorithm>

#include "gestura/ik/chain.hpp"

namespace gestura {

quat clamp_joint_rotation(const Skeleton& skeleton, int joint, const quat& local_rotation) {
  const JointDofs& d = skeleton.dofs[joint];
  if (d.axes == 0) return local_rotation;
  vec3 a = joint_angles(skeleton, joint, local_rotation);
  for (int axis = 0; axis < 3; ++axis) a[axis] = d.free(axis) ? std::clamp(a[axis], d.min_angle[axis], d.max_angle[axis]) : 0.0f;
  return joint_rotation(skeleton, joint, a);
}

LimbIkResult solve_limb(const Skeleton& skeleton, Pose& pose, int start, int mid, int end, const vec3& mid_axis,
                        const vec3& target, const vec3& pole, float soften) {
  const mat4 parent = parent_model_matrix(skeleton, pose, start);
  const quat parent_rotation = glm::normalize(glm::quat_cast(mat3(parent)));
  auto place = [&](const quat& start_local, const quat& mid_local, vec3& mid_pos, vec3& end_pos, quat& start_rot, quat& mid_rot) {
    const vec3 start_pos = vec3(parent[3]) + parent_rotation * pose.translations[start];
    start_rot = parent_rotation * start_local;
    mid_pos = start_pos + start_rot * pose.translations[mid];
    mid_rot = start_rot * mid_local;
    end_pos = mid_pos + mid_rot * pose.translations[end];
    return start_pos;
  };
  TwoBoneInput in;
  in.start = place(pose.rotations[start], pose.rotations[mid], in.mid, in.end, in.start_rotation, in.mid_rotation);
  in.start_parent_rotation = parent_rotation;
  in.mid_axis = mid_axis;
  in.target = target;
  in.pole = pole;
  in.soften = soften;
  const TwoBoneResult solved = solve_two_bone(in);
  LimbIkResult out;
  out.reached = solved.reached;
  pose.rotations[start] = clamp_joint_rotation(skeleton, start, solved.start_local);
  pose.rotations[mid] = clamp_joint_rotation(skeleton, mid, solved.mid_local);
  out.clamped = glm::abs(glm::dot(pose.rotations[start], solved.start_local)) < 1.0f - 1e-6f ||
                glm::abs(glm::dot(pose.rotations[mid], solved.mid_local)) < 1.0f - 1e-6f;
  vec3 mid_pos, end_pos;
  quat start_rot, mid_rot;
  place(pose.rotations[start], pose.rotations[mid], mid_pos, end_pos, start_rot, mid_rot);
  out.position_error = glm::length(end_pos - target);
  return out;
}

}  // namespace gestura
