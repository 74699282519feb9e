#include "gestura/world/bvh.hpp"

#include <algorithm>

namespace gestura {
namespace {

constexpr int kBins = 12;
constexpr std::uint32_t kLeafSize = 4;
constexpr int kMaxDepth = 48;  // keeps the traversal stacks (64 entries) from overflowing

}  // namespace

float Aabb::area() const {
  if (empty()) return 0.0f;
  const vec3 d = max - min;
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

float ray_triangle(const vec3& origin, const vec3& direction, const vec3& a, const vec3& b, const vec3& c) {
  const vec3 e1 = b - a, e2 = c - a;
  const vec3 p = glm::cross(direction, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return -1.0f;
  const float inv = 1.0f / det;
  const vec3 s = origin - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const vec3 q = glm::cross(s, e1);
  const float v = glm::dot(direction, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  return glm::dot(e2, q) * inv;
}

Bvh::Bvh(std::span<const vec3> positions, std::span<const std::uint32_t> indices)
    : positions_(positions.begin(), positions.end()), indices_(indices.begin(), indices.end()) {
  const std::size_t n = indices_.size() / 3;
  indices_.resize(n * 3);
  order_.resize(n);
  tri_boxes_.resize(n);
  tri_centres_.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    order_[t] = t;
    vec3 a, b, c;
    triangle(t, a, b, c);
    Aabb box;
    box.grow(a), box.grow(b), box.grow(c);
    tri_boxes_[t] = box;
    tri_centres_[t] = box.centre();
  }
  if (n == 0) return;
  nodes_.reserve(2 * n);
  nodes_.push_back({});
  nodes_[0].first = 0;
  nodes_[0].count = static_cast<std::uint32_t>(n);
  build(0, 0);
}

void Bvh::build(std::uint32_t node, int depth) {
  const std::uint32_t first = nodes_[node].first, count = nodes_[node].count;
  Aabb box, centres;
  for (std::uint32_t k = first; k < first + count; ++k) box.grow(tri_boxes_[order_[k]]), centres.grow(tri_centres_[order_[k]]);
  nodes_[node].box = box;
  if (count <= kLeafSize || depth >= kMaxDepth) return;

  // Binned SAH over the widest axis of the centres.
  const vec3 extent = centres.max - centres.min;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  if (!(extent[axis] > 1e-9f)) return;  // all centres coincide: a leaf
  struct Bin {
    Aabb box;
    std::uint32_t count = 0;
  } bins[kBins];
  const float scale = static_cast<float>(kBins) / extent[axis];
  auto bin_of = [&](std::uint32_t t) {
    return std::min(kBins - 1, static_cast<int>((tri_centres_[t][axis] - centres.min[axis]) * scale));
  };
  for (std::uint32_t k = first; k < first + count; ++k) {
    Bin& b = bins[bin_of(order_[k])];
    b.box.grow(tri_boxes_[order_[k]]);
    ++b.count;
  }
  float best_cost = 1e30f;
  int best_split = -1;
  for (int split = 1; split < kBins; ++split) {
    Aabb left, right;
    std::uint32_t nl = 0, nr = 0;
    for (int i = 0; i < split; ++i) left.grow(bins[i].box), nl += bins[i].count;
    for (int i = split; i < kBins; ++i) right.grow(bins[i].box), nr += bins[i].count;
    if (nl == 0 || nr == 0) continue;
    const float cost = left.area() * static_cast<float>(nl) + right.area() * static_cast<float>(nr);
    if (cost < best_cost) best_cost = cost, best_split = split;
  }
  if (best_split < 0) return;
  const auto mid_it = std::partition(order_.begin() + first, order_.begin() + first + count,
                                     [&](std::uint32_t t) { return bin_of(t) < best_split; });
  const auto left_count = static_cast<std::uint32_t>(mid_it - (order_.begin() + first));
  if (left_count == 0 || left_count == count) return;
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[left].first = first, nodes_[left].count = left_count;
  nodes_[left + 1].first = first + left_count, nodes_[left + 1].count = count - left_count;
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(left, depth + 1);
  build(left + 1, depth + 1);
}

}  // namespace gestura
