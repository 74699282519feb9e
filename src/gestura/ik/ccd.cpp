#include "gestura/ik/ccd.hpp"

#include <algorithm>

#include "gestura/ik/residual.hpp"

namespace gestura {

IkResult solve_ccd(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                   const IkSettings& settings, IkWorkspace& ws, Pose& pose) {
  load_angles(skeleton, chain, pose, ws);
  const float wo = target.has_orientation ? settings.orientation_scale * settings.orientation_scale : 0.0f;
  const mat3 desired = glm::mat3_cast(target.orientation);
  quat effector_rotation;
  vec3 effector = chain_forward(skeleton, chain, pose, base, ws, effector_rotation);
  IkResult result = measure_residual(effector, effector_rotation, target, settings);
  while (!result.converged && result.iterations < settings.max_iterations) {
    for (std::size_t i = chain.dof_count(); i-- > 0;) {
      const vec3 a = ws.axes[i];
      const vec3 p = ws.positions[chain.dof_link[i]];
      const vec3 pc = effector - p, pd = target.position - p;
      float k1 = glm::dot(pd, a) * glm::dot(pc, a);
      float k2 = glm::dot(pd, pc);
      vec3 cross = glm::cross(pc, pd);
      if (wo > 0.0f) {
        const mat3 current = glm::mat3_cast(effector_rotation);
        for (int j = 0; j < 3; ++j) {
          k1 += wo * glm::dot(desired[j], a) * glm::dot(current[j], a);
          k2 += wo * glm::dot(desired[j], current[j]);
          cross += wo * glm::cross(current[j], desired[j]);
        }
      }
      const float k3 = glm::dot(a, cross);
      const float theta = std::clamp(std::atan2(k3, k2 - k1), -settings.max_angle_step, settings.max_angle_step);
      const float updated = std::clamp(ws.angles[i] + theta, ws.lower[i], ws.upper[i]);
      if (updated == ws.angles[i]) continue;
      // Turning this angle turns everything distal rigidly about (p, a); the joints and axes closer
      // to the root, which the rest of the sweep visits, do not move. So only the effector frame is
      // updated here, and the chain is recomputed once per sweep.
      const quat turn = glm::angleAxis(updated - ws.angles[i], a);
      ws.angles[i] = updated;
      effector = p + turn * pc;
      effector_rotation = glm::normalize(turn * effector_rotation);
    }
    effector = chain_forward(skeleton, chain, pose, base, ws, effector_rotation);
    const int done = result.iterations + 1;
    const float before = result.position_error + settings.orientation_scale * result.orientation_error;
    result = measure_residual(effector, effector_rotation, target, settings);
    result.iterations = done;
    // A sweep that gains nothing will not gain later: the target is out of reach (or pinned by limits).
    if (before - (result.position_error + settings.orientation_scale * result.orientation_error) < 1e-9f) break;
  }
  store_angles(skeleton, chain, ws, pose);
  return result;
}

}  // namespace gestura
