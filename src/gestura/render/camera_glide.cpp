#include "gestura/render/camera_glide.hpp"

#include <algorithm>
#include <cmath>

namespace gestura {
namespace {

// One step of a critically damped spring toward `goal` (the closed form's Padé approximation, exact
// enough for any step up to a few smooth times: it never overshoots).
void damp(float& value, float& velocity, float goal, float smooth_time, float dt) {
  const float omega = 2.0f / smooth_time, x = omega * dt;
  const float decay = 1.0f / (1.0f + x + 0.48f * x * x + 0.235f * x * x * x);
  const float change = value - goal;
  const float temp = (velocity + omega * change) * dt;
  velocity = (velocity - omega * temp) * decay;
  value = goal + (change + temp) * decay;
}

struct Perspective {
  float fov = 0.8f, aspect = 1.0f, near = 0.05f, far = 50.0f;
};

Perspective read_perspective(const mat4& p) {
  Perspective out;
  out.fov = 2.0f * std::atan(1.0f / p[1][1]);
  out.aspect = p[1][1] / p[0][0];
  out.near = p[3][2] / (p[2][2] - 1.0f);
  out.far = p[3][2] / (p[2][2] + 1.0f);
  return out;
}

}  // namespace

Camera CameraGlide::follow(const Camera& shot, float dt) {
  if (shot.orthographic) {
    started_ = false;
    return shot;
  }
  const Perspective lens = read_perspective(shot.projection);
  const vec3 offset = shot.eye - shot.target;
  const float distance = std::max(1e-4f, glm::length(offset));
  const float yaw = std::atan2(offset.x, offset.z), pitch = std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f));
  if (!started_ || dt <= 0.0f) {
    for (int a = 0; a < 3; ++a) target_[a] = {shot.target[a], 0.0f};
    yaw_ = {yaw, 0.0f}, pitch_ = {pitch, 0.0f}, distance_ = {distance, 0.0f}, fov_ = {lens.fov, 0.0f};
    started_ = true;
    return shot;
  }
  // Round the shorter way: the yaw goal is taken within half a turn of where the camera is.
  float yaw_goal = yaw;
  while (yaw_goal - yaw_.value > kPi) yaw_goal -= 2.0f * kPi;
  while (yaw_goal - yaw_.value < -kPi) yaw_goal += 2.0f * kPi;
  for (int a = 0; a < 3; ++a) damp(target_[a].value, target_[a].velocity, shot.target[a], smooth_time_, dt);
  damp(yaw_.value, yaw_.velocity, yaw_goal, smooth_time_, dt);
  damp(pitch_.value, pitch_.velocity, pitch, smooth_time_, dt);
  damp(distance_.value, distance_.velocity, distance, smooth_time_, dt);
  damp(fov_.value, fov_.velocity, lens.fov, smooth_time_, dt);

  Camera c = shot;
  c.target = vec3(target_[0].value, target_[1].value, target_[2].value);
  const float p = std::clamp(pitch_.value, deg(-89.0f), deg(89.0f));
  c.eye = c.target + distance_.value * vec3(std::cos(p) * std::sin(yaw_.value), std::sin(p), std::cos(p) * std::cos(yaw_.value));
  for (int axis : {0, 2})
    if (inside_min_[axis] <= inside_max_[axis]) c.eye[axis] = std::clamp(c.eye[axis], inside_min_[axis], inside_max_[axis]);
  c.view = glm::lookAt(c.eye, c.target, vec3(0, 1, 0));
  c.projection = glm::perspective(std::clamp(fov_.value, deg(5.0f), deg(150.0f)), lens.aspect, lens.near, lens.far);
  return c;
}

}  // namespace gestura
