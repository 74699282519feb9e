#include "gestura/world/environment.hpp"

#include <algorithm>
#include <limits>

#include "gestura/core/error.hpp"

namespace gestura {

vec3 Environment::triangle_normal(std::uint32_t t) const {
  const vec3 a = positions[indices[3 * t]], b = positions[indices[3 * t + 1]], c = positions[indices[3 * t + 2]];
  const vec3 n = glm::cross(b - a, c - a);
  const float len = glm::length(n);
  return len > 0.0f ? n / len : vec3(0, 1, 0);
}

Environment build_environment(const SceneGeometry& geometry, std::span<const mat4> object_transforms,
                              const EnvironmentOptions& options) {
  const std::size_t objects = geometry.object_names.size();
  if (!object_transforms.empty() && object_transforms.size() != objects)
    throw Error("build_environment: " + std::to_string(object_transforms.size()) + " transforms for " +
                std::to_string(objects) + " objects");
  if (objects > 65535) throw Error("build_environment: more than 65535 top-level objects");
  auto transform_of = [&](std::size_t o) -> const mat4& {
    return object_transforms.empty() ? geometry.object_transforms[o] : object_transforms[o];
  };
  Environment env;
  env.walkable_cos = std::cos(deg(std::clamp(options.max_slope_degrees, 0.0f, 89.0f)));
  for (std::size_t o = 0; o < objects; ++o) {
    if (!geometry.object_obstacle[o]) continue;
    const mat4& m = transform_of(o);
    const bool mirrored = glm::determinant(mat3(m)) < 0.0f;
    const std::uint32_t first = geometry.object_first[o], count = geometry.object_count[o];
    // Only the vertices this object's triangles use, in order of first use.
    std::vector<std::uint32_t> remap;
    std::vector<std::uint32_t> used;
    for (std::uint32_t k = first; k < first + count; ++k) used.push_back(geometry.indices[k]);
    std::uint32_t lo = used.empty() ? 0 : *std::min_element(used.begin(), used.end());
    std::uint32_t hi = used.empty() ? 0 : *std::max_element(used.begin(), used.end());
    const auto base = static_cast<std::uint32_t>(env.positions.size());
    for (std::uint32_t v = lo; v <= hi && !used.empty(); ++v) env.positions.push_back(vec3(m * vec4(geometry.positions[v], 1.0f)));
    for (std::uint32_t k = 0; k + 2 < count; k += 3) {
      const std::uint32_t a = base + used[k] - lo, b = base + used[k + 1] - lo, c = base + used[k + 2] - lo;
      env.indices.push_back(a);
      env.indices.push_back(mirrored ? c : b);
      env.indices.push_back(mirrored ? b : c);
      env.triangle_object.push_back(static_cast<std::uint16_t>(o));
    }
  }
  env.triangle_walkable.resize(env.triangle_count());
  for (std::uint32_t t = 0; t < env.triangle_count(); ++t)
    env.triangle_walkable[t] = env.triangle_normal(t).y >= env.walkable_cos ? 1 : 0;
  for (const PlacedPrimitive& p : geometry.primitives) {
    const auto o = static_cast<std::size_t>(p.object);
    if (!geometry.object_obstacle[o]) continue;
    WorldPrimitive w;
    w.object = p.object;
    w.shape = p.shape;
    w.to_world = transform_of(o) * p.to_object;
    w.to_local = glm::inverse(w.to_world);
    w.scale_min = std::min({glm::length(vec3(w.to_world[0])), glm::length(vec3(w.to_world[1])), glm::length(vec3(w.to_world[2]))});
    // World box from the tessellation's corners (exact enough for culling; spheres and cylinders
    // are covered by their bounding box in the local frame).
    vec3 half = p.shape.kind == ShapeKind::Box ? p.shape.size * 0.5f
                : p.shape.kind == ShapeKind::Plane ? vec3(p.shape.size.x * 0.5f, 0.0f, p.shape.size.z * 0.5f)
                : p.shape.kind == ShapeKind::Cylinder ? vec3(p.shape.radius, p.shape.height * 0.5f, p.shape.radius)
                                                      : vec3(p.shape.radius);
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 c((corner & 1) ? half.x : -half.x, (corner & 2) ? half.y : -half.y, (corner & 4) ? half.z : -half.z);
      w.box.grow(vec3(w.to_world * vec4(c, 1.0f)));
    }
    env.primitives.push_back(w);
  }
  env.bvh = Bvh(env.positions, env.indices);
  env.max_climb = options.max_climb;
  // Where each steep face starts to be in the way: the ground just outside it (below its lowest
  // point, a little off the face along its normal) plus the climbable step height.
  env.obstacle_floor.assign(env.triangle_count(), std::numeric_limits<float>::infinity());
  for (std::uint32_t t = 0; t < env.triangle_count(); ++t) {
    if (env.triangle_walkable[t]) continue;
    const vec3 a = env.positions[env.indices[3 * t]], b = env.positions[env.indices[3 * t + 1]], c = env.positions[env.indices[3 * t + 2]];
    const float lowest = std::min({a.y, b.y, c.y});
    vec3 n = env.triangle_normal(t);
    n.y = 0.0f;
    const vec3 out = glm::length(n) > 1e-4f ? glm::normalize(n) * 0.02f : vec3(0.0f);
    const vec3 probe = (a + b + c) / 3.0f + out;
    const auto ground = ground_below(env, vec3(probe.x, lowest + 0.01f, probe.z), 1000.0f);
    env.obstacle_floor[t] = (ground ? ground->height : lowest) + options.max_climb;
  }
  return env;
}

