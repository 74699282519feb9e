#include "gestura/body/mesh_simplify.hpp"

#include <algorithm>
#include <array>

namespace gestura {

int collapse_short_edges(std::vector<vec3>& positions, std::vector<std::uint32_t>& indices, float ratio) {
  using Tri = std::array<std::uint32_t, 3>;
  const std::size_t nt = indices.size() / 3, nv = positions.size();
  std::vector<Tri> tris(nt);
  std::vector<std::uint8_t> tri_alive(nt, 1), vert_alive(nv, 1);
  std::vector<std::vector<std::uint32_t>> around(nv);
  for (std::size_t t = 0; t < nt; ++t) {
    tris[t] = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    for (std::uint32_t v : tris[t]) around[v].push_back(static_cast<std::uint32_t>(t));
  }
  // Candidates: (relative length, u, v).
  struct Candidate {
    float rel;
    std::uint32_t u, v;
  };
  std::vector<Candidate> candidates;
  for (const Tri& t : tris) {
    float longest = 0.0f;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::distance(positions[t[k]], positions[t[(k + 1) % 3]]));
    for (int k = 0; k < 3; ++k) {
      const float len = glm::distance(positions[t[k]], positions[t[(k + 1) % 3]]);
      if (len < ratio * longest) candidates.push_back({len / longest, t[k], t[(k + 1) % 3]});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.rel < b.rel; });

  auto neighbours = [&](std::uint32_t v) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t t : around[v])
      if (tri_alive[t])
        for (std::uint32_t w : tris[t])
          if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  auto normal = [&](const Tri& t, std::uint32_t moved, const vec3& to) {
    auto p = [&](std::uint32_t v) { return v == moved ? to : positions[v]; };
    return glm::cross(p(t[1]) - p(t[0]), p(t[2]) - p(t[0]));
  };

  int collapses = 0;
  for (const Candidate& c : candidates) {
    const std::uint32_t u = c.u, v = c.v;
    if (!vert_alive[u] || !vert_alive[v]) continue;
    std::vector<std::uint32_t> shared;  // triangles with both u and v
    for (std::uint32_t t : around[u])
      if (tri_alive[t] && std::find(tris[t].begin(), tris[t].end(), v) != tris[t].end()) shared.push_back(t);
    if (shared.size() != 2) continue;
    // Link condition: the common neighbours of u and v are exactly the two opposite vertices.
    const auto nu = neighbours(u), nv2 = neighbours(v);
    std::vector<std::uint32_t> common;
    std::set_intersection(nu.begin(), nu.end(), nv2.begin(), nv2.end(), std::back_inserter(common));
    if (common.size() != 2) continue;
    if (nu.size() + nv2.size() < 8) continue;  // would leave a vertex of valence < 3 (tetrahedron case)
    const vec3 target = 0.5f * (positions[u] + positions[v]);
    bool ok = true;
    for (std::uint32_t w : {u, v})
      for (std::uint32_t t : around[w]) {
        if (!tri_alive[t] || t == shared[0] || t == shared[1]) continue;
        const vec3 before = normal(tris[t], w, positions[w]);
        // After the collapse both u and v sit at `target`.
        Tri after = tris[t];
        for (std::uint32_t& x : after)
          if (x == u) x = v;
        const vec3 n = normal(after, v, target);
        const float lb = glm::length(before), la = glm::length(n);
        if (la < 1e-12f || lb < 1e-14f || glm::dot(before, n) < 0.5f * la * lb) ok = false;
      }
    if (!ok) continue;
    for (std::uint32_t t : shared) tri_alive[t] = 0;
    for (std::uint32_t t : around[u]) {
      if (!tri_alive[t]) continue;
      for (std::uint32_t& x : tris[t])
        if (x == u) x = v;
      around[v].push_back(t);
    }
    around[u].clear();
    vert_alive[u] = 0;
    positions[v] = target;
    ++collapses;
  }

  std::vector<std::uint32_t> remap(nv, UINT32_MAX);
  std::vector<vec3> kept;
  std::vector<std::uint8_t> used(nv, 0);
  for (std::size_t t = 0; t < nt; ++t)
    if (tri_alive[t])
      for (std::uint32_t x : tris[t]) used[x] = 1;
  for (std::size_t v = 0; v < nv; ++v)
    if (used[v]) {
      remap[v] = static_cast<std::uint32_t>(kept.size());
      kept.push_back(positions[v]);
    }
  indices.clear();
  for (std::size_t t = 0; t < nt; ++t)
    if (tri_alive[t])
      for (std::uint32_t x : tris[t]) indices.push_back(remap[x]);
  positions = std::move(kept);
  return collapses;
}

}  // namespace gestura
