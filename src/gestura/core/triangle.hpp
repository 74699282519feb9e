#pragma once
// Point–triangle queries shared by the collision world and the surface measures.
#include "gestura/core/math.hpp"

namespace gestura {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection §5.1.5).
// Contract: any triangle, degenerate ones included (the answer is then a point on an edge or vertex).
vec3 closest_point_on_triangle(const vec3& p, const vec3& a, const vec3& b, const vec3& c);

}  // namespace gestura
