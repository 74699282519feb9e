#pragma once
// The pose editor's direct manipulation (ALIAS Motion Editor, ch. 4): a limb picked by clicking
// the 3D view (the mouse ray against capsules around the bones) and a hand or foot dragged to a
// point by the IK solvers — the analytic two-bone solve (shoulder–elbow–wrist, hip–knee–ankle)
// inside the joint limits, refined by CCD when a limit stopped it short.
#include <optional>
#include <span>

#include "gestura/skeleton/skeleton.hpp"

namespace gestura::studio {

// The joint whose bone (from the joint to its child) the ray meets first within `radius` metres of
// the bone's axis; -1 when it meets none. `direction` need not be unit length.
// Contract: model holds the model matrices of every joint of `skeleton`.
int pick_bone(const Skeleton& skeleton, std::span<const mat4> model, const vec3& origin, const vec3& direction,
              float radius = 0.035f);

// The limb a joint belongs to, as the chain IK moves: start (shoulder, hip), mid (elbow, knee),
// end (wrist, ankle). Any joint of an arm or hand picks the arm, of a leg or foot the leg.
struct DragLimb {
  int start = -1, mid = -1, end = -1;
  bool arm = true;
  char side = 'l';
};
std::optional<DragLimb> limb_of(const Skeleton& skeleton, int joint);

// Moves the limb of `pose` so its end joint reaches `target` (model space, metres), keeping every
// joint in its limits. Returns the distance left from the end joint to the target.
float drag_limb(const Skeleton& skeleton, Pose& pose, const DragLimb& limb, const vec3& target);

}  // namespace gestura::studio
