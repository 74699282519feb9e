#pragma once
// The geometry under the environment editor's mouse (alias-movement-through-environments.txt ch. 7):
// the ray a camera sees through a pixel and back, rays against the four primitives, and the gizmo's
// drags (along an axis, in a plane, round an axis). Plain functions over plain data, so they can be
// tested without a window.
//
// Pixels: x to the right, y down, origin at the view's top-left corner; `size` is the view's size in
// pixels. Rays: a unit direction; hits are distances along it (metres).
#include <optional>
#include <span>

#include "gestura/core/math.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/world/scene.hpp"

namespace gestura::studio {

struct Ray {
  vec3 origin{0.0f};
  vec3 direction{0.0f, 0.0f, -1.0f};  // unit

  vec3 at(float t) const { return origin + direction * t; }
};

// The ray through `pixel` (perspective: from the eye; orthographic: parallel, from the near plane).
Ray pixel_ray(const Camera& camera, vec2 pixel, vec2 size);
// Where `point` lands in the view; none when it lies behind a perspective camera.
std::optional<vec2> project_to_pixel(const Camera& camera, const vec3& point, vec2 size);

// First hit (distance ≥ 0) of `ray` with a primitive in its own frame (box, plane, cylinder, sphere:
// centred on the origin, as world/shapes.hpp lays them). A ray starting inside a solid hits its
// surface on the way out. None for a miss and for kinds None and Mesh.
std::optional<float> ray_shape(const Ray& local_ray, const Shape& shape);
// The same for a primitive placed by `to_world` (any affine map, non-uniform scale included); the
// distance is along the world ray.
std::optional<float> ray_placed_shape(const Ray& world_ray, const Shape& shape, const mat4& to_world);
// Möller–Trumbore; both sides count.
std::optional<float> ray_triangle(const Ray& ray, const vec3& a, const vec3& b, const vec3& c);
// Triangles (`indices` into `positions`) placed by `to_world`: the nearest hit.
std::optional<float> ray_triangles(const Ray& world_ray, std::span<const vec3> positions, std::span<const std::uint32_t> indices,
                                   const mat4& to_world);
// An upright cylinder standing on `base` (a character's body): sides and top.
std::optional<float> ray_upright_cylinder(const Ray& ray, const vec3& base, float radius, float height);
std::optional<float> ray_plane(const Ray& ray, const vec3& point, const vec3& normal);

// ---- the gizmo ----

// The parameter t of the point on the line `origin + t·axis` (axis unit) nearest to the ray; none
// when the ray runs along the axis (within 1°), where a drag along it means nothing.
std::optional<float> closest_on_axis(const Ray& ray, const vec3& origin, const vec3& axis);
// How far a drag from ray `from` to ray `to` moves a point along `axis` through `origin`.
std::optional<float> drag_along_axis(const Ray& from, const Ray& to, const vec3& origin, const vec3& axis);
// How far a drag moves a point in the plane through `point` with `normal` (the hits' difference).
std::optional<vec3> drag_in_plane(const Ray& from, const Ray& to, const vec3& point, const vec3& normal);
// The angle (radians, counter-clockwise looking down `axis` toward `centre`, i.e. the right-hand
// rule about `axis`) swept by a drag round `centre`; none when the plane is seen edge-on.
std::optional<float> drag_angle(const Ray& from, const Ray& to, const vec3& centre, const vec3& axis);
// Euler angles (degrees: yaw about Y outermost, then pitch about X, then roll about Z, as
// ObjectTransform) after turning by `radians` about `axis` (unit, in the parent's frame).
vec3 rotate_euler(const vec3& euler_degrees, const vec3& axis, float radians);
// Rounds to the nearest multiple of `step`; step ≤ 0 leaves the value.
float snap(float value, float step);
// Distance (pixels) from `p` to the segment a–b on screen: how near the mouse is to a handle.
float distance_to_segment(vec2 p, vec2 a, vec2 b);

}  // namespace gestura::studio
