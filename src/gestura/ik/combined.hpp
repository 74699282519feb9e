#pragma once
// The combined method the mpeg4 paper's CCD comes from (Wang & Chen 1991): a few CCD sweeps find a
// feasible posture near the goal quickly and robustly (each sweep is globally optimal per joint, so
// it does not get caught where a gradient would), then damped least squares converges quadratically
// from there.
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/dls.hpp"

namespace gestura {

// Same contract as solve_ccd / solve_dls. `ccd_sweeps` CCD sweeps first (at most), then DLS with
// `settings`; iterations in the result count both.
IkResult solve_combined(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                        const IkSettings& settings, IkWorkspace& ws, Pose& pose, int ccd_sweeps = 8);

}  // namespace gestura
