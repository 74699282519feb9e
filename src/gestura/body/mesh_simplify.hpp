#pragma once
// Removes the needle and sliver triangles marching cubes leaves where the surface passes close to
// lattice nodes, by collapsing short edges. Each collapse keeps the surface a closed 2-manifold
// (the link condition) and never folds a triangle over (normals may turn by at most ~60°).
#include <cstdint>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

// Collapses every edge shorter than `ratio` × the longest edge of a triangle it belongs to, shortest
// relative length first, then drops unused vertices. Returns the number of collapses. Indices are
// rewritten; positions are compacted (the order of the kept vertices is preserved).
int collapse_short_edges(std::vector<vec3>& positions, std::vector<std::uint32_t>& indices, float ratio = 0.3f);

}  // namespace gestura
