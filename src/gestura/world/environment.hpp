#pragma once
// The environment as the characters sense and collide with it: the scene's solid triangles in world
// space in a BVH, each marked walkable (a floor, a tread, a ramp: its normal within the walkable
// slope of up) or not (walls, furniture sides, stair risers), plus the primitives for exact
// distances. "Environment data bases are accessible to characters, so characters can search through
// the data base to find the ground plane" (alias-movement-through-environments.txt ch. 7).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gestura/core/triangle.hpp"
#include "gestura/world/bvh.hpp"
#include "gestura/world/scene_geometry.hpp"

namespace gestura {

struct EnvironmentOptions {
  float max_slope_degrees = 40.0f;  // steeper surfaces are not ground
  float max_climb = 0.3f;           // a step this high is climbed, not walked around (stair risers, kerbs)
};

struct WorldPrimitive {
  int object = -1;
  Shape shape;
  mat4 to_world{1.0f};
  mat4 to_local{1.0f};
  float scale_min = 1.0f;  // smallest axis scale of to_world (distances in the local frame × this)
  Aabb box;                // world bounds, for culling
};

struct Environment {
  std::vector<vec3> positions;                 // world space
  std::vector<std::uint32_t> indices;
  std::vector<std::uint16_t> triangle_object;  // top-level object per triangle
  std::vector<std::uint8_t> triangle_walkable; // 1 = ground
  // Per triangle: the height above which it is in a standing character's way — the ground just
  // outside the face plus max_climb (a stair riser never is; a wall is from knee height on);
  // +inf for walkable triangles.
  std::vector<float> obstacle_floor;
  std::vector<WorldPrimitive> primitives;
  Bvh bvh;
  float walkable_cos = 0.766f;
  float max_climb = 0.3f;

  std::size_t triangle_count() const { return indices.size() / 3; }
  vec3 triangle_normal(std::uint32_t t) const;
};

// The solid (obstacle) objects of `geometry` placed by `object_transforms` (empty: the geometry's
// own), in a BVH. Cost: linear in the triangles (a few ms for a furnished room).
Environment build_environment(const SceneGeometry& geometry, std::span<const mat4> object_transforms = {},
                              const EnvironmentOptions& options = {});

struct GroundHit {
  float height = 0.0f;
  vec3 normal{0, 1, 0};
  int object = -1;
};

// The ground under (x, z): the first upward-facing surface met by a ray going down from
// (x, from_y, z), no further than max_drop. Walls and undersides are passed through.
std::optional<GroundHit> ground_below(const Environment& env, const vec3& from, float max_drop = 100.0f);

// Whether the straight segment a–b is free of obstacles (ignores triangles of object `ignore`).
bool line_of_sight(const Environment& env, const vec3& a, const vec3& b, int ignore = -1);

// Exact signed distance from `p` to the nearest primitive (negative inside one); +1e30 without
// primitives. Meshes are not counted (they have no inside): use the BVH for them.
float primitive_signed_distance(const Environment& env, const vec3& p, int* object = nullptr);

// Closest points between segment p0–p1 and triangle abc; returns the distance.
float segment_triangle_distance(const vec3& p0, const vec3& p1, const vec3& a, const vec3& b, const vec3& c,
                                vec3* on_segment = nullptr, vec3* on_triangle = nullptr);

// Closest points between segments p0–p1 and q0–q1; returns the distance.
float segment_segment_distance(const vec3& p0, const vec3& p1, const vec3& q0, const vec3& q1, vec3* on_p = nullptr,
                               vec3* on_q = nullptr);

}  // namespace gestura
