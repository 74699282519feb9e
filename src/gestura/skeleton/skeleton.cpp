#include "gestura/skeleton/skeleton.hpp"

#include <algorithm>
#include <unordered_set>

#include "gestura/core/error.hpp"

namespace gestura {

mat4 DenavitHartenberg::matrix(float joint_angle) const {
  const float th = theta + joint_angle;
  const float ct = std::cos(th), st = std::sin(th), ca = std::cos(alpha), sa = std::sin(alpha);
  // Column-major: columns are images of the x, y, z axes and the origin.
  return mat4(vec4(ct, st, 0, 0), vec4(-st * ca, ct * ca, sa, 0), vec4(st * sa, -ct * sa, ca, 0),
              vec4(a * ct, a * st, d, 1));
}

int Skeleton::find(std::string_view name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

int Skeleton::add_joint(std::string name, int parent, const vec3& rest_translation,
                        const quat& rest_rotation) {
  if (parent >= static_cast<int>(names.size()))
    throw Error("joint '" + name + "': parent " + std::to_string(parent) + " does not exist yet");
  names.push_back(std::move(name));
  parents.push_back(static_cast<std::int16_t>(parent));
  rest_translations.push_back(rest_translation);
  rest_rotations.push_back(rest_rotation);
  rest_scales.push_back(vec3(1.0f));
  dofs.push_back(JointDofs{});
  if (!dh.empty()) dh.emplace_back();
  return static_cast<int>(names.size() - 1);
}

void Skeleton::validate() const {
  const std::size_t n = names.size();
  if (parents.size() != n || rest_translations.size() != n || rest_rotations.size() != n ||
      rest_scales.size() != n || dofs.size() != n || (!dh.empty() && dh.size() != n))
    throw Error("skeleton arrays disagree in size");
  if (n > 32767) throw Error("skeleton has too many joints (" + std::to_string(n) + ")");
  std::unordered_set<std::string> seen;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string who = "joint " + std::to_string(i) + " '" + names[i] + "'";
    if (names[i].empty()) throw Error("joint " + std::to_string(i) + " has no name");
    if (!seen.insert(names[i]).second) throw Error(who + ": duplicate name");
    if (parents[i] >= static_cast<int>(i) || parents[i] < -1)
      throw Error(who + ": parent " + std::to_string(parents[i]) + " does not come before it");
    if (!is_finite(rest_translations[i]) || !is_finite(rest_rotations[i]) || !is_finite(rest_scales[i]))
      throw Error(who + ": non-finite rest transform");
    for (int a = 0; a < 3; ++a)
      if (dofs[i].free(a) && !(dofs[i].min_angle[a] <= dofs[i].max_angle[a]))
        throw Error(who + ": limit min > max on axis " + "xyz"[a]);
  }
}

int Skeleton::total_dofs() const {
  int total = 0;
  for (const JointDofs& d : dofs) total += d.count();
  return total;
}

void Pose::resize(std::size_t n) {
  translations.resize(n, vec3(0.0f));
  rotations.resize(n, quat(1.0f, 0.0f, 0.0f, 0.0f));
  scales.resize(n, vec3(1.0f));
}

Pose rest_pose(const Skeleton& skeleton) {
  Pose pose;
  pose.translations = skeleton.rest_translations;
  pose.rotations = skeleton.rest_rotations;
  pose.scales = skeleton.rest_scales;
  return pose;
}

void local_to_model(std::span<const std::int16_t> parents, std::span<const vec3> translations,
                    std::span<const quat> rotations, std::span<const vec3> scales,
                    std::span<mat4> out, const mat4& root) {
  const std::size_t n = parents.size();
  for (std::size_t i = 0; i < n; ++i) {
    // Build T·R·S directly (cheaper than composing three matrices).
    const quat& q = rotations[i];
    const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    const vec3& s = scales[i];
    mat4 local(vec4((1 - 2 * (yy + zz)) * s.x, 2 * (xy + wz) * s.x, 2 * (xz - wy) * s.x, 0),
               vec4(2 * (xy - wz) * s.y, (1 - 2 * (xx + zz)) * s.y, 2 * (yz + wx) * s.y, 0),
               vec4(2 * (xz + wy) * s.z, 2 * (yz - wx) * s.z, (1 - 2 * (xx + yy)) * s.z, 0),
               vec4(translations[i], 1));
    const int p = parents[i];
    out[i] = (p < 0 ? root : out[static_cast<std::size_t>(p)]) * local;
  }
}

void local_to_model(const Skeleton& skeleton, const Pose& pose, std::span<mat4> out) {
  local_to_model(skeleton.parents, pose.translations, pose.rotations, pose.scales, out);
}

void model_positions(std::span<const mat4> model, std::span<vec3> out) {
  for (std::size_t i = 0; i < model.size(); ++i) out[i] = vec3(model[i][3]);
}

mat4 segment_transform(const vec3& joint_centre, const vec3& angles, RotationOrder order) {
  const mat4 B = glm::translate(mat4(1.0f), joint_centre);
  const mat4 B_inv = glm::translate(mat4(1.0f), -joint_centre);
  return B * glm::mat4_cast(euler_to_quat(angles, order)) * B_inv;
}

vec3 joint_angles(const Skeleton& skeleton, int joint, const quat& local_rotation) {
  const quat rel = glm::inverse(skeleton.rest_rotations[joint]) * local_rotation;
  // Of the two Euler solutions (and 2π shifts) take the one nearest the middle of the limits, so a
  // pose inside the limits is always recognised as such.
  const JointDofs& d = skeleton.dofs[joint];
  const vec3 middle = 0.5f * (d.min_angle + d.max_angle);
  const vec3 nearest = quat_to_euler_near(rel, d.order, middle);
  // Limits wider than 180° on an outer or inner axis (shoulder flexion spans 249°) can hold the other
  // Euler solution (a + π, π − b, c + π) of the same rotation while the nearest one lies outside:
  // prefer whichever solution is inside the limits.
  auto inside = [&](const vec3& a) {
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = d.free(axis) ? d.min_angle[axis] : 0.0f, hi = d.free(axis) ? d.max_angle[axis] : 0.0f;
      if (a[axis] < lo - 1e-4f || a[axis] > hi + 1e-4f) return false;
    }
    return true;
  };
  if (inside(nearest)) return nearest;
  const auto ax = axes_of(d.order);
  vec3 twin = nearest;
  twin[ax[0]] += kPi;
  twin[ax[1]] = kPi - nearest[ax[1]];
  twin[ax[2]] += kPi;
  for (int axis = 0; axis < 3; ++axis)
    twin[axis] += 2.0f * kPi * std::round((middle[axis] - twin[axis]) / (2.0f * kPi));
  return inside(twin) ? twin : nearest;
}

