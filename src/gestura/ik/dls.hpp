#pragma once
// Damped-least-squares Jacobian IK (the pseudo-inverse method of alias-movement-through-environments.txt
// §5.3/§6.2, damped so that it stays steady near singular, fully stretched poses).
//
// Per iteration, with e the error (position, and orientation scaled by IkSettings::orientation_scale)
// and J its Jacobian over the free joint angles:
//     Δq = Jᵀ(JJᵀ + λ²I)⁻¹ e  +  (I − J⁺J) · g (q_preferred − q)
// The second term moves inside the null space of the task — the arm's redundant "elbow swivel" of a
// 7-DoF arm — toward a comfortable posture without disturbing the hand. Joint limits: a step that
// would push an angle past its limit pins that angle at the limit and the step is recomputed without
// it (a clamping loop), so the remaining joints make up the difference.
#include "gestura/ik/chain.hpp"

namespace gestura {

// Same contract as solve_ccd. Additionally `settings.preferred_angles`, when given, has one angle per
// dof of the chain (in IkChain dof order). Never allocates.
IkResult solve_dls(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                   const IkSettings& settings, IkWorkspace& ws, Pose& pose);

}  // namespace gestura
