#include "gestura/body/surface_quality.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

#include "gestura/core/triangle.hpp"

namespace gestura {
namespace {

float angle_degrees(vec3 a, vec3 b) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f) || !(lb > 0.0f)) return 0.0f;
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f)));
}

// Triangles bucketed in a uniform grid, for nearest-point queries within a few cells.
class TriangleGrid {
 public:
  TriangleGrid(const Mesh& mesh, const std::vector<std::uint32_t>& triangles, float cell) : mesh_(mesh), cell_(cell) {
    for (std::uint32_t t : triangles) {
      vec3 lo(1e9f), hi(-1e9f);
      for (int k = 0; k < 3; ++k) {
        lo = glm::min(lo, mesh.positions[mesh.indices[3 * t + k]]);
        hi = glm::max(hi, mesh.positions[mesh.indices[3 * t + k]]);
      }
      const glm::ivec3 a = key(lo), b = key(hi);
      for (int z = a.z; z <= b.z; ++z)
        for (int y = a.y; y <= b.y; ++y)
          for (int x = a.x; x <= b.x; ++x) cells_[hash({x, y, z})].push_back(t);
    }
  }

  // Distance from p to the nearest bucketed triangle, or `cap` when none lies within it.
  float distance(vec3 p, float cap) const {
    const int reach = static_cast<int>(std::ceil(cap / cell_));
    const glm::ivec3 c = key(p);
    float best = cap;
    for (int z = -reach; z <= reach; ++z)
      for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x) {
          const auto it = cells_.find(hash(c + glm::ivec3(x, y, z)));
          if (it == cells_.end()) continue;
          for (std::uint32_t t : it->second) {
            const vec3 a = mesh_.positions[mesh_.indices[3 * t]], b = mesh_.positions[mesh_.indices[3 * t + 1]],
                       d = mesh_.positions[mesh_.indices[3 * t + 2]];
            best = std::min(best, glm::distance(p, closest_point_on_triangle(p, a, b, d)));
          }
        }
    return best;
  }

 private:
  glm::ivec3 key(vec3 p) const { return glm::ivec3(glm::floor(p / cell_)); }
  static std::uint64_t hash(glm::ivec3 k) {
    return (static_cast<std::uint64_t>(k.x + (1 << 20)) << 42) | (static_cast<std::uint64_t>(k.y + (1 << 20)) << 21) |
           static_cast<std::uint64_t>(k.z + (1 << 20));
  }
  const Mesh& mesh_;
  float cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace

Spread spread_of(std::span<const float> values) {
  Spread s;
  s.count = static_cast<int>(values.size());
  if (values.empty()) return s;
  std::vector<float> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  for (float v : sorted) sum += v;
  s.mean = static_cast<float>(sum / static_cast<double>(sorted.size()));
  s.p95 = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size())))];
  s.max = sorted.back();
  return s;
}

SurfaceQuality measure_surface(const Mesh& mesh, const std::function<bool(std::size_t triangle)>& keep) {
  SurfaceQuality q;
  const std::size_t nt = mesh.triangle_count(), nv = mesh.vertex_count();
  std::vector<std::uint8_t> kept(nt, 0);
  std::vector<std::uint32_t> kept_list;
  std::vector<int> around(nv, 0), around_kept(nv, 0);
  std::vector<vec3> face_normal(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const std::uint32_t* i = &mesh.indices[3 * t];
    face_normal[t] = glm::cross(mesh.positions[i[1]] - mesh.positions[i[0]], mesh.positions[i[2]] - mesh.positions[i[0]]);
    kept[t] = keep(t) ? 1 : 0;
    if (kept[t]) kept_list.push_back(static_cast<std::uint32_t>(t));
    for (int k = 0; k < 3; ++k) {
      ++around[i[k]];
      around_kept[i[k]] += kept[t];
    }
  }
  std::vector<std::uint8_t> measured(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) measured[v] = around[v] > 0 && around[v] == around_kept[v];

  // Creases: interior edges of the region (both triangles kept).
  std::unordered_map<std::uint64_t, std::uint32_t> first_triangle;
  std::vector<float> creases;
  double edge_length = 0.0;
  std::size_t edges = 0;
  std::vector<std::vector<std::uint32_t>> neighbours(nv);
  for (std::uint32_t t : kept_list)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
      const std::uint64_t e = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const auto [it, fresh] = first_triangle.try_emplace(e, t);
      if (fresh) {
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
        edge_length += glm::distance(mesh.positions[a], mesh.positions[b]);
        ++edges;
      } else {
        creases.push_back(angle_degrees(face_normal[it->second], face_normal[t]));
      }
    }
  q.crease_degrees = spread_of(creases);
  q.mean_edge_mm = edges ? static_cast<float>(1000.0 * edge_length / static_cast<double>(edges)) : 0.0f;

  // Roughness: a vertex's shading normal against its neighbours' mean.
  std::vector<float> rough;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!measured[v] || neighbours[v].empty()) continue;
    vec3 mean(0.0f);
    for (std::uint32_t u : neighbours[v]) mean += mesh.normals[u];
    rough.push_back(angle_degrees(mesh.normals[v], mean));
  }
  q.roughness_degrees = spread_of(rough);

  // Asymmetry: the mirror image's distance to the region's surface (capped at 20 mm).
  constexpr float kCap = 0.020f;
  const TriangleGrid grid(mesh, kept_list, 0.01f);
  std::vector<float> asym;
  for (std::size_t v = 0; v < nv; ++v) {
    const vec3 p = mesh.positions[v];
    if (!measured[v] || std::abs(p.x) < 0.001f) continue;
    asym.push_back(1000.0f * grid.distance(vec3(-p.x, p.y, p.z), kCap));
  }
  q.asymmetry_mm = spread_of(asym);
  return q;
}

