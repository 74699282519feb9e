#pragma once
// Cyclic coordinate descent with position and orientation error (mpeg4-humanoid-animation.txt §5,
// after Wang & Chen 1991).
//
// Each sweep visits the degrees of freedom from the effector back to the chain root. For one revolute
// axis a through joint position p, turning by θ moves the effector rigidly, and the combined error
//     E = |Pd − Pc|² + s² · Σ_j (1 − ud_j · uc_j)         (Pc, Pd relative to p; u the frame axes)
// becomes E(θ) = const − [k1 + (k2 − k1) cos θ + k3 sin θ] with
//     k1 = (Pd·a)(Pc·a) + s² Σ (ud_j·a)(uc_j·a)
//     k2 =  Pd·Pc       + s² Σ  ud_j·uc_j
//     k3 = a·(Pc × Pd   + s² Σ  uc_j × ud_j),
// minimised in closed form by θ = atan2(k3, k2 − k1). The orientation term is the linear form
// Σ(1 − ud·uc) of the paper's Σ(ud·uc − 1)²: both vanish at the same frames and agree to leading order
// near the goal, and the linear form keeps the one-joint problem analytic. After every update the
// angle is clamped into the joint's limits, and the effector frame is recomputed before the next axis.
#include "gestura/ik/chain.hpp"

namespace gestura {

// Contract: `ws` was built for `chain`; `chain` was made from `skeleton`; `base` is the rigid model
// transform of the chain root's parent (parent_model_matrix), chain joints have unit scale.
// Reads the chain's current rotations from `pose` as the starting guess and writes the solution back
// (only the chain joints' rotations change). Never allocates.
IkResult solve_ccd(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                   const IkSettings& settings, IkWorkspace& ws, Pose& pose);

}  // namespace gestura
