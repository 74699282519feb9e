#pragma once
// Key interpolation. Scalar and vector tracks use cubic Hermite segments whose tangents come from
// the neighbouring keys (Catmull-Rom, cardinal, Kochanek–Bartels); quaternion tracks use nlerp,
// slerp or squad. Tangents are adjusted for uneven key spacing so splines stay C1 *in time*.
#include <cstdint>
#include <optional>
#include <string_view>

#include "gestura/core/math.hpp"

namespace gestura {

enum class Interpolation : std::uint8_t {
  Step,             // hold the previous key
  Linear,           // lerp; for rotations nlerp on the shortest arc
  Cardinal,         // Hermite with tangents (1 - tension)·(p[k+1] - p[k-1]) / 2  (track tension)
  CatmullRom,       // cardinal with tension 0
  KochanekBartels,  // per-key tension, continuity, bias (TCB)
  Slerp,            // rotations: constant angular speed along the great arc
  Squad,            // rotations: spherical cubic through the keys (C1 for evenly timed keys)
};

std::string_view to_string(Interpolation interpolation);
std::optional<Interpolation> parse_interpolation(std::string_view text);

// Kochanek–Bartels parameters of one key; all zero gives Catmull-Rom.
struct Tcb {
  float tension = 0.0f;
  float continuity = 0.0f;
  float bias = 0.0f;
};

// Cubic Hermite basis on u ∈ [0, 1]: p0, p1 the end values, m0, m1 the end tangents per unit u.
template <class T>
inline T hermite(const T& p0, const T& m0, const T& p1, const T& m1, float u) {
  const float u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
}

// Kochanek–Bartels tangents at key k given the previous/next values and the two adjacent segment
// durations. `outgoing` is the tangent leaving k (for segment k→k+1, per unit of that segment's
// parameter); `incoming` the tangent arriving at k (segment k-1→k). Both are scaled for uneven
// spacing: with continuity 0 they give the same velocity in time on both sides.
template <class T>
inline void kb_tangents(const T& prev, const T& cur, const T& next, float dt_prev, float dt_next,
                        const Tcb& tcb, T& incoming, T& outgoing) {
  const T d_in = cur - prev, d_out = next - cur;
  const float t = tcb.tension, c = tcb.continuity, b = tcb.bias;
  const T src = (0.5f * (1 - t) * (1 + b) * (1 - c)) * d_in + (0.5f * (1 - t) * (1 - b) * (1 + c)) * d_out;
  const T dst = (0.5f * (1 - t) * (1 + b) * (1 + c)) * d_in + (0.5f * (1 - t) * (1 - b) * (1 - c)) * d_out;
  const float sum = dt_prev + dt_next;
  outgoing = sum > 0 ? (2.0f * dt_next / sum) * src : src;
  incoming = sum > 0 ? (2.0f * dt_prev / sum) * dst : dst;
}

// Quaternion helpers for squad.
quat quat_log(const quat& q);  // unit q → pure quaternion (w = 0)
quat quat_exp(const quat& q);  // pure quaternion → unit q
// Intermediate control point of squad at q (Shoemake): q·exp(−(log(q⁻¹·next) + log(q⁻¹·prev))/4).
quat squad_control(const quat& prev, const quat& q, const quat& next);
quat squad(const quat& q0, const quat& q1, const quat& s0, const quat& s1, float u);

}  // namespace gestura