SurfaceQuality measure_body_region(const Mesh& mesh, const Skeleton& skeleton, BodyRegion region) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  auto at = [&](const char* name) -> std::optional<vec3> {
    const int j = skeleton.find(name);
    if (j < 0) return std::nullopt;
    return vec3(model[static_cast<std::size_t>(j)][3]);
  };
  auto surface_material = [&](std::size_t t, std::initializer_list<MaterialId> allowed) {
    for (int k = 0; k < 3; ++k) {
      const auto m = static_cast<MaterialId>(mesh.materials[mesh.indices[3 * t + static_cast<std::size_t>(k)]]);
      if (std::find(allowed.begin(), allowed.end(), m) == allowed.end()) return false;
    }
    return true;
  };
  auto centroid = [&](std::size_t t) {
    return (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
            mesh.positions[mesh.indices[3 * t + 2]]) /
           3.0f;
  };
  std::function<bool(std::size_t)> keep = [](std::size_t) { return false; };
  switch (region) {
    case BodyRegion::Face: {
      const auto skull = at("skullbase"), l_eye = at("l_eyeball_joint"), r_eye = at("r_eyeball_joint");
      if (!skull || !l_eye || !r_eye) break;
      const float eyes = glm::distance(*l_eye, *r_eye);
      // From the chin (about one eye spacing below the skull base) to the brows; the eye
      // openings (the lids' margins are creases by design) left out.
      const float bottom = skull->y - 0.6f * eyes, top = l_eye->y + 0.75f * eyes, opening = 0.27f * eyes;
      keep = [=, &mesh](std::size_t t) {
        const vec3 c = centroid(t);
        return surface_material(t, {MaterialId::Skin, MaterialId::Brow}) && c.z > skull->z + 0.5f * eyes &&
               c.y > bottom && c.y < top && glm::distance(c, *l_eye) > opening && glm::distance(c, *r_eye) > opening &&
               std::abs(c.x) < 1.1f * eyes;
      };
      break;
    }
    case BodyRegion::Hands: {
      const auto lw = at("l_wrist"), rw = at("r_wrist"), le = at("l_elbow"), re = at("r_elbow");
      if (!lw || !rw || !le || !re) break;
      keep = [=, &mesh](std::size_t t) {
        const vec3 c = centroid(t);
        const bool beyond = glm::dot(c - *lw, glm::normalize(*lw - *le)) > 0.01f ||
                            glm::dot(c - *rw, glm::normalize(*rw - *re)) > 0.01f;
        return beyond && surface_material(t, {MaterialId::Skin});
      };
      break;
    }
    case BodyRegion::Trunk: {
      const auto ls = at("l_shoulder"), lh = at("l_hip");
      if (!ls || !lh) break;
      keep = [=, &mesh](std::size_t t) {
        const vec3 c = centroid(t);
        return std::abs(c.x) < 0.7f * ls->x && c.y > lh->y && c.y < ls->y - 0.04f && surface_material(t, {MaterialId::Cloth});
      };
      break;
    }
  }
  return measure_surface(mesh, keep);
}

}  // namespace gestura
