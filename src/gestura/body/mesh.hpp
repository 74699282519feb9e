#pragma once
// A skinned, morphable triangle mesh: what the avatar builder and importers produce, what skinning
// deforms and what the renderer and exporters consume. Plain arrays; all per-vertex arrays have the
// same length. Positions in metres in the skeleton's model space at bind (rest) pose.
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

// Up to four joint influences per vertex; weights sum to 1 (unused slots: joint 0, weight 0).
using JointIndices = glm::u16vec4;

// Coarse surface regions: let renderers colour skin, clothing, hair, eyes, lips, teeth separately.
// Cloth is the top (shirt), Trousers what is worn below its hem. Mouth is the lining of the oral
// cavity (dark: it lies in the shadow of the lips); Nail the nail plates of fingers and thumbs.
enum class MaterialId : std::uint8_t { Skin = 0, Cloth = 1, Hair = 2, EyeWhite = 3, Iris = 4, Lips = 5, Teeth = 6, Tongue = 7, Brow = 8, Pupil = 9, Mouth = 10, Nail = 11, Trousers = 12 };
inline constexpr int kMaterialCount = 13;

// A morph target (ukrainian-sign-language-3d-model.txt eq. 7: V' = V + Σ w·ΔV): sparse offsets.
struct MorphTarget {
  std::string name;
  std::vector<std::uint32_t> vertices;  // indices into the mesh
  std::vector<vec3> position_deltas;    // one per listed vertex
  std::vector<vec3> normal_deltas;      // same length, or empty
};

struct Mesh {
  std::vector<vec3> positions;
  std::vector<vec3> normals;
  std::vector<std::uint8_t> materials;  // MaterialId per vertex
  std::vector<JointIndices> joints;     // skin influences
  std::vector<vec4> weights;
  std::vector<std::uint32_t> indices;   // triangles, counter-clockwise seen from outside
  std::vector<MorphTarget> morphs;
  // The colour the mesh was made to be shown in, per MaterialId (sRGB, 0..1): kMaterialCount
  // entries, or none (a renderer's or exporter's own defaults apply).
  std::vector<vec3> material_colors;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
  int find_morph(const std::string& name) const;
};

inline int Mesh::find_morph(const std::string& name) const {
  for (std::size_t i = 0; i < morphs.size(); ++i)
    if (morphs[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace gestura
