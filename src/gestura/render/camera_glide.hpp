#pragma once
// A camera that glides to each new shot instead of cutting to it: the shot's aim point, its
// direction round that point (yaw and pitch), its distance and its field of view each follow the
// shot as a critically damped spring (the fastest approach that never overshoots), so a framing that
// jumps — the `characters` view turning round the room when a wall comes in the way — becomes a move
// round the subject that starts and ends gently. Perspective cameras only; an orthographic shot is
// passed through.
#include "gestura/render/camera.hpp"

namespace gestura {

class CameraGlide {
 public:
  // `smooth_time`: seconds the spring takes to cover most of a jump (about 0.6 of it per
  // smooth_time at rest). Contract: > 0.
  explicit CameraGlide(float smooth_time = 0.6f) : smooth_time_(smooth_time) {}

  // The camera `dt` seconds after the last call, heading for `shot`. The first call after
  // construction or reset(), and any call with dt <= 0, takes the shot as it is (a cut).
  Camera follow(const Camera& shot, float dt);
  // Keeps the gliding eye's x and z within [min, max] (a room's walls, less a margin): the way round
  // between two framings inside a room stays inside it. Unset when min > max on either axis.
  void keep_inside(const vec3& min, const vec3& max) { inside_min_ = min, inside_max_ = max; }
  void reset() { started_ = false; }

 private:
  struct Spring {
    float value = 0.0f, velocity = 0.0f;
  };
  float smooth_time_;
  bool started_ = false;
  Spring target_[3], yaw_, pitch_, distance_, fov_;
  vec3 inside_min_{1.0f}, inside_max_{-1.0f};
};

}  // namespace gestura