quat joint_rotation(const Skeleton& skeleton, int joint, const vec3& angles) {
  return skeleton.rest_rotations[joint] * euler_to_quat(angles, skeleton.dofs[joint].order);
}

static vec3 clamp_angles(const JointDofs& d, vec3 a) {
  for (int axis = 0; axis < 3; ++axis)
    a[axis] = d.free(axis) ? std::clamp(a[axis], d.min_angle[axis], d.max_angle[axis]) : 0.0f;
  return a;
}

bool clamp_joint_to_limits(const Skeleton& skeleton, int joint, quat& local_rotation) {
  const JointDofs& d = skeleton.dofs[static_cast<std::size_t>(joint)];
  if (d.axes == 0) return false;
  const vec3 a = joint_angles(skeleton, joint, local_rotation);
  const vec3 c = clamp_angles(d, a);
  if (c == a) return false;
  // Joints whose range spans more than 180° (the shoulder) have rotations with two Euler readings;
  // the clamped rotation can read back through the other one. Clamp again until it reads inside.
  quat q = joint_rotation(skeleton, joint, c);
  for (int pass = 0; pass < 3 && !within_limits(skeleton, joint, q, 1e-4f); ++pass)
    q = joint_rotation(skeleton, joint, clamp_angles(d, joint_angles(skeleton, joint, q)));
  local_rotation = q;
  return true;
}

int clamp_to_limits(const Skeleton& skeleton, Pose& pose) {
  int changed = 0;
  for (std::size_t j = 0; j < skeleton.size(); ++j)
    if (clamp_joint_to_limits(skeleton, static_cast<int>(j), pose.rotations[j])) ++changed;
  return changed;
}

bool within_limits(const Skeleton& skeleton, int joint, const quat& local_rotation, float tolerance) {
  const JointDofs& d = skeleton.dofs[joint];
  if (d.axes == 0) return true;
  const vec3 a = joint_angles(skeleton, joint, local_rotation);
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = d.free(axis) ? d.min_angle[axis] : 0.0f;
    const float hi = d.free(axis) ? d.max_angle[axis] : 0.0f;
    if (a[axis] < lo - tolerance || a[axis] > hi + tolerance) return false;
  }
  return true;
}

}  // namespace gestura
