#pragma once
// Where a character's body is over time: the point on the floor under its pelvis and the way it
// faces, sampled at a fixed rate. What the simulation produces and the walking skill turns into steps.
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

struct RootTrajectory {
  float dt = 1.0f / 60.0f;           // seconds between samples
  std::vector<vec3> positions;       // on the floor (y = ground height under the pelvis)
  std::vector<float> yaws;           // radians about +Y; 0 faces +Z

  std::size_t size() const { return positions.size(); }
  float duration() const { return positions.empty() ? 0.0f : dt * static_cast<float>(positions.size() - 1); }
  void push(const vec3& p, float yaw) { positions.push_back(p), yaws.push_back(yaw); }

  // Linear interpolation (yaw along the short way), clamped to the ends.
  vec3 position_at(float t) const;
  float yaw_at(float t) const;
  // Horizontal speed (m/s) and turn rate (rad/s) by central differences.
  float speed_at(float t) const;
  float turn_rate_at(float t) const;
};

// Forward direction of a yaw: (sin yaw, 0, cos yaw).
inline vec3 heading(float yaw) { return {std::sin(yaw), 0.0f, std::cos(yaw)}; }
// The yaw of a horizontal direction.
inline float yaw_of(const vec3& d) { return std::atan2(d.x, d.z); }
// a − b wrapped into (−π, π].
float angle_difference(float a, float b);

}  // namespace gestura
