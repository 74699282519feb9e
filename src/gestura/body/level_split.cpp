#include "gestura/body/level_split.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "gestura/core/error.hpp"

namespace gestura {

std::size_t split_at_level(LevelSplitMesh mesh, float level, float snap, const LevelCrossing& crossing) {
  const std::size_t nv = mesh.positions.size();
  if (mesh.values.size() != nv || mesh.eligible.size() != nv)
    throw Error("split_at_level: values and eligible must have one entry per vertex");
  for (std::size_t v = 0; v < nv; ++v)
    if (mesh.eligible[v] && std::abs(mesh.values[v] - level) < snap)
      mesh.values[v] = mesh.values[v] < level ? level - snap : level + snap;

  auto above = [&](std::uint32_t v) { return mesh.values[v] > level; };
  auto cut = [&](std::uint32_t a, std::uint32_t b) {
    return mesh.eligible[a] && mesh.eligible[b] && above(a) != above(b);
  };
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_on_edge;
  auto vertex = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    auto [it, fresh] = vertex_on_edge.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
    if (fresh) {
      float t = (level - mesh.values[a]) / (mesh.values[b] - mesh.values[a]);
      if (crossing) t = std::clamp(crossing(a, b, t), 0.05f, 0.95f);
      mesh.positions.push_back(glm::mix(mesh.positions[a], mesh.positions[b], t));
      mesh.values.push_back(level);
      mesh.eligible.push_back(1);
    }
    return it->second;
  };

  std::vector<std::uint32_t> out;
  out.reserve(mesh.indices.size() + mesh.indices.size() / 8);
  const auto& P = mesh.positions;
  for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
    const std::array<std::uint32_t, 3> t{mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]};
    std::array<bool, 3> edge_cut{};  // edge k runs from corner k to corner k + 1
    int cuts = 0;
    for (int k = 0; k < 3; ++k) {
      edge_cut[k] = cut(t[k], t[(k + 1) % 3]);
      cuts += edge_cut[k] ? 1 : 0;
    }
    if (cuts == 0) {
      out.insert(out.end(), t.begin(), t.end());
      continue;
    }
    if (cuts == 1) {
      // Corners a → b carry the cut; c is opposite.
      int k = 0;
      while (!edge_cut[k]) ++k;
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const std::uint32_t p = vertex(a, b);
      out.insert(out.end(), {a, p, c, p, b, c});
      continue;
    }
    // Two cut edges meet at the corner a that lies alone on its side: a → b and c → a.
    int k = 0;
    while (!(edge_cut[k] && edge_cut[(k + 2) % 3])) ++k;
    const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    const std::uint32_t p = vertex(a, b), q = vertex(c, a);
    out.insert(out.end(), {a, p, q});
    // The quad p b c q, split along its shorter diagonal.
    if (glm::distance(P[p], P[c]) <= glm::distance(P[b], P[q]))
      out.insert(out.end(), {p, b, c, p, c, q});
    else
      out.insert(out.end(), {p, b, q, b, c, q});
  }
  mesh.indices = std::move(out);
  return mesh.positions.size() - nv;
}

}  // namespace gestura
