#pragma once
// Cuts a triangle mesh along a level line of a per-vertex scalar, so that a border drawn by that
// scalar (a material edge) runs along triangle edges instead of zig-zagging through triangles.
//
// The scalar is taken as linear on each triangle. An edge is cut where the scalar crosses `level`,
// if both its ends are `eligible`; the new vertex is shared by the two triangles of the edge, so a
// closed manifold stays closed and manifold. A triangle with one cut edge becomes two triangles,
// with two cut edges three (a triangle with three cut edges cannot occur). Orientation is kept.
#include <cstdint>
#include <functional>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

struct LevelSplitMesh {
  std::vector<vec3>& positions;
  std::vector<std::uint32_t>& indices;
  std::vector<float>& values;           // one per vertex; new vertices get exactly `level`
  std::vector<std::uint8_t>& eligible;  // one per vertex; new vertices are eligible
};

// Where along edge a → b the cut goes, given the linear estimate t (0 at a, 1 at b); lets a caller
// place the vertex on the true level of the function the values sample. Results are clamped to
// 0.05 .. 0.95 so no sliver is made.
using LevelCrossing = std::function<float(std::uint32_t a, std::uint32_t b, float t)>;

// Before cutting, eligible values within `snap` of `level` are pushed to level ± snap (keeping
// their side), so no cut passes closer than that to a vertex and no sliver triangle is made.
// Returns the number of vertices added.
std::size_t split_at_level(LevelSplitMesh mesh, float level, float snap, const LevelCrossing& crossing = {});

}  // namespace gestura
