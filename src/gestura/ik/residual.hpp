#pragma once
// How far an effector frame is from its target, as the solvers report it.
#include "gestura/ik/chain.hpp"

namespace gestura {

// Residuals of `effector`/`effector_rotation` against `target`; converged per the tolerances.
// iterations is left at 0 for the caller to fill.
inline IkResult measure_residual(const vec3& effector, const quat& effector_rotation, const IkTarget& target,
                                 const IkSettings& settings) {
  IkResult r;
  r.position_error = glm::length(target.position - effector);
  r.orientation_error = target.has_orientation ? glm::length(rotation_error(effector_rotation, target.orientation)) : 0.0f;
  r.converged = r.position_error <= settings.position_tolerance && r.orientation_error <= settings.orientation_tolerance;
  return r;
}

}  // namespace gestura
