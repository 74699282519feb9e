#pragma once
// Topology audit of a triangle mesh: is it a closed, manifold, consistently oriented surface?
// Used by the avatar tests and useful to anyone importing or generating meshes.
#include <cstdint>
#include <span>

#include "gestura/core/math.hpp"

namespace gestura {

struct MeshTopology {
  int triangles = 0;
  int edges = 0;                  // distinct undirected edges
  int boundary_edges = 0;         // used by one triangle (holes)
  int nonmanifold_edges = 0;      // used by more than two triangles
  int misoriented_edges = 0;      // two triangles traverse the edge in the same direction
  int nonmanifold_vertices = 0;   // triangle fan around the vertex is not a single disc
  int degenerate_triangles = 0;   // repeated index or area below min_area
  int out_of_range_indices = 0;
  int euler_characteristic = 0;   // V − E + F over referenced vertices
  double signed_volume = 0.0;     // > 0 for outward (counter-clockwise) orientation

  bool closed_manifold() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 && nonmanifold_vertices == 0 &&
           out_of_range_indices == 0;
  }
};

MeshTopology audit_topology(std::span<const vec3> positions, std::span<const std::uint32_t> indices,
                            double min_area = 1e-12);

}  // namespace gestura
