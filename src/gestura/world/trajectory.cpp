#include "gestura/world/trajectory.hpp"

#include <algorithm>

namespace gestura {

float angle_difference(float a, float b) {
  float d = std::fmod(a - b, 2.0f * kPi);
  if (d > kPi) d -= 2.0f * kPi;
  if (d <= -kPi) d += 2.0f * kPi;
  return d;
}

namespace {

// Sample index and fraction for time t.
std::pair<std::size_t, float> locate(const RootTrajectory& r, float t) {
  if (r.size() < 2 || !(t > 0.0f)) return {0, 0.0f};
  const float x = t / r.dt;
  const auto i = static_cast<std::size_t>(x);
  if (i >= r.size() - 1) return {r.size() - 2, 1.0f};
  return {i, x - static_cast<float>(i)};
}

}  // namespace

vec3 RootTrajectory::position_at(float t) const {
  if (positions.empty()) return vec3(0.0f);
  if (positions.size() == 1) return positions[0];
  const auto [i, f] = locate(*this, t);
  return glm::mix(positions[i], positions[i + 1], f);
}

float RootTrajectory::yaw_at(float t) const {
  if (yaws.empty()) return 0.0f;
  if (yaws.size() == 1) return yaws[0];
  const auto [i, f] = locate(*this, t);
  return yaws[i] + f * angle_difference(yaws[i + 1], yaws[i]);
}

float RootTrajectory::speed_at(float t) const {
  const float h = dt;
  const vec3 a = position_at(t - h), b = position_at(t + h);
  const float span = std::min(t + h, duration()) - std::max(t - h, 0.0f);
  if (span <= 0.0f) return 0.0f;
  return glm::length(vec2(b.x - a.x, b.z - a.z)) / span;
}

float RootTrajectory::turn_rate_at(float t) const {
  const float h = dt;
  const float span = std::min(t + h, duration()) - std::max(t - h, 0.0f);
  if (span <= 0.0f) return 0.0f;
  return angle_difference(yaw_at(t + h), yaw_at(t - h)) / span;
}

}  // namespace gestura
