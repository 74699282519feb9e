#pragma once
// Morph targets, applied before skinning (ukrainian-sign-language-3d-model.txt eq. 7):
// V' = V + Σ_i w_i · ΔV_i, with sparse deltas per target (see MorphTarget in mesh.hpp).
// The result goes into a caller-owned scratch buffer that the skinning kernels then read as their
// rest positions/normals; nothing is allocated per frame.
#include <span>

#include "gestura/body/mesh.hpp"

namespace gestura {

// out = rest + Σ weights[i] · morphs[i].position_deltas. Targets with weight 0 cost nothing.
// Contract: weights.size() == morphs.size(), out.size() == rest.size(), out does not overlap rest.
// A delta naming a vertex outside the mesh throws gestura::Error (target and entry named).
void apply_morphs(std::span<const vec3> rest_positions, std::span<const MorphTarget> morphs,
                  std::span<const float> weights, std::span<vec3> out_positions);

// The same for normals, using each target's normal_deltas (targets without them leave normals
// alone); vertices moved by any weighted target are renormalised.
void apply_morph_normals(std::span<const vec3> rest_normals, std::span<const MorphTarget> morphs,
                         std::span<const float> weights, std::span<vec3> out_normals);

}  // namespace gestura
