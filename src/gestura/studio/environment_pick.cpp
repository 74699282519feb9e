#include "gestura/studio/environment_pick.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtx/euler_angles.hpp>
#include <limits>

namespace gestura::studio {
namespace {

// The routines below take any direction (not only unit ones) and return the ray parameter, so a ray
// carried into a scaled frame keeps its world distances.

std::optional<float> first_non_negative(float t0, float t1) {
  if (t0 > t1) std::swap(t0, t1);
  if (t1 < 0.0f) return std::nullopt;
  return t0 >= 0.0f ? t0 : t1;
}

std::optional<float> ray_box(const Ray& r, const vec3& half) {
  float enter = -std::numeric_limits<float>::infinity(), exit = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(r.direction[a]) < 1e-12f) {
      if (std::abs(r.origin[a]) > half[a]) return std::nullopt;
      continue;
    }
    float t0 = (-half[a] - r.origin[a]) / r.direction[a], t1 = (half[a] - r.origin[a]) / r.direction[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0), exit = std::min(exit, t1);
    if (enter > exit) return std::nullopt;
  }
  return first_non_negative(enter, exit);
}

std::optional<float> ray_sphere(const Ray& r, float radius) {
  const float a = glm::dot(r.direction, r.direction), b = glm::dot(r.origin, r.direction);
  const float c = glm::dot(r.origin, r.origin) - radius * radius;
  const float disc = b * b - a * c;
  if (a <= 0.0f || disc < 0.0f) return std::nullopt;
  const float s = std::sqrt(disc);
  return first_non_negative((-b - s) / a, (-b + s) / a);
}

std::optional<float> ray_cylinder(const Ray& r, float radius, float half_height) {
  std::optional<float> best;
  const auto keep = [&](float t) {
    if (t >= 0.0f && (!best || t < *best)) best = t;
  };
  // The side: (ox + t dx)² + (oz + t dz)² = r², within the height.
  const float a = r.direction.x * r.direction.x + r.direction.z * r.direction.z;
  const float b = r.origin.x * r.direction.x + r.origin.z * r.direction.z;
  const float c = r.origin.x * r.origin.x + r.origin.z * r.origin.z - radius * radius;
  if (a > 1e-12f) {
    const float disc = b * b - a * c;
    if (disc >= 0.0f) {
      const float s = std::sqrt(disc);
      for (float t : {(-b - s) / a, (-b + s) / a})
        if (std::abs(r.origin.y + t * r.direction.y) <= half_height) keep(t);
    }
  }
  // The caps.
  if (std::abs(r.direction.y) > 1e-12f)
    for (float y : {-half_height, half_height}) {
      const float t = (y - r.origin.y) / r.direction.y;
      const float x = r.origin.x + t * r.direction.x, z = r.origin.z + t * r.direction.z;
      if (x * x + z * z <= radius * radius) keep(t);
    }
  return best;
}

}  // namespace

Ray pixel_ray(const Camera& camera, vec2 pixel, vec2 size) {
  const vec2 ndc(2.0f * pixel.x / std::max(1.0f, size.x) - 1.0f, 1.0f - 2.0f * pixel.y / std::max(1.0f, size.y));
  const mat4 inverse = glm::inverse(camera.projection * camera.view);
  const vec4 near = inverse * vec4(ndc, -1.0f, 1.0f), far = inverse * vec4(ndc, 1.0f, 1.0f);
  const vec3 a = vec3(near) / near.w, b = vec3(far) / far.w;
  return Ray{a, glm::normalize(b - a)};
}

