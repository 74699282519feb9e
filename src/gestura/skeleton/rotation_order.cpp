#include "gestura/skeleton/rotation_order.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace gestura {

std::array<int, 3> axes_of(RotationOrder order) {
  switch (order) {
    case RotationOrder::XYZ: return {0, 1, 2};
    case RotationOrder::XZY: return {0, 2, 1};
    case RotationOrder::YXZ: return {1, 0, 2};
    case RotationOrder::YZX: return {1, 2, 0};
    case RotationOrder::ZXY: return {2, 0, 1};
    case RotationOrder::ZYX: return {2, 1, 0};
  }
  return {0, 1, 2};
}

std::string_view to_string(RotationOrder order) {
  static constexpr std::string_view names[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  return names[static_cast<int>(order)];
}

std::optional<RotationOrder> parse_rotation_order(std::string_view text) {
  if (text.size() != 3) return std::nullopt;
  std::string up(text);
  for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (RotationOrder o : kAllRotationOrders)
    if (to_string(o) == up) return o;
  return std::nullopt;
}

static quat axis_rotation(int axis, float angle) {
  vec3 a(0.0f);
  a[axis] = 1.0f;
  return glm::angleAxis(angle, a);
}

quat euler_to_quat(const vec3& angles, RotationOrder order) {
  const auto ax = axes_of(order);
  return axis_rotation(ax[0], angles[ax[0]]) * axis_rotation(ax[1], angles[ax[1]]) *
         axis_rotation(ax[2], angles[ax[2]]);
}

// Decomposition of R = R_i(a) R_j(b) R_k(c) for any permutation (i, j, k) of the axes, using the
// rotation matrix. parity is +1 for cyclic (x→y→z) permutations and −1 otherwise.
vec3 quat_to_euler(const quat& q, RotationOrder order) {
  const auto ax = axes_of(order);
  const int i = ax[0], j = ax[1], k = ax[2];
  const float parity = ((j - i + 3) % 3 == 1) ? 1.0f : -1.0f;
  const mat3 m = glm::mat3_cast(glm::normalize(q));  // m[col][row]
  auto M = [&](int r, int c) { return static_cast<double>(m[c][r]); };
  vec3 out(0.0f);
  const double sb = std::clamp(parity * M(i, k), -1.0, 1.0);
  const double b = std::asin(sb);
  double a, c;
  if (std::abs(sb) < 0.9999995) {
    a = std::atan2(-parity * M(j, k), M(k, k));
    c = std::atan2(-parity * M(i, j), M(i, i));
  } else {
    // Gimbal lock: only a ± c is defined; put it all in the outer angle.
    c = 0.0;
    a = std::atan2(parity * M(k, j), M(j, j));
  }
  out[i] = static_cast<float>(a);
  out[j] = static_cast<float>(b);
  out[k] = static_cast<float>(c);
  return out;
}

static float wrap_near(float angle, float target) {
  const float two_pi = 2.0f * kPi;
  return angle + two_pi * std::round((target - angle) / two_pi);
}

vec3 quat_to_euler_near(const quat& q, RotationOrder order, const vec3& near) {
  const auto ax = axes_of(order);
  const vec3 first = quat_to_euler(q, order);
  // The other solution of the same rotation: (a + π, π − b, c + π).
  vec3 second = first;
  second[ax[0]] += kPi;
  second[ax[1]] = kPi - first[ax[1]];
  second[ax[2]] += kPi;
  vec3 best = first;
  float best_d = 1e30f;
  for (vec3 cand : {first, second}) {
    for (int a = 0; a < 3; ++a) cand[a] = wrap_near(cand[a], near[a]);
    const vec3 d = cand - near;
    const float dist = glm::dot(d, d);
    if (dist < best_d) best_d = dist, best = cand;
  }
  return best;
}

}  // namespace gestura
