#pragma once
// Re-expressing a skeleton and its clip in another coordinate frame (e.g. a Z-up file in our +Y-up
// space). Every local transform T·R becomes B·T·R·B⁻¹, so the whole chain becomes B·(chain)·B⁻¹ and
// each model-space joint position p becomes B·p: the motion is the same, only the axes are renamed.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Z-up, facing −Y (Blender, MakeHuman BVH export) → +Y up, facing +Z: (x, y, z) ↦ (x, z, −y),
// a −90° turn about X. The character's left stays +X.
inline quat z_up_to_y_up() { return glm::angleAxis(-0.5f * kPi, vec3(1.0f, 0.0f, 0.0f)); }

// Applies `basis` (a unit rotation) to rest translations and rotations, translation keys and
// rotation keys. Scales are kept, which is exact for uniform scale only; joint limits and Euler
// orders are kept too (they describe the joint, not the frame it is written in).
// Contract: clip tracks are indexed like `skeleton`.
void change_basis(Skeleton& skeleton, Clip& clip, const quat& basis);

}  // namespace gestura
