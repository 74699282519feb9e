#pragma once
// Moving a character's body along a planned path: turn on the spot toward the way to go when it
// lies behind, start (accelerate), walk with the speed each bend allows, slow down to stop at the
// goal, and turn to a final facing. The pelvis follows the planned path itself (by arc length), so
// the clearance the planner kept holds for the body; avoidance of other walkers (behaviour.hpp)
// shifts it sideways within that clearance or holds it back.
#include <optional>
#include <span>
#include <vector>

#include "gestura/world/environment.hpp"
#include "gestura/world/trajectory.hpp"

namespace gestura {

struct LocomotionParams {
  float speed = 1.3f;               // cruising speed, m/s
  float acceleration = 1.2f;        // m/s² starting
  float deceleration = 1.1f;        // m/s² stopping
  float lateral_acceleration = 1.0f;  // m/s² in bends: speed ≤ √(a·R)
  float climb_slowing = 2.5f;       // up or down stairs and ramps: speed ≤ cruise / (1 + this · rise per metre)
  float turn_rate = deg(140.0f);    // rad/s of the body while walking
  float turn_in_place_rate = deg(110.0f);
  float turn_in_place_above = deg(50.0f);  // a first leg further round than this: turn before walking
};

// A path with its arc length, for following by distance.
struct PathTrack {
  std::vector<vec3> points;
  std::vector<float> lengths;        // cumulative horizontal arc length at each point
  std::vector<float> clearances;     // free room beside each point (metres beyond the radius; ≥ 0)
  std::vector<float> ground;         // the floor's height every 10 cm along the track (empty: the points' heights)

  float total() const { return lengths.empty() ? 0.0f : lengths.back(); }
  vec3 point_at(float s) const;
  vec3 tangent_at(float s) const;    // unit, horizontal
  // Speed limit from the bend around s (circumscribed arcs: the turn of the segments near s).
  float curvature_at(float s) const;
  float clearance_at(float s) const;
  float ground_at(float s) const;    // the floor under the track at s (stairs' treads, not the straight line)
};

// Contract: at least two points. `env` (optional) fills the clearances beside the path.
PathTrack make_track(std::span<const vec3> points, const Environment* env = nullptr, float radius = 0.3f,
                     float body_height = 1.8f);

// One walker's progress along its track.
struct Locomotor {
  enum class Mode : std::uint8_t { Idle, TurnFirst, Walk, TurnLast };
  Mode mode = Mode::Idle;
  vec3 position{0.0f};
  float yaw = 0.0f;
  float speed = 0.0f;         // along the track
  float progress = 0.0f;      // arc length travelled
  float offset = 0.0f;        // sideways shift from the track (+ = left of the direction of travel)
  PathTrack track;
  std::optional<float> final_yaw;
  std::optional<float> turn_goal;  // turning on the spot to this yaw (TurnFirst / TurnLast, or a turn command)
  std::vector<float> speed_limits; // along the track every 5 cm (bends, the stop at the end); made on the first step

  bool busy() const { return mode != Mode::Idle; }
  // Starts following `track` (from the current position, which should be its first point).
  void follow(PathTrack path, std::optional<float> facing_at_end = std::nullopt);
  void turn_to(float yaw);
  void stop();
};

// Advances one walker by dt. `speed_scale` in [0, 1] holds it back (yielding to others);
// `desired_offset` is where avoidance wants it beside the track (clamped to the room there).
void step_locomotor(Locomotor& w, const LocomotionParams& p, float dt, float speed_scale = 1.0f, float desired_offset = 0.0f);

// The whole motion along a path, alone: the root trajectory at `dt`, standing still `hold` seconds
// before and after. Starts facing `start_yaw`; ends facing `end_yaw` when given.
RootTrajectory follow_path(std::span<const vec3> path, float start_yaw, std::optional<float> end_yaw,
                           const LocomotionParams& params = {}, float dt = 1.0f / 60.0f, float hold = 0.5f,
                           const Environment* env = nullptr);

}  // namespace gestura
