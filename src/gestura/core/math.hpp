#pragma once
// Math vocabulary on glm. Units: metres, seconds, radians. +Y up, the avatar faces +Z, its left is +X.
// Quaternions are glm::quat (w, x, y, z constructor order; stored x, y, z, w).
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cmath>
#include <numbers>

namespace gestura {

using glm::mat3;
using glm::mat4;
using glm::quat;
using glm::vec2;
using glm::vec3;
using glm::vec4;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float deg(float degrees) { return degrees * (kPi / 180.0f); }
inline constexpr float to_degrees(float radians) { return radians * (180.0f / kPi); }

// A rigid-plus-scale transform kept in parts (what animation stores and blends).
struct Transform {
  vec3 translation{0.0f};
  quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  vec3 scale{1.0f};

  mat4 matrix() const;  // T · R · S
};

inline mat4 Transform::matrix() const {
  mat4 m = glm::mat4_cast(rotation);
  m[0] *= scale.x;
  m[1] *= scale.y;
  m[2] *= scale.z;
  m[3] = vec4(translation, 1.0f);
  return m;
}

// Normalised linear interpolation on the shortest arc (cheap, monotonic enough between close keys).
inline quat nlerp(const quat& a, const quat& b, float t) {
  const float sign = glm::dot(a, b) < 0.0f ? -1.0f : 1.0f;
  quat q{a.w + (sign * b.w - a.w) * t, a.x + (sign * b.x - a.x) * t, a.y + (sign * b.y - a.y) * t,
         a.z + (sign * b.z - a.z) * t};
  return glm::normalize(q);
}

inline bool is_finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool is_finite(const quat& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

}  // namespace gestura
