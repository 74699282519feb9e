#include "gestura/ik/chain.hpp"

#include <algorithm>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

IkChain make_chain(const Skeleton& skeleton, int root, int tip, const vec3& effector_offset,
                   const quat& effector_rotation) {
  const int n = static_cast<int>(skeleton.size());
  if (root < 0 || root >= n || tip < 0 || tip >= n)
    throw Error("IK chain: joint index out of range (root " + std::to_string(root) + ", tip " +
                std::to_string(tip) + ", skeleton has " + std::to_string(n) + ")");
  IkChain chain;
  for (int j = tip; j != root; j = skeleton.parents[j]) {
    if (j < 0)
      throw Error("IK chain: '" + skeleton.names[tip] + "' does not descend from '" + skeleton.names[root] + "'");
    chain.joints.push_back(j);
  }
  chain.joints.push_back(root);
  std::reverse(chain.joints.begin(), chain.joints.end());
  if (chain.joints.size() > 64) throw Error("IK chain: more than 64 joints");
  chain.effector_offset = effector_offset;
  chain.effector_rotation = glm::normalize(effector_rotation);
  for (std::size_t k = 0; k < chain.joints.size(); ++k) {
    const JointDofs& d = skeleton.dofs[chain.joints[k]];
    const auto order = axes_of(d.order);
    for (int slot = 0; slot < 3; ++slot) {
      if (!d.free(order[slot])) continue;
      chain.dof_link.push_back(static_cast<std::uint8_t>(k));
      chain.dof_axis.push_back(static_cast<std::uint8_t>(order[slot]));
      chain.dof_slot.push_back(static_cast<std::uint8_t>(slot));
    }
  }
  return chain;
}

IkWorkspace::IkWorkspace(const IkChain& chain)
    : angles(chain.dof_count()),
      lower(chain.dof_count()),
      upper(chain.dof_count()),
      link_angles(chain.size()),
      positions(chain.size()),
      rotations(chain.size()),
      axes(chain.dof_count()),
      jacobian(6 * chain.dof_count()),
      step(chain.dof_count()),
      previous(chain.dof_count()),
      active(chain.dof_count()) {}

mat4 parent_model_matrix(const Skeleton& skeleton, const Pose& pose, int joint) {
  mat4 m(1.0f);
  for (int j = skeleton.parents[joint]; j >= 0; j = skeleton.parents[j]) {
    const Transform local{pose.translations[j], pose.rotations[j], pose.scales[j]};
    m = local.matrix() * m;
  }
  return m;
}

void load_angles(const Skeleton& skeleton, const IkChain& chain, const Pose& pose, IkWorkspace& ws) {
  if (ws.angles.size() != chain.dof_count() || ws.positions.size() != chain.size())
    throw Error("IK: workspace was made for another chain (" + std::to_string(ws.angles.size()) + " dofs, chain has " +
                std::to_string(chain.dof_count()) + ")");
  if (pose.size() != skeleton.size()) throw Error("IK: pose has " + std::to_string(pose.size()) + " joints, skeleton " + std::to_string(skeleton.size()));
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const int j = chain.joints[k];
    ws.link_angles[k] = skeleton.dofs[j].axes ? joint_angles(skeleton, j, pose.rotations[j]) : vec3(0.0f);
  }
  for (std::size_t i = 0; i < chain.dof_count(); ++i) {
    const JointDofs& d = skeleton.dofs[chain.joints[chain.dof_link[i]]];
    const int axis = chain.dof_axis[i];
    ws.lower[i] = d.min_angle[axis];
    ws.upper[i] = d.max_angle[axis];
    ws.angles[i] = std::clamp(ws.link_angles[chain.dof_link[i]][axis], ws.lower[i], ws.upper[i]);
  }
}

void store_angles(const Skeleton& skeleton, const IkChain& chain, IkWorkspace& ws, Pose& pose) {
  for (std::size_t i = 0; i < chain.dof_count(); ++i) ws.link_angles[chain.dof_link[i]][chain.dof_axis[i]] = ws.angles[i];
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const int j = chain.joints[k];
    if (skeleton.dofs[j].axes) pose.rotations[j] = joint_rotation(skeleton, j, ws.link_angles[k]);
  }
}

vec3 chain_forward(const Skeleton& skeleton, const IkChain& chain, const Pose& pose, const mat4& base,
                   IkWorkspace& ws, quat& effector_rotation) {
  // Scatter dof angles into per-link Euler angles (locked axes keep what load_angles found: the
  // solvers never move them, and a pose off a locked axis is the caller's to clamp).
  for (std::size_t i = 0; i < chain.dof_count(); ++i) ws.link_angles[chain.dof_link[i]][chain.dof_axis[i]] = ws.angles[i];
  vec3 parent_position(base[3]);
  quat parent_rotation = glm::normalize(glm::quat_cast(mat3(base)));
  std::size_t dof = 0;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const int j = chain.joints[k];
    const vec3 position = parent_position + parent_rotation * pose.translations[j];
    quat rotation = parent_rotation * skeleton.rest_rotations[j];
    const auto order = axes_of(skeleton.dofs[j].order);
    for (int slot = 0; slot < 3; ++slot) {
      const int axis = order[slot];
      vec3 unit(0.0f);
      unit[axis] = 1.0f;
      // The axis of this Euler angle is the joint frame after the outer rotations: rotating that
      // angle turns everything distal rigidly about this model-space axis through the joint.
      if (dof < chain.dof_count() && chain.dof_link[dof] == k && chain.dof_slot[dof] == slot)
        ws.axes[dof++] = rotation * unit;
      const float angle = ws.link_angles[k][axis];
      if (angle != 0.0f) rotation = rotation * glm::angleAxis(angle, unit);
    }
    ws.positions[k] = position;
    ws.rotations[k] = rotation;
    parent_position = position;
    parent_rotation = rotation;
  }
  effector_rotation = parent_rotation * chain.effector_rotation;
  return parent_position + parent_rotation * chain.effector_offset;
}

vec3 rotation_error(const quat& from, const quat& to) {
  quat d = to * glm::inverse(from);
  if (d.w < 0.0f) d = -d;
  const vec3 v(d.x, d.y, d.z);
  const float s = glm::length(v);
  if (s < 1e-12f) return 2.0f * v;
  return v * (2.0f * std::atan2(s, d.w) / s);
}

}  // namespace gestura
