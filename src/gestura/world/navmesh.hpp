#pragma once
// The walkable floor of an environment as a Recast navigation mesh, queried with Detour: where a
// character of a given radius can stand (floors, treads, ramps up to the walkable slope, steps up to
// the climb height), and the corridor of polygons from A to B with its string-pulled corners.
//
// The mesh is eroded by the agent's radius plus a margin (voxel and contour simplification errors
// can otherwise bring its edges up to a cell or two closer to obstacles than the radius), so every
// point on it keeps at least the radius from the obstacles. path_planner.hpp then pulls the path
// tight against the true radius.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gestura/world/environment.hpp"

namespace gestura {

struct NavMeshSettings {
  float agent_radius = 0.3f;
  float agent_height = 1.8f;
  float max_climb = 0.3f;          // step height
  float max_slope_degrees = 40.0f;
  float cell_size = 0.05f;         // horizontal voxel size, metres
  float cell_height = 0.02f;       // vertical voxel size
  // Extra erosion beyond the radius, in cells: covers the voxelisation and the contour tracing
  // (Recast's chamfer distance and simplification put walls up to ~1.5 cells closer).
  float margin_cells = 2.0f;
};

enum class NavQueryStatus : std::uint8_t { Found, StartOffMesh, GoalOffMesh, Disconnected };

struct NavPath {
  NavQueryStatus status = NavQueryStatus::Found;
  std::vector<vec3> points;   // string-pulled corners, start and goal included (on the mesh)
};

class NavMesh {
 public:
  NavMesh();
  ~NavMesh();
  NavMesh(NavMesh&&) noexcept;
  NavMesh& operator=(NavMesh&&) noexcept;

  // Builds the mesh for one agent size. Throws gestura::Error when Recast or Detour fail (an
  // environment with no walkable ground at all builds an empty mesh, on which every query misses).
  static NavMesh build(const Environment& env, const NavMeshSettings& settings);

  const NavMeshSettings& settings() const;
  bool empty() const;
  int polygon_count() const;

  // The nearest point on the mesh within `search` (half extents) of p, or none.
  std::optional<vec3> nearest_point(const vec3& p, const vec3& search = vec3(0.5f, 1.0f, 0.5f)) const;

  // Corridor and straight path from `start` to `goal` (each snapped onto the mesh within
  // `snap`); Disconnected when the goal's polygon cannot be reached from the start's.
  NavPath find_path(const vec3& start, const vec3& goal, const vec3& snap = vec3(0.5f, 1.0f, 0.5f)) const;

  // The shortest path within the mesh's floor: the visibility graph of the floor outline's inner
  // corners (the only places a shortest path can turn), searched by A* with each edge checked by a
  // walk along the mesh (Detour raycast). Only paths shorter than `bound` are searched (pass the
  // length of a known path: the search stays inside the ellipse it allows). Corners are moved 2 cm
  // into the floor so paths between them do not graze its edges. None when nothing within the
  // bound connects start and goal (both must be on the mesh).
  std::optional<std::vector<vec3>> visibility_path(const vec3& start, const vec3& goal, float bound) const;
  std::size_t corner_count() const;

  // Moves from `from` toward `to` along the mesh surface, stopping at its edges (what a walker
  // pushed by avoidance may do without leaving the floor). `from` must be on the mesh.
  vec3 move_along_surface(const vec3& from, const vec3& to) const;

  // Whether a straight walk from a to b stays on the mesh.
  bool straight_walkable(const vec3& a, const vec3& b) const;

  // The outline edges of the mesh polygons (pairs of points) for drawing the floor plan.
  std::vector<vec3> boundary_edges() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gestura