std::optional<GroundHit> ground_below(const Environment& env, const vec3& from, float max_drop) {
  BvhHit hit;
  const bool found = env.bvh.raycast(from, vec3(0, -1, 0), max_drop, hit, [&](std::uint32_t t) {
    return env.triangle_normal(t).y > 0.2f;  // an upward-facing surface: floors, treads, ramps, table tops
  });
  if (!found) return std::nullopt;
  return GroundHit{hit.point.y, hit.normal, env.triangle_object[hit.triangle]};
}

bool line_of_sight(const Environment& env, const vec3& a, const vec3& b, int ignore) {
  const vec3 d = b - a;
  const float len = glm::length(d);
  if (len < 1e-6f) return true;
  BvhHit hit;
  return !env.bvh.raycast(a, d / len, len * (1.0f - 1e-4f), hit,
                          [&](std::uint32_t t) { return static_cast<int>(env.triangle_object[t]) != ignore; });
}

float primitive_signed_distance(const Environment& env, const vec3& p, int* object) {
  float best = 1e30f;
  for (const WorldPrimitive& w : env.primitives) {
    // Cull by the box: the distance is at least the distance to the box.
    const vec3 outside = glm::max(glm::max(w.box.min - p, p - w.box.max), vec3(0.0f));
    if (glm::length(outside) >= best) continue;
    const vec3 local = vec3(w.to_local * vec4(p, 1.0f));
    const float d = shape_signed_distance(w.shape, local) * w.scale_min;
    if (d < best) {
      best = d;
      if (object) *object = w.object;
    }
  }
  return best;
}

float segment_segment_distance(const vec3& p0, const vec3& p1, const vec3& q0, const vec3& q1, vec3* on_p, vec3* on_q) {
  // Ericson 5.1.9.
  const vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  float s = 0.0f, t = 0.0f;
  if (a <= 1e-12f && e <= 1e-12f) {
    s = t = 0.0f;
  } else if (a <= 1e-12f) {
    t = std::clamp(f / e, 0.0f, 1.0f);
  } else {
    const float c = glm::dot(d1, r);
    if (e <= 1e-12f) {
      s = std::clamp(-c / a, 0.0f, 1.0f);
    } else {
      const float b = glm::dot(d1, d2), denom = a * e - b * b;
      s = denom > 1e-12f ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0.0f) t = 0.0f, s = std::clamp(-c / a, 0.0f, 1.0f);
      else if (t > 1.0f) t = 1.0f, s = std::clamp((b - c) / a, 0.0f, 1.0f);
    }
  }
  const vec3 cp = p0 + d1 * s, cq = q0 + d2 * t;
  if (on_p) *on_p = cp;
  if (on_q) *on_q = cq;
  return glm::length(cp - cq);
}

float segment_triangle_distance(const vec3& p0, const vec3& p1, const vec3& a, const vec3& b, const vec3& c, vec3* on_segment,
                                vec3* on_triangle) {
  // The segment crossing the triangle: distance 0 at the crossing.
  const vec3 d = p1 - p0;
  const float t = ray_triangle(p0, d, a, b, c);
  if (t >= 0.0f && t <= 1.0f) {
    const vec3 x = p0 + d * t;
    if (on_segment) *on_segment = x;
    if (on_triangle) *on_triangle = x;
    return 0.0f;
  }
  // Otherwise the closest pair involves a segment end against the face or the segment against an edge.
  float best = 1e30f;
  vec3 bs{0.0f}, bt{0.0f};
  for (const vec3& p : {p0, p1}) {
    const vec3 q = closest_point_on_triangle(p, a, b, c);
    const float dist = glm::length(p - q);
    if (dist < best) best = dist, bs = p, bt = q;
  }
  const vec3 edges[3][2] = {{a, b}, {b, c}, {c, a}};
  for (const auto& e : edges) {
    vec3 sp, tp;
    const float dist = segment_segment_distance(p0, p1, e[0], e[1], &sp, &tp);
    if (dist < best) best = dist, bs = sp, bt = tp;
  }
  if (on_segment) *on_segment = bs;
  if (on_triangle) *on_triangle = bt;
  return best;
}

}  // namespace gestura
