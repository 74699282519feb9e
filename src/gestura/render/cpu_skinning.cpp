#include "gestura/render/cpu_skinning.hpp"

#include <algorithm>

namespace gestura {

void cpu_skin_for_render(const Mesh& mesh, std::span<const mat4> skinning, std::span<const float> morph_weights,
                         std::span<vec3> scratch_positions, std::span<vec3> scratch_normals,
                         std::span<vec3> out_positions, std::span<vec3> out_normals) {
  const std::size_t n = mesh.vertex_count();
  std::copy_n(mesh.positions.begin(), n, scratch_positions.begin());
  std::copy_n(mesh.normals.begin(), n, scratch_normals.begin());
  for (std::size_t m = 0; m < morph_weights.size() && m < mesh.morphs.size(); ++m) {
    const float w = morph_weights[m];
    if (w == 0.0f) continue;
    const MorphTarget& target = mesh.morphs[m];
    for (std::size_t k = 0; k < target.vertices.size(); ++k) {
      scratch_positions[target.vertices[k]] += w * target.position_deltas[k];
      if (!target.normal_deltas.empty()) scratch_normals[target.vertices[k]] += w * target.normal_deltas[k];
    }
  }
  for (std::size_t v = 0; v < n; ++v) {
    const JointIndices j = mesh.joints[v];
    const vec4 w = mesh.weights[v];
    const mat4 m = skinning[j.x] * w.x + skinning[j.y] * w.y + skinning[j.z] * w.z + skinning[j.w] * w.w;
    out_positions[v] = vec3(m * vec4(scratch_positions[v], 1.0f));
    out_normals[v] = mat3(m) * scratch_normals[v];
  }
}

}  // namespace gestura
