#pragma once
// A bounding-volume hierarchy over triangles: axis-aligned boxes split by the surface-area
// heuristic (binned), nodes in one flat array, children of a node next to each other. The queries
// the world needs: the first hit of a ray, whether anything blocks a segment (line of sight), and
// every triangle whose box meets a query box (for distance and penetration tests).
#include <cstdint>
#include <span>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

struct Aabb {
  vec3 min{1e30f};
  vec3 max{-1e30f};

  void grow(const vec3& p) { min = glm::min(min, p), max = glm::max(max, p); }
  void grow(const Aabb& b) { min = glm::min(min, b.min), max = glm::max(max, b.max); }
  bool empty() const { return min.x > max.x; }
  vec3 centre() const { return (min + max) * 0.5f; }
  float area() const;
  bool overlaps(const Aabb& b) const {
    return min.x <= b.max.x && max.x >= b.min.x && min.y <= b.max.y && max.y >= b.min.y && min.z <= b.max.z && max.z >= b.min.z;
  }
};

struct BvhNode {
  Aabb box;
  std::uint32_t first = 0;   // leaf: first entry in Bvh::order; inner: index of the left child
  std::uint32_t count = 0;   // leaf: triangle count; 0 = inner node (children first, first + 1)
};

struct BvhHit {
  float distance = 0.0f;
  std::uint32_t triangle = 0;
  vec3 point{0.0f};
  vec3 normal{0.0f};  // geometric, from the winding, not flipped toward the ray
};

class Bvh {
 public:
  Bvh() = default;
  // Contract: `indices` holds whole triangles into `positions`. Copies both.
  Bvh(std::span<const vec3> positions, std::span<const std::uint32_t> indices);

  std::size_t triangle_count() const { return indices_.size() / 3; }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_[0].box; }
  void triangle(std::uint32_t t, vec3& a, vec3& b, vec3& c) const {
    a = positions_[indices_[3 * t]], b = positions_[indices_[3 * t + 1]], c = positions_[indices_[3 * t + 2]];
  }

  // The nearest hit with distance in (0, max_distance] along the unit `direction`. Triangles for
  // which `accept(t)` is false are passed through (e.g. the actor's own door, non-obstacles).
  template <class Accept>
  bool raycast(const vec3& origin, const vec3& direction, float max_distance, BvhHit& hit, Accept&& accept) const;
  bool raycast(const vec3& origin, const vec3& direction, float max_distance, BvhHit& hit) const {
    return raycast(origin, direction, max_distance, hit, [](std::uint32_t) { return true; });
  }

  // Calls visit(t) for every triangle whose box overlaps `box`.
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const;

 private:
  void build(std::uint32_t node, int depth);
  std::vector<vec3> positions_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::uint32_t> order_;   // triangle ids, leaves own contiguous runs
  std::vector<Aabb> tri_boxes_;
  std::vector<vec3> tri_centres_;
  std::vector<BvhNode> nodes_;
};

// Möller–Trumbore; the distance along `direction` (any length) or a negative value on a miss.
float ray_triangle(const vec3& origin, const vec3& direction, const vec3& a, const vec3& b, const vec3& c);

// Slab test: the entry distance into `box` along the ray (inv_direction = 1/direction), or a value
// beyond max_distance on a miss.
inline float ray_box(const vec3& origin, const vec3& inv_direction, const Aabb& box, float max_distance) {
  const vec3 t0 = (box.min - origin) * inv_direction, t1 = (box.max - origin) * inv_direction;
  const vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
  const float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, 0.0f));
  const float leave = std::min(std::min(hi.x, hi.y), std::min(hi.z, max_distance));
  return enter <= leave ? enter : max_distance * 2.0f + 1.0f;
}

template <class Accept>
bool Bvh::raycast(const vec3& origin, const vec3& direction, float max_distance, BvhHit& hit, Accept&& accept) const {
  if (nodes_.empty()) return false;
  const vec3 inv(1.0f / direction.x, 1.0f / direction.y, 1.0f / direction.z);
  float best = max_distance;
  bool found = false;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& n = nodes_[stack[--top]];
    if (ray_box(origin, inv, n.box, best) > best) continue;
    if (n.count == 0) {
      const float dl = ray_box(origin, inv, nodes_[n.first].box, best);
      const float dr = ray_box(origin, inv, nodes_[n.first + 1].box, best);
      // Nearer child on top of the stack, so its hits shrink `best` before the other is opened.
      if (dl <= dr) {
        if (dr <= best) stack[top++] = n.first + 1;
        if (dl <= best) stack[top++] = n.first;
      } else {
        if (dl <= best) stack[top++] = n.first;
        if (dr <= best) stack[top++] = n.first + 1;
      }
      continue;
    }
    for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
      const std::uint32_t t = order_[k];
      vec3 a, b, c;
      triangle(t, a, b, c);
      const float d = ray_triangle(origin, direction, a, b, c);
      if (d > 0.0f && d <= best && accept(t)) {
        best = d, found = true;
        hit.distance = d;
        hit.triangle = t;
        const vec3 nrm = glm::cross(b - a, c - a);
        hit.normal = glm::length(nrm) > 0.0f ? glm::normalize(nrm) : vec3(0, 1, 0);
      }
    }
  }
  if (found) hit.point = origin + direction * hit.distance;
  return found;
}

template <class Visit>
void Bvh::query(const Aabb& box, Visit&& visit) const {
  if (nodes_.empty()) return;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& n = nodes_[stack[--top]];
    if (!n.box.overlaps(box)) continue;
    if (n.count == 0) {
      stack[top++] = n.first;
      stack[top++] = n.first + 1;
      continue;
    }
    for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
      if (tri_boxes_[order_[k]].overlaps(box)) visit(order_[k]);
  }
}

}  // namespace gestura
