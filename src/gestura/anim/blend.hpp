#pragma once
// Blending poses: weighted layers with per-joint masks and priorities, additive layers, crossfades.
//
// Priorities implement the reserve/lock lists of alias-movement-through-environments.txt §5.4: a
// higher-priority layer claims the joints its mask covers (one motion's arms over another's legs);
// lower layers only fill the weight left over on each joint.
//
// The work is one pass over the joints, 8 (AVX2) or 4 (SSE2) at a time, every layer accumulated in
// registers (anim/blend_kernel.hpp); layers, masks and priorities only decide the weights beforehand.
#include <span>

#include "gestura/core/simd_path.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct BlendLayer {
  const Pose* pose = nullptr;
  float weight = 1.0f;
  std::span<const float> joint_weights;  // per joint in [0, 1]; empty = 1 everywhere
  int priority = 0;                      // higher claims first (ignored for additive layers)
  bool additive = false;                 // `pose` is a delta (make_additive), applied on top of the blend
};

// Contract: every layer pose and `rest` have the same size, masks are empty or that size (otherwise
// gestura::Error); `out` is resized and may be one of the layers' poses. On each joint the layers are
// taken by priority, highest first; within one priority level weights are normalised among
// themselves if they exceed what is left. Weight left unclaimed on a joint is filled by the layers'
// normalised blend or, if no layer touches the joint, by `rest`. Rotations are blended as a weighted
// quaternion sum on one hemisphere. Additive layers then apply in order as apply_additive does, and
// each rotation is normalised once at the end.
// Portable and AVX2 paths agree within 1e-5 (core/simd_path.hpp).
void blend_layers(std::span<const BlendLayer> layers, const Pose& rest, Pose& out, SimdPath path = SimdPath::Auto);

// Additive animation: the difference of `pose` from `reference` (delta = reference⁻¹ · pose for
// rotation, pose − reference for translation, pose / reference for scale).
void make_additive(const Pose& reference, const Pose& pose, Pose& delta);

// Applies `delta` on top of `inout` with `weight` and an optional per-joint mask (w = weight · mask):
// rotation · nlerp(identity, delta, w), translation + w · delta, scale · mix(1, delta, w).
void apply_additive(const Pose& delta, float weight, std::span<const float> joint_weights, Pose& inout,
                    SimdPath path = SimdPath::Auto);

// out = a·(1 − t) + b·t per joint (t in [0, 1]); rotations by nlerp on the short arc.
void crossfade(const Pose& a, const Pose& b, float t, Pose& out, SimdPath path = SimdPath::Auto);

// Smooth crossfade weight for time `t` into a fade of `length` seconds (ease in-out, C1).
float crossfade_weight(float t, float length);

}  // namespace gestura
