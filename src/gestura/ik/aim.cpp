#include "gestura/ik/aim.hpp"

#include <algorithm>

namespace gestura {

// The rotation taking the orthonormal frame (f, u, f × u) onto (F, U, F × U).
static quat frame_to_frame(const vec3& f, const vec3& u, const vec3& F, const vec3& U) {
  const mat3 from(f, u, glm::cross(f, u));
  const mat3 to(F, U, glm::cross(F, U));
  return glm::normalize(glm::quat_cast(to * glm::transpose(from)));
}

quat aim_local_rotation(const AimInput& in) {
  const quat local = glm::inverse(in.parent_rotation) * in.rotation;
  const vec3 to_target = in.target - in.position;
  const float distance = glm::length(to_target);
  if (distance < 1e-6f) return local;
  const vec3 F = to_target / distance;
  // Up reference: world_up unless it is (nearly) along the aim line, then the joint's own current up.
  vec3 ref = in.world_up - F * glm::dot(in.world_up, F);
  if (glm::length(ref) < 1e-4f) {
    const vec3 current_up = in.rotation * in.up;
    ref = current_up - F * glm::dot(current_up, F);
    if (glm::length(ref) < 1e-4f) ref = glm::cross(F, std::abs(F.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0));
  }
  const vec3 U = glm::normalize(ref);
  const vec3 f = glm::normalize(in.forward);
  const vec3 u = glm::normalize(in.up - f * glm::dot(in.up, f));
  const quat aimed = frame_to_frame(f, u, F, U);  // model rotation of the aimed joint
  const quat model = in.weight >= 1.0f ? aimed : glm::slerp(in.rotation, aimed, std::max(in.weight, 0.0f));
  return glm::normalize(glm::inverse(in.parent_rotation) * model);
}

void aim_chain(std::span<vec3> positions, std::span<quat> rotations, const quat& root_parent_rotation,
               std::span<const float> weights, const vec3& forward, const vec3& up, const vec3& target,
               const vec3& world_up, std::span<quat> local_out) {
  const std::size_t n = positions.size(), last = n - 1;
  for (std::size_t k = 0; k < last; ++k) {
    const vec3 end_forward = rotations[last] * forward;
    const vec3 to_target = target - positions[last];
    if (glm::length(to_target) < 1e-6f) break;
    const quat full = glm::rotation(glm::normalize(end_forward), glm::normalize(to_target));
    const quat turn = glm::slerp(quat(1.0f, 0.0f, 0.0f, 0.0f), full, std::clamp(weights[k], 0.0f, 1.0f));
    // Turn link k and everything after it rigidly about link k's joint.
    for (std::size_t i = k; i < n; ++i) {
      rotations[i] = glm::normalize(turn * rotations[i]);
      positions[i] = positions[k] + turn * (positions[i] - positions[k]);
    }
  }
  AimInput end{positions[last], rotations[last], last > 0 ? rotations[last - 1] : root_parent_rotation,
               forward, up, target, world_up, weights[last]};
  const quat end_local = aim_local_rotation(end);
  rotations[last] = glm::normalize(end.parent_rotation * end_local);
  for (std::size_t k = 0; k < n; ++k)
    local_out[k] = glm::normalize(glm::inverse(k > 0 ? rotations[k - 1] : root_parent_rotation) * rotations[k]);
}

}  // namespace gestura
