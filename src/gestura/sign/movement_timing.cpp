#include "gestura/sign/movement_timing.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

float clamp01(float t) { return std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f; }

// Trapezoidal speed with ramps of fraction r: peak speed v = 1 / (1 − r) so the area is 1.
float ramped_progress(float t) {
  const float r = kRampFraction, v = 1.0f / (1.0f - r);
  if (t < r) return 0.5f * v * t * t / r;
  if (t > 1.0f - r) {
    const float u = 1.0f - t;
    return 1.0f - 0.5f * v * u * u / r;
  }
  return 0.5f * v * r + v * (t - r);
}
float ramped_velocity(float t) {
  const float r = kRampFraction, v = 1.0f / (1.0f - r);
  if (t < r) return v * t / r;
  if (t > 1.0f - r) return v * (1.0f - t) / r;
  return v;
}
float ramped_acceleration(float t) {
  const float r = kRampFraction, v = 1.0f / (1.0f - r);
  if (t < r) return v / r;
  if (t > 1.0f - r) return -v / r;
  return 0.0f;
}

float phase(float start, float duration, float time) {
  if (!(duration > 0.0f)) return time >= start ? 1.0f : 0.0f;
  return clamp01((time - start) / duration);
}

void check_length(float length, const char* what) {
  if (!std::isfinite(length) || length < 0.0f)
    throw Error(std::string(what) + ": path length must be a finite, non-negative number of metres");
}

}  // namespace

float minimum_jerk(float t) {
  t = clamp01(t);
  return t * t * t * (10.0f + t * (-15.0f + 6.0f * t));
}
float minimum_jerk_velocity(float t) {
  t = clamp01(t);
  return 30.0f * t * t * (1.0f - t) * (1.0f - t);
}
float minimum_jerk_acceleration(float t) {
  t = clamp01(t);
  return 60.0f * t * (1.0f - t) * (1.0f - 2.0f * t);
}

float profile_progress(VelocityProfile profile, float t) {
  t = clamp01(t);
  switch (profile) {
    case VelocityProfile::Linear: return t;
    case VelocityProfile::MinimumJerk: return minimum_jerk(t);
    case VelocityProfile::EaseInOut: return 0.5f * (1.0f - std::cos(kPi * t));
    case VelocityProfile::ConstantRamped: return ramped_progress(t);
  }
  return t;
}
float profile_velocity(VelocityProfile profile, float t) {
  t = clamp01(t);
  switch (profile) {
    case VelocityProfile::Linear: return 1.0f;
    case VelocityProfile::MinimumJerk: return minimum_jerk_velocity(t);
    case VelocityProfile::EaseInOut: return 0.5f * kPi * std::sin(kPi * t);
    case VelocityProfile::ConstantRamped: return ramped_velocity(t);
  }
  return 1.0f;
}
float profile_acceleration(VelocityProfile profile, float t) {
  t = clamp01(t);
  switch (profile) {
    case VelocityProfile::Linear: return 0.0f;
    case VelocityProfile::MinimumJerk: return minimum_jerk_acceleration(t);
    case VelocityProfile::EaseInOut: return 0.5f * kPi * kPi * std::cos(kPi * t);
    case VelocityProfile::ConstantRamped: return ramped_acceleration(t);
  }
  return 0.0f;
}

float speed_factor(MovementSpeed speed) {
  switch (speed) {
    case MovementSpeed::Slow: return 1.5f;
    case MovementSpeed::Normal: return 1.0f;
    case MovementSpeed::Fast: return 0.65f;
  }
  return 1.0f;
}

float straight_duration(float path_length, MovementSpeed speed) {
  check_length(path_length, "straight movement");
  return (0.3f + path_length / 0.45f) * speed_factor(speed);
}

float continuous_duration(float path_length, MovementSpeed speed) {
  check_length(path_length, "continuous movement");
  return (0.3f + path_length / 0.6f) * speed_factor(speed);
}

float transition_duration(float distance) {
  check_length(distance, "transition");
  return 0.15f + distance / 0.8f;
}

HandPosture sample(const PostureTransition& transition, float time) {
  return mix(transition.from, transition.to, minimum_jerk(phase(transition.start, transition.duration, time)));
}

Placement sample(const PlacementTransition& transition, float time) {
  const float s = minimum_jerk(phase(transition.start, transition.duration, time));
  return {transition.from_position + (transition.to_position - transition.from_position) * s,
          glm::normalize(glm::slerp(transition.from_rotation, transition.to_rotation, s))};
}

}  // namespace gestura
