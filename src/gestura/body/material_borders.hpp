#pragma once
// Clean borders between material regions of a per-vertex-material mesh.
//
// Materials live on vertices, so on a marching-cubes mesh a border between two regions follows
// the lattice and reads as a staircase. Here a border is drawn by a smooth field instead (negative
// on one material's side, positive on the other's): the vertices of either material take the
// material of the field's sign, and the mesh is cut along two level lines of the field, one a
// little inside each region. The colour then changes within a narrow band whose edges follow the
// field, wherever the lattice's vertices happen to lie; the mesh stays closed and manifold.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "gestura/body/mesh.hpp"

namespace gestura {

struct MaterialBorder {
  MaterialId below = MaterialId::Skin;  // the material where field < 0 …
  MaterialId above = MaterialId::Skin;  // … and where field > 0
  std::function<float(const vec3&)> field;  // smooth; any scale (it is measured along the surface)
};

// For each border in turn: vertices labelled `below` or `above` near a change between the two are
// relabelled by the field's sign, and triangles made only of such vertices are cut where the field,
// rescaled to a distance along the surface, is ±half_width (metres). `materials` holds one MaterialId
// per vertex and grows with the new vertices.
void sharpen_material_borders(std::span<const MaterialBorder> borders, float half_width, std::vector<vec3>& positions,
                              std::vector<std::uint32_t>& indices, std::vector<std::uint8_t>& materials);

}  // namespace gestura
