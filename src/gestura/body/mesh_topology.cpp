#include "gestura/body/mesh_topology.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace gestura {

MeshTopology audit_topology(std::span<const vec3> positions, std::span<const std::uint32_t> indices,
                            double min_area) {
  MeshTopology t;
  t.triangles = static_cast<int>(indices.size() / 3);
  const std::size_t nv = positions.size();
  // Directed edge (a → b) counts, keyed by the undirected pair.
  struct EdgeUse {
    int forward = 0, backward = 0;  // forward: a → b with a < b
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(indices.size());
  std::vector<std::uint8_t> referenced(nv, 0);
  std::vector<std::vector<std::uint32_t>> fans(nv);  // triangles around each vertex
  for (std::size_t f = 0; f + 2 < indices.size(); f += 3) {
    const std::uint32_t v[3] = {indices[f], indices[f + 1], indices[f + 2]};
    if (v[0] >= nv || v[1] >= nv || v[2] >= nv) {
      ++t.out_of_range_indices;
      continue;
    }
    const glm::dvec3 a(positions[v[0]]), b(positions[v[1]]), c(positions[v[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || 0.5 * glm::length(n) < min_area) ++t.degenerate_triangles;
    t.signed_volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = v[k], q = v[(k + 1) % 3];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(p, q)) << 32) | std::max(p, q);
      EdgeUse& use = edges[key];
      (p < q ? use.forward : use.backward) += 1;
      referenced[p] = 1;
      fans[p].push_back(static_cast<std::uint32_t>(f / 3));
    }
  }
  t.edges = static_cast<int>(edges.size());
  for (const auto& [key, use] : edges) {
    const int n = use.forward + use.backward;
    if (n == 1) ++t.boundary_edges;
    if (n > 2) ++t.nonmanifold_edges;
    if (n == 2 && (use.forward != 1 || use.backward != 1)) ++t.misoriented_edges;
  }
  // A vertex is manifold when its triangles form one cycle: walk "next triangle" links around it.
  int referenced_count = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!referenced[v]) continue;
    ++referenced_count;
    const auto& fan = fans[v];
    // For each triangle around v, the vertex after v ("out") and before v ("in").
    std::unordered_map<std::uint32_t, std::size_t> by_in;
    std::vector<std::uint32_t> outs(fan.size());
    for (std::size_t i = 0; i < fan.size(); ++i) {
      const std::uint32_t* tri = &indices[fan[i] * 3];
      const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      outs[i] = tri[(k + 1) % 3];
      by_in[tri[(k + 2) % 3]] = i;
    }
    std::size_t steps = 0, i = 0;
    do {
      auto it = by_in.find(outs[i]);
      if (it == by_in.end()) break;
      i = it->second;
      ++steps;
    } while (i != 0 && steps <= fan.size());
    if (i != 0 || steps != fan.size()) ++t.nonmanifold_vertices;
  }
  t.euler_characteristic = referenced_count - t.edges + t.triangles;
  return t;
}

}  // namespace gestura
