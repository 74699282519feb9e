#include "gestura/world/clearance.hpp"

#include <algorithm>

namespace gestura {

float cross2(const vec2& a, const vec2& b) { return a.x * b.y - a.y * b.x; }

float point_segment_distance2(const vec2& p, const vec2& a, const vec2& b, vec2* closest) {
  const vec2 d = b - a;
  const float len2 = glm::dot(d, d);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
  const vec2 c = a + d * t;
  if (closest) *closest = c;
  return glm::length(p - c);
}

float segment_segment_distance2(const vec2& p0, const vec2& p1, const vec2& q0, const vec2& q1, vec2* on_p, vec2* on_q) {
  const vec2 r = p1 - p0, s = q1 - q0;
  const float denom = cross2(r, s);
  if (std::abs(denom) > 1e-12f) {
    const float t = cross2(q0 - p0, s) / denom, u = cross2(q0 - p0, r) / denom;
    if (t >= 0.0f && t <= 1.0f && u >= 0.0f && u <= 1.0f) {
      const vec2 x = p0 + r * t;
      if (on_p) *on_p = x;
      if (on_q) *on_q = x;
      return 0.0f;
    }
  }
  float best = 1e30f;
  vec2 bp{0.0f}, bq{0.0f}, c;
  auto consider = [&](float d, const vec2& pp, const vec2& qq) {
    if (d < best) best = d, bp = pp, bq = qq;
  };
  consider(point_segment_distance2(p0, q0, q1, &c), p0, c);
  consider(point_segment_distance2(p1, q0, q1, &c), p1, c);
  consider(point_segment_distance2(q0, p0, p1, &c), c, q0);
  consider(point_segment_distance2(q1, p0, p1, &c), c, q1);
  if (on_p) *on_p = bp;
  if (on_q) *on_q = bq;
  return best;
}

namespace {

// Clips a convex polygon to lo <= y <= hi (Sutherland–Hodgman on two planes). At most 5 points.
int clip_to_band(const vec3* in, int n, float lo, float hi, vec3* out) {
  vec3 tmp[8];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const vec3& a = in[i];
    const vec3& b = in[(i + 1) % n];
    const bool ia = a.y >= lo, ib = b.y >= lo;
    if (ia) tmp[m++] = a;
    if (ia != ib) tmp[m++] = a + (b - a) * ((lo - a.y) / (b.y - a.y));
  }
  int k = 0;
  for (int i = 0; i < m; ++i) {
    const vec3& a = tmp[i];
    const vec3& b = tmp[(i + 1) % m];
    const bool ia = a.y <= hi, ib = b.y <= hi;
    if (ia) out[k++] = a;
    if (ia != ib) out[k++] = a + (b - a) * ((hi - a.y) / (b.y - a.y));
  }
  return k;
}

}  // namespace

Clearance segment_clearance(const Environment& env, const vec3& a, const vec3& b, float body_height, float search) {
  Clearance best;
  best.distance = search;
  const vec2 a2(a.x, a.z), b2(b.x, b.z);
  const float top = std::max(a.y, b.y) + body_height;
  Aabb box;
  box.min = vec3(std::min(a.x, b.x) - search, std::min(a.y, b.y) - 1.0f, std::min(a.z, b.z) - search);
  box.max = vec3(std::max(a.x, b.x) + search, top, std::max(a.z, b.z) + search);
  env.bvh.query(box, [&](std::uint32_t t) {
    const float floor = env.obstacle_floor[t];
    if (!(floor < top)) return;  // walkable, or entirely below what is in the way
    const vec3 tri[3] = {env.positions[env.indices[3 * t]], env.positions[env.indices[3 * t + 1]],
                         env.positions[env.indices[3 * t + 2]]};
    vec3 poly[8];
    const int n = clip_to_band(tri, 3, floor, top, poly);
    if (n == 0) return;
    // The projected polygon: the segment inside it or crossing an edge means distance 0.
    float d = 1e30f;
    vec2 on_path{0.0f}, on_obstacle{0.0f};
    bool inside = n >= 3;
    float sign = 0.0f;
    for (int i = 0; i < n && d > 0.0f; ++i) {
      const vec2 p(poly[i].x, poly[i].z), q(poly[(i + 1) % n].x, poly[(i + 1) % n].z);
      vec2 sp, sq;
      const float e = segment_segment_distance2(a2, b2, p, q, &sp, &sq);
      if (e < d) d = e, on_path = sp, on_obstacle = sq;
      const float side = cross2(q - p, a2 - p);
      if (std::abs(side) > 1e-9f) {
        if (sign == 0.0f) sign = side;
        else if ((side > 0.0f) != (sign > 0.0f)) inside = false;
      }
    }
    if (inside && sign != 0.0f && d > 0.0f) d = 0.0f, on_path = a2, on_obstacle = a2;
    if (d < best.distance) {
      best.distance = d;
      best.on_path = on_path;
      best.obstacle = on_obstacle;
      best.object = env.triangle_object[t];
    }
  });
  return best;
}

}  // namespace gestura
