#pragma once
// Aim / look-at: turn a joint so a local forward axis points at a target, keeping a local up axis as
// close as possible to a model-space up direction; and aim chains, where several joints (neck, head,
// eye) each take a share of the turn so the last one ends up looking at the target.
#include <span>

#include "gestura/core/math.hpp"

namespace gestura {

struct AimInput {
  vec3 position;                       // joint position, model space
  quat rotation;                       // joint rotation, model space
  quat parent_rotation{1.0f, 0.0f, 0.0f, 0.0f};  // parent's model rotation
  vec3 forward{0.0f, 0.0f, 1.0f};      // joint-local axis to point at the target (unit)
  vec3 up{0.0f, 1.0f, 0.0f};           // joint-local axis to keep up (unit, not parallel to forward)
  vec3 target;                         // model space
  vec3 world_up{0.0f, 1.0f, 0.0f};     // model-space up direction
  float weight = 1.0f;                 // 0 = unchanged, 1 = fully aimed
};

// The joint's new local rotation. When the target is on the joint the rotation is unchanged; when
// the target lies along world_up the joint's current up direction is kept as the reference instead.
quat aim_local_rotation(const AimInput& in);

// Aim chain over plain arrays, links root first, each the parent of the next (e.g. neck, skullbase,
// l_eyeball). positions/rotations are model space and are updated in place as links turn. Link k
// turns the chain's end toward the target by weights[k] of the remaining angle (1 for the last link
// makes the end look exactly at the target); the last link also rolls its `up` toward world_up.
// Writes the links' new local rotations to `local_out`. Contract: all spans the same size ≥ 1.
void aim_chain(std::span<vec3> positions, std::span<quat> rotations, const quat& root_parent_rotation,
               std::span<const float> weights, const vec3& forward, const vec3& up, const vec3& target,
               const vec3& world_up, std::span<quat> local_out);

}  // namespace gestura