std::optional<vec2> project_to_pixel(const Camera& camera, const vec3& point, vec2 size) {
  const vec4 clip = camera.projection * camera.view * vec4(point, 1.0f);
  if (clip.w <= 1e-6f) return std::nullopt;
  const vec2 ndc = vec2(clip) / clip.w;
  return vec2((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
}

std::optional<float> ray_shape(const Ray& r, const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Box: return ray_box(r, shape.size * 0.5f);
    case ShapeKind::Plane: {
      if (std::abs(r.direction.y) < 1e-12f) return std::nullopt;
      const float t = -r.origin.y / r.direction.y;
      const vec3 p = r.origin + r.direction * t;
      if (t < 0.0f || std::abs(p.x) > shape.size.x * 0.5f || std::abs(p.z) > shape.size.z * 0.5f) return std::nullopt;
      return t;
    }
    case ShapeKind::Sphere: return ray_sphere(r, shape.radius);
    case ShapeKind::Cylinder: return ray_cylinder(r, shape.radius, shape.height * 0.5f);
    default: return std::nullopt;
  }
}

std::optional<float> ray_placed_shape(const Ray& world_ray, const Shape& shape, const mat4& to_world) {
  const mat4 inverse = glm::inverse(to_world);
  const Ray local{vec3(inverse * vec4(world_ray.origin, 1.0f)), vec3(inverse * vec4(world_ray.direction, 0.0f))};
  return ray_shape(local, shape);
}

std::optional<float> ray_triangle(const Ray& ray, const vec3& a, const vec3& b, const vec3& c) {
  const vec3 e1 = b - a, e2 = c - a;
  const vec3 p = glm::cross(ray.direction, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return std::nullopt;
  const float inv = 1.0f / det;
  const vec3 s = ray.origin - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const vec3 q = glm::cross(s, e1);
  const float v = glm::dot(ray.direction, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  const float t = glm::dot(e2, q) * inv;
  if (t < 0.0f) return std::nullopt;
  return t;
}

std::optional<float> ray_triangles(const Ray& world_ray, std::span<const vec3> positions, std::span<const std::uint32_t> indices,
                                   const mat4& to_world) {
  const mat4 inverse = glm::inverse(to_world);
  const Ray local{vec3(inverse * vec4(world_ray.origin, 1.0f)), vec3(inverse * vec4(world_ray.direction, 0.0f))};
  std::optional<float> best;
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    if (indices[i] >= positions.size() || indices[i + 1] >= positions.size() || indices[i + 2] >= positions.size()) continue;
    const auto t = ray_triangle(local, positions[indices[i]], positions[indices[i + 1]], positions[indices[i + 2]]);
    if (t && (!best || *t < *best)) best = t;
  }
  return best;
}

std::optional<float> ray_upright_cylinder(const Ray& ray, const vec3& base, float radius, float height) {
  const Ray local{ray.origin - (base + vec3(0.0f, height * 0.5f, 0.0f)), ray.direction};
  return ray_cylinder(local, radius, height * 0.5f);
}

std::optional<float> ray_plane(const Ray& ray, const vec3& point, const vec3& normal) {
  const float d = glm::dot(ray.direction, normal);
  if (std::abs(d) < 1e-6f) return std::nullopt;
  return glm::dot(point - ray.origin, normal) / d;
}

std::optional<float> closest_on_axis(const Ray& ray, const vec3& origin, const vec3& axis) {
  // Lines p(s) = origin + s·axis and q(t) = ray.origin + t·dir: minimise |p − q|.
  const vec3 d = glm::normalize(ray.direction);
  const float b = glm::dot(axis, d);
  const float denominator = 1.0f - b * b;
  if (denominator < 3e-4f) return std::nullopt;  // within about 1° of the axis
  const vec3 w = origin - ray.origin;
  return (b * glm::dot(d, w) - glm::dot(axis, w)) / denominator;
}

std::optional<float> drag_along_axis(const Ray& from, const Ray& to, const vec3& origin, const vec3& axis) {
  const auto a = closest_on_axis(from, origin, axis), b = closest_on_axis(to, origin, axis);
  if (!a || !b) return std::nullopt;
  return *b - *a;
}

std::optional<vec3> drag_in_plane(const Ray& from, const Ray& to, const vec3& point, const vec3& normal) {
  const auto a = ray_plane(from, point, normal), b = ray_plane(to, point, normal);
  if (!a || !b) return std::nullopt;
  return to.at(*b) - from.at(*a);
}

std::optional<float> drag_angle(const Ray& from, const Ray& to, const vec3& centre, const vec3& axis) {
  if (std::abs(glm::dot(glm::normalize(from.direction), axis)) < 0.05f) return std::nullopt;  // edge-on
  const auto a = ray_plane(from, centre, axis), b = ray_plane(to, centre, axis);
  if (!a || !b) return std::nullopt;
  const vec3 u = from.at(*a) - centre, v = to.at(*b) - centre;
  if (glm::length(u) < 1e-6f || glm::length(v) < 1e-6f) return std::nullopt;
  return std::atan2(glm::dot(glm::cross(u, v), axis), glm::dot(u, v));
}

vec3 rotate_euler(const vec3& e, const vec3& axis, float radians) {
  const ObjectTransform before{vec3(0.0f), e, vec3(1.0f)};
  const mat4 turned = glm::mat4_cast(glm::angleAxis(radians, axis) * before.orientation());
  float yaw = 0, pitch = 0, roll = 0;
  glm::extractEulerAngleYXZ(turned, yaw, pitch, roll);
  const auto clean = [](float r) {
    const float d = to_degrees(r);
    return std::abs(d) < 1e-4f ? 0.0f : d;
  };
  return vec3(clean(pitch), clean(yaw), clean(roll));
}

float snap(float value, float step) { return step > 0.0f ? std::round(value / step) * step : value; }

float distance_to_segment(vec2 p, vec2 a, vec2 b) {
  const vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + ab * t));
}

}  // namespace gestura::studio
