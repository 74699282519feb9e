#pragma once
// The four ALIAS primitives (box, plane, cylinder, sphere) as triangles and as exact signed distance
// functions, both in the shape's own frame (centred on its origin; the plane in y = 0 facing +Y, the
// cylinder's axis along +Y).
#include <cstdint>
#include <vector>

#include "gestura/world/scene.hpp"

namespace gestura {

// Triangles with per-vertex normals; hard edges (box corners, cylinder rims) get split vertices so
// flat faces shade flat. Counter-clockwise seen from outside.
struct TriangleMesh {
  std::vector<vec3> positions;
  std::vector<vec3> normals;
  std::vector<std::uint32_t> indices;

  std::size_t triangle_count() const { return indices.size() / 3; }
  void append(const TriangleMesh& other, const mat4& transform);  // normals by the inverse transpose
};

inline constexpr int kDefaultSegments = 32;

// Contract: a validated primitive (kind Box, Plane, Cylinder or Sphere; sizes positive).
TriangleMesh tessellate(const Shape& shape);

// Signed distance from `p` (shape frame) to the primitive's surface, negative inside. A plane is a
// zero-thickness rectangle (never negative). Exact for every primitive, ignoring tessellation.
float shape_signed_distance(const Shape& shape, const vec3& p);

}  // namespace gestura
