#pragma once
// Collision-free shortest paths for a character of a given radius (alias-movement-through-
// environments.txt §7.2). Detour finds the corridor and its string-pulled corners on a navigation
// mesh; the path is then pulled tight against the true radius — each obstacle corner the path turns
// at is wrapped by an arc of the radius (the Minkowski growth of the obstacle by the character's
// disc, Lozano-Pérez), joined by common tangents, the arcs drawn as circumscribed polygons so no
// point comes nearer than the radius — and every segment is checked against the geometry.
//
// Voxels make a navigation mesh either a little too generous or a little too strict near walls, so
// two are used: one eroded a cell less than the radius (it leaves every passage the radius fits
// through open: the shortest way is found), and, when the tightened path through it fails the
// check (the passage was too narrow after all), one eroded two cells more (every point on it keeps
// the radius: its path is safe as it is). A goal that cannot be reached gives a NoPath result saying
// why, never a made-up path.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "gestura/world/navmesh.hpp"

namespace gestura {

struct PathRequest {
  vec3 start{0.0f};
  vec3 goal{0.0f};
  float radius = 0.3f;
  // The goal is an object, not a point on the floor: walk to the reachable point nearest to it.
  bool approach = false;
  vec3 approach_extent{1.0f, 0.6f, 1.0f};  // how far around the goal a floor point may be (approach)
};

enum class PathStatus : std::uint8_t { Found, NoPath };

struct PlannedPath {
  PathStatus status = PathStatus::NoPath;
  std::vector<vec3> points;     // start … goal on the floor; smoothed
  float length = 0.0f;          // horizontal length (m)
  float min_clearance = 0.0f;   // measured: the nearest any segment comes to an obstacle
  std::string reason;           // why there is no path
  bool tightened = false;       // false: the safe navmesh path was kept (tightening failed its check)
};

class PathPlanner {
 public:
  // Contract: `env` outlives the planner. Navigation meshes are built per radius on first use.
  explicit PathPlanner(const Environment& env, const NavMeshSettings& base = {});

  PlannedPath plan(const PathRequest& request);
  // The strict mesh (every point keeps the radius), or with `generous` the one that leaves every
  // passage open. Built on first use.
  const NavMesh& navmesh(float radius, bool generous = false);
  const Environment& environment() const { return *env_; }
  const NavMeshSettings& settings() const { return base_; }

 private:
  const Environment* env_;
  NavMeshSettings base_;
  std::map<std::pair<int, bool>, NavMesh> meshes_;  // by radius in millimetres and generosity
};

// The tightening step alone (exposed for tests): `corners` is a safe polyline from start to goal
// (e.g. Detour's straight path); returns the taut path keeping `radius` from the obstacles, or
// `corners` unchanged when the taut path fails the clearance check.
std::vector<vec3> tighten_path(const Environment& env, std::span<const vec3> corners, float radius, float body_height,
                               bool* tightened = nullptr);

float path_length(std::span<const vec3> points);  // horizontal
// The smallest horizontal clearance along the polyline (searching up to `search`).
float path_clearance(const Environment& env, std::span<const vec3> points, float body_height, float search);

}  // namespace gestura
