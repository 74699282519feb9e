#include "gestura/ik/combined.hpp"

namespace gestura {

IkResult solve_combined(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                        const IkSettings& settings, IkWorkspace& ws, Pose& pose, int ccd_sweeps) {
  IkSettings first = settings;
  first.max_iterations = ccd_sweeps;
  const IkResult rough = solve_ccd(skeleton, chain, base, target, first, ws, pose);
  if (rough.converged) return rough;
  IkResult fine = solve_dls(skeleton, chain, base, target, settings, ws, pose);
  fine.iterations += rough.iterations;
  return fine;
}

}  // namespace gestura
