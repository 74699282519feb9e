#pragma once
// The renderer's own CPU linear-blend skinning (with morph targets), used by the CPU-upload path
// to compare against GPU skinning. A plain loop; the body/skinning module is the tuned one.
#include <span>

#include "gestura/body/mesh.hpp"

namespace gestura {

// Contract: out_positions/out_normals have mesh.vertex_count() entries; every joint index in
// mesh.joints < skinning.size(); morph_weights.size() <= mesh.morphs.size() (missing = 0).
// `scratch_*` are per-vertex buffers of the same size (morphed bind positions and normals).
void cpu_skin_for_render(const Mesh& mesh, std::span<const mat4> skinning, std::span<const float> morph_weights,
                         std::span<vec3> scratch_positions, std::span<vec3> scratch_normals,
                         std::span<vec3> out_positions, std::span<vec3> out_normals);

}  // namespace gestura
