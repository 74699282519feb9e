#include "gestura/body/material_borders.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/body/level_split.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Vertices within `rings` edges of a vertex for which `seed` is true.
std::vector<std::uint8_t> grow(std::vector<std::uint8_t> mark, std::span<const std::uint32_t> indices, int rings) {
  for (int r = 0; r < rings; ++r) {
    std::vector<std::uint8_t> next = mark;
    for (std::size_t f = 0; f + 2 < indices.size(); f += 3)
      if (mark[indices[f]] || mark[indices[f + 1]] || mark[indices[f + 2]])
        next[indices[f]] = next[indices[f + 1]] = next[indices[f + 2]] = 1;
    mark = std::move(next);
  }
  return mark;
}

void sharpen(const MaterialBorder& border, float half_width, std::vector<vec3>& positions,
             std::vector<std::uint32_t>& indices, std::vector<std::uint8_t>& materials) {
  const auto below = static_cast<std::uint8_t>(border.below), above = static_cast<std::uint8_t>(border.above);
  const std::size_t n = positions.size();
  std::vector<std::uint8_t> eligible(n, 0), seed(n, 0);
  for (std::size_t v = 0; v < n; ++v) eligible[v] = materials[v] == below || materials[v] == above;
  // Seeds: both ends of every edge between the two materials. The field is evaluated three rings
  // around them (enough to rescale it on the two rings where its level lines can run).
  for (std::size_t f = 0; f + 2 < indices.size(); f += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = indices[f + k], b = indices[f + (k + 1) % 3];
      if (eligible[a] && eligible[b] && materials[a] != materials[b]) seed[a] = seed[b] = 1;
    }
  const std::vector<std::uint8_t> evaluated = grow(seed, indices, 3);
  std::vector<float> g(n, 0.0f);
  for (std::size_t v = 0; v < n; ++v)
    if (evaluated[v] && eligible[v]) g[v] = border.field(positions[v]);

  // The field's rate of change along the surface at each vertex: the mean gradient magnitude of its
  // linear interpolant over the triangles around it.
  std::vector<float> slope(n, 0.0f), count(n, 0.0f);
  for (std::size_t f = 0; f + 2 < indices.size(); f += 3) {
    const std::uint32_t a = indices[f], b = indices[f + 1], c = indices[f + 2];
    if (!(evaluated[a] && evaluated[b] && evaluated[c] && eligible[a] && eligible[b] && eligible[c])) continue;
    const vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
    const vec3 normal = glm::cross(e1, e2);
    const float area2 = glm::dot(normal, normal);
    if (!(area2 > 0.0f)) continue;
    // Gradient of the linear function with values g at the corners, in the triangle's plane.
    const vec3 grad = ((g[b] - g[a]) * glm::cross(e2, normal) + (g[c] - g[a]) * glm::cross(normal, e1)) / area2;
    const float m = glm::length(grad);
    for (std::uint32_t v : {a, b, c}) slope[v] += m, count[v] += 1.0f;
  }
  // Signed distance to the border along the surface (first order); vertices away from the border
  // keep their side at a distance no level line can reach.
  std::vector<float> s(n, 0.0f);
  const float far = 1e3f;
  for (std::size_t v = 0; v < n; ++v) {
    if (!eligible[v]) continue;
    const float side = materials[v] == below ? -1.0f : 1.0f;
    if (!evaluated[v] || count[v] == 0.0f || !(slope[v] > 0.0f)) {
      s[v] = side * far;
      continue;
    }
    s[v] = g[v] / (slope[v] / count[v]);
    if (!std::isfinite(s[v]) || std::abs(s[v]) >= far) s[v] = side * far;
  }
  // Only vertices whose whole neighbourhood was rescaled take part in the cuts; the others keep their
  // material (they are two rings away from any change).
  std::vector<std::uint8_t> cut_eligible(n, 0);
  for (std::size_t v = 0; v < n; ++v) cut_eligible[v] = eligible[v] && count[v] > 0.0f && std::abs(s[v]) < far;
  for (std::size_t v = 0; v < n; ++v)
    if (cut_eligible[v]) materials[v] = s[v] < 0.0f ? below : above;

  // Each cut vertex goes where the field itself reaches the level (rescaled by the edge's slope),
  // found by bisection along the edge: a linear guess misplaces it wherever the field bends within
  // a triangle, as across a brow's thin tail.
  const std::size_t original = n;
  auto crossing_at = [&](float level) {
    return [&, level](std::uint32_t a, std::uint32_t b, float t) {
      float rate = 0.0f, known = 0.0f;
      for (std::uint32_t v : {a, b})
        if (v < original && count[v] > 0.0f) rate += slope[v] / count[v], known += 1.0f;
      if (known == 0.0f) return t;
      const float target = level * rate / known;
      const vec3 pa = positions[a], pb = positions[b];
      float lo = 0.0f, hi = 1.0f;
      const float fa = border.field(pa) - target, fb = border.field(pb) - target;
      if ((fa < 0.0f) == (fb < 0.0f)) return t;
      for (int i = 0; i < 12; ++i) {
        const float mid = 0.5f * (lo + hi);
        ((border.field(glm::mix(pa, pb, mid)) - target < 0.0f) == (fa < 0.0f) ? lo : hi) = mid;
      }
      return 0.5f * (lo + hi);
    };
  };
  const float snap = 0.25f * half_width;
  for (float level : {-half_width, half_width}) {
    split_at_level({positions, indices, s, cut_eligible}, level, snap, crossing_at(level));
    materials.resize(positions.size(), level < 0.0f ? below : above);
  }
}

}  // namespace

void sharpen_material_borders(std::span<const MaterialBorder> borders, float half_width, std::vector<vec3>& positions,
                              std::vector<std::uint32_t>& indices, std::vector<std::uint8_t>& materials) {
  if (materials.size() != positions.size())
    throw Error("sharpen_material_borders: one material per vertex expected");
  if (!(half_width > 0.0f)) throw Error("sharpen_material_borders: half_width must be positive");
  for (const MaterialBorder& border : borders) sharpen(border, half_width, positions, indices, materials);
}

}  // namespace gestura
