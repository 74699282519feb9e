#pragma once
// The exact shortest path on a polygonal floor plan by the visibility graph of the grown obstacles
// (Lozano-Pérez & Wesley 1979; Lozano-Pérez 1983, cited in alias-movement-through-environments.txt
// §7.2): grow every convex obstacle by the walker's disc (a Minkowski sum with a regular polygon
// circumscribing the disc, so the grown obstacle contains every point nearer than the radius),
// connect start, goal and the grown obstacles' corners by every straight segment that enters no grown
// obstacle, and search that graph (Dijkstra). The reference the navigation-mesh planner is measured
// against; plane coordinates are (x, z).
#include <span>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

using Polygon2 = std::vector<vec2>;

// Convex hull, counter-clockwise (Andrew's monotone chain); collinear points dropped.
Polygon2 convex_hull(std::vector<vec2> points);

// The convex polygon grown by a disc of `radius`, the disc approximated from outside by a regular
// polygon of `sides` sides.
Polygon2 grow_convex(std::span<const vec2> polygon, float radius, int sides = 64);

// Whether the segment a–b passes through the interior of the convex, counter-clockwise polygon
// (running along its edges or touching a corner does not count).
bool segment_enters(const vec2& a, const vec2& b, std::span<const vec2> polygon, float tolerance = 1e-6f);

struct PlanPath {
  bool found = false;
  std::vector<vec2> points;
  float length = 0.0f;
};

// Shortest path among already grown convex obstacles (unions of them model concave ones).
PlanPath visibility_graph_path(std::span<const Polygon2> grown, const vec2& start, const vec2& goal);

}  // namespace gestura
