#include "gestura/world/visibility_graph.hpp"

#include <algorithm>
#include <limits>
#include <queue>

namespace gestura {
namespace {

float cross(const vec2& o, const vec2& a, const vec2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool strictly_inside(const vec2& p, std::span<const vec2> polygon, float tolerance) {
  if (polygon.size() < 3) return false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const vec2& a = polygon[i];
    const vec2& b = polygon[(i + 1) % polygon.size()];
    const float len = glm::length(b - a);
    if (len <= 0.0f || cross(a, b, p) / len <= tolerance) return false;
  }
  return true;
}

}  // namespace

Polygon2 convex_hull(std::vector<vec2> points) {
  std::sort(points.begin(), points.end(), [](const vec2& a, const vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Polygon2 hull(2 * points.size());
  std::size_t k = 0;
  for (const vec2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0f) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    const vec2& p = points[i];
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p) <= 0.0f) --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);
  return hull;
}

Polygon2 grow_convex(std::span<const vec2> polygon, float radius, int sides) {
  const float reach = radius / std::cos(kPi / static_cast<float>(sides));
  std::vector<vec2> sums;
  for (const vec2& v : polygon)
    for (int k = 0; k < sides; ++k) {
      const float a = 2.0f * kPi * (static_cast<float>(k) + 0.5f) / static_cast<float>(sides);
      sums.push_back(v + reach * vec2(std::cos(a), std::sin(a)));
    }
  return convex_hull(std::move(sums));
}

bool segment_enters(const vec2& a, const vec2& b, std::span<const vec2> polygon, float tolerance) {
  if (polygon.size() < 3) return false;
  // Cyrus–Beck: the part of the segment on the inner side of every edge.
  float enter = 0.0f, leave = 1.0f;
  const vec2 d = b - a;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const vec2& p = polygon[i];
    const vec2& q = polygon[(i + 1) % polygon.size()];
    const vec2 edge = q - p;
    const float len = glm::length(edge);
    if (len <= 0.0f) continue;
    const vec2 inward(-edge.y / len, edge.x / len);  // left of a counter-clockwise edge
    const float num = glm::dot(a - p, inward) - tolerance;  // > 0: a strictly inside this edge
    const float den = glm::dot(d, inward);
    if (std::abs(den) < 1e-12f) {
      if (num <= 0.0f) return false;  // parallel and not strictly inside
      continue;
    }
    const float t = -num / den;
    if (den > 0.0f) enter = std::max(enter, t);
    else leave = std::min(leave, t);
    if (enter >= leave) return false;
  }
  return (leave - enter) * glm::length(d) > tolerance;
}

PlanPath visibility_graph_path(std::span<const Polygon2> grown, const vec2& start, const vec2& goal) {
  PlanPath out;
  const float tol = 1e-5f;
  for (const Polygon2& g : grown)
    if (strictly_inside(start, g, tol) || strictly_inside(goal, g, tol)) return out;
  std::vector<vec2> nodes{start, goal};
  for (std::size_t i = 0; i < grown.size(); ++i)
    for (const vec2& v : grown[i]) {
      bool free = true;
      for (std::size_t j = 0; j < grown.size() && free; ++j)
        if (j != i && strictly_inside(v, grown[j], tol)) free = false;
      if (free) nodes.push_back(v);
    }
  const std::size_t n = nodes.size();
  auto visible = [&](std::size_t a, std::size_t b) {
    for (const Polygon2& g : grown)
      if (segment_enters(nodes[a], nodes[b], g, tol)) return false;
    return true;
  };
  std::vector<float> dist(n, std::numeric_limits<float>::infinity());
  std::vector<std::size_t> previous(n, n);
  std::vector<bool> done(n, false);
  dist[0] = 0.0f;
  using Item = std::pair<float, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  open.push({0.0f, 0});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (done[u]) continue;
    done[u] = true;
    if (u == 1) break;
    for (std::size_t v = 0; v < n; ++v) {
      if (done[v]) continue;
      const float w = glm::length(nodes[v] - nodes[u]);
      if (d + w >= dist[v] || !visible(u, v)) continue;
      dist[v] = d + w;
      previous[v] = u;
      open.push({dist[v], v});
    }
  }
  if (!done[1]) return out;
  out.found = true;
  out.length = dist[1];
  for (std::size_t v = 1; v != n; v = previous[v]) {
    out.points.push_back(nodes[v]);
    if (v == 0) break;
  }
  std::reverse(out.points.begin(), out.points.end());
  return out;
}

}  // namespace gestura
