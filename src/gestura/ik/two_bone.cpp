#include "gestura/ik/two_bone.hpp"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gestura {
namespace {

// 1/√x: the SSE estimate refined by one Newton step (about 2e-7 relative; shorter latency than a
// square root followed by a division, and the solve is a chain of them).
float inverse_sqrt(float x) {
#if defined(__SSE2__)
  const float y = _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)));
  return y * (1.5f - 0.5f * x * y * y);
#else
  return 1.0f / std::sqrt(x);
#endif
}

quat unit(const quat& q) { return q * inverse_sqrt(glm::dot(q, q)); }

// Angles are carried as unit (cos, sin) pairs and turned into quaternions by half-angle formulas, so
// the solve needs square roots but no trigonometry (acos, atan2, sin, cos) on its common path.
struct Turn {
  float c = 1.0f, s = 0.0f;
};

Turn operator*(const Turn& a, const Turn& b) { return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s}; }  // a + b
Turn reverse(const Turn& a) { return {a.c, -a.s}; }                                                      // −a

// The rotation by the angle `a` about the unit axis n, cos(a/2) ≥ 0: (1 + cos a, sin a · n) points
// the way of (cos a/2, sin a/2 · n) (scaled by 2 cos a/2), so one normalisation gives it; near half a
// turn, where that vanishes, sin a/2 comes from its own half-angle formula.
quat axis_turn(const vec3& n, const Turn& a) {
  float w, s;
  if (a.c > -0.5f) {
    w = std::sqrt(0.5f * (1.0f + a.c));
    s = a.s / (2.0f * w);
  } else {
    s = std::copysign(std::sqrt(0.5f * (1.0f - a.c)), a.s);
    w = a.s / (2.0f * s);
  }
  return quat(w, s * n.x, s * n.y, s * n.z);
}

// The signed angle from u to v about the unit axis n, both taken in the plane perpendicular to n;
// no turn when either has no direction there (as atan2(0, 0) = 0).
Turn signed_turn(const vec3& u, const vec3& v, const vec3& n) {
  const vec3 up = u - n * glm::dot(u, n), vp = v - n * glm::dot(v, n);
  const float c = glm::dot(up, vp), s = glm::dot(n, glm::cross(up, vp));
  const float length2 = c * c + s * s;  // |up|² |vp|²
  if (!(length2 > 0.0f)) return {};
  const float inv = inverse_sqrt(length2);
  return {c * inv, s * inv};
}

// The shortest rotation taking the direction of u (length `length`) onto unit v: the half-way
// quaternion (|u| + u·v, u × v), normalised; half a turn about an axis perpendicular to u when
// they are opposite.
quat from_to(const vec3& u, float length, const vec3& v) {
  const float c = glm::dot(u, v);
  if (c >= (1.0f - 1e-6f) * length) return quat(1.0f, 0.0f, 0.0f, 0.0f);
  if (c < (-1.0f + 1e-6f) * length) {
    vec3 axis = glm::cross(vec3(0.0f, 0.0f, 1.0f), u);
    if (glm::dot(axis, axis) < 1e-6f * length * length) axis = glm::cross(vec3(1.0f, 0.0f, 0.0f), u);
    axis = glm::normalize(axis);
    return quat(0.0f, axis.x, axis.y, axis.z);
  }
  const vec3 axis = glm::cross(u, v);
  return unit(quat(length + c, axis.x, axis.y, axis.z));
}

quat weighted(const quat& q, float weight) {
  return weight >= 1.0f ? q : glm::slerp(quat(1.0f, 0.0f, 0.0f, 0.0f), q, std::max(weight, 0.0f));
}

}  // namespace

TwoBoneResult solve_two_bone(const TwoBoneInput& in) {
  const float l1 = glm::length(in.mid - in.start), l2 = glm::length(in.end - in.mid);
  const vec3 to_target = in.target - in.start;
  const float d = glm::length(to_target);
  TwoBoneResult out;
  const float longest = l1 + l2, shortest = std::abs(l1 - l2);
  out.reached = d <= longest + 1e-6f && d >= shortest - 1e-6f;

  // Effective distance: clamped to the reachable annulus, softened near full extension.
  float reach = std::clamp(d, shortest, longest);
  const float soft_start = std::clamp(in.soften, 0.0f, 1.0f) * longest;
  if (in.soften < 1.0f && d > soft_start) {
    const float band = longest - soft_start;
    reach = soft_start + band * (1.0f - std::exp(-(d - soft_start) / band));
  }

  // Mid hinge: fold ψ = π − interior angle, positive about the hinge axis. The wanted interior angle
  // from the law of cosines, its sine from Heron's area (accurate for thin triangles too); the two
  // agree to rounding, so the pair needs no normalising.
  const vec3 hinge = in.mid_rotation * in.mid_axis;
  const vec3 n = hinge * inverse_sqrt(glm::dot(hinge, hinge));
  const float heron = std::max(0.0f, (l1 + l2 + reach) * (l2 - l1 + reach) * (l1 - l2 + reach) * (l1 + l2 - reach));
  const float inv_2l1l2 = 1.0f / (2.0f * l1 * l2);
  const Turn interior{(l1 * l1 + l2 * l2 - reach * reach) * inv_2l1l2, std::sqrt(heron) * inv_2l1l2};
  const Turn fold_wanted{-interior.c, interior.s};                          // π − interior
  const Turn bend_now = signed_turn(in.start - in.mid, in.end - in.mid, n);  // fold now = bend − π
  const Turn fold_now{-bend_now.c, -bend_now.s};
  const Turn fold = fold_wanted * reverse(fold_now);
  const quat mid_turn = weighted(axis_turn(n, fold), in.weight);
  // Where the end goes, by Rodrigues' formula on (cos, sin) straight away (the start's solve need not
  // wait for the quaternion); with a partial weight the quaternion itself turns it.
  const vec3 mid_end = in.end - in.mid;
  const vec3 end_after = in.weight >= 1.0f ? in.mid + mid_end * fold.c + glm::cross(n, mid_end) * fold.s +
                                                 n * (glm::dot(n, mid_end) * (1.0f - fold.c))
                                           : in.mid + mid_turn * mid_end;

  // Start: the rotation that takes the limb's frame onto the target's — the limb's direction onto the
  // start→target line, and the mid joint's side of the limb onto the pole's side of that line. (It is
  // the swing of the limb onto the line followed by the turn about the line toward the pole.)
  quat start_turn(1.0f, 0.0f, 0.0f, 0.0f);
  const vec3 limb = end_after - in.start;
  const float limb_length2 = glm::dot(limb, limb);
  if (d > 1e-6f && limb_length2 > 1e-12f) {
    const vec3 line = to_target * (1.0f / d);
    const vec3 a0 = limb * inverse_sqrt(limb_length2);
    const vec3 start_mid = in.mid - in.start, pole_dir = in.pole - in.start;
    const vec3 mid_side = start_mid - a0 * glm::dot(start_mid, a0);
    const vec3 pole_side = pole_dir - line * glm::dot(pole_dir, line);
    const float mid_side2 = glm::dot(mid_side, mid_side), pole_side2 = glm::dot(pole_side, pole_side);
    quat turn;
    if (mid_side2 > 1e-12f && pole_side2 > 1e-12f) {
      const vec3 a1 = mid_side * inverse_sqrt(mid_side2), b1 = pole_side * inverse_sqrt(pole_side2);
      const vec3 a2 = glm::cross(a0, a1), b2 = glm::cross(line, b1);
      // R = Σ b_i a_iᵀ, column by column.
      const mat3 r(line * a0.x + b1 * a1.x + b2 * a2.x, line * a0.y + b1 * a1.y + b2 * a2.y, line * a0.z + b1 * a1.z + b2 * a2.z);
      turn = glm::quat_cast(r);
    } else {
      turn = from_to(limb, limb_length2 * inverse_sqrt(limb_length2), line);  // no side to turn toward: the swing alone
    }
    if (in.twist != 0.0f) turn = axis_turn(line, Turn{std::cos(in.twist), std::sin(in.twist)}) * turn;  // only when asked for
    start_turn = weighted(unit(turn), in.weight);
  }

  // Rotations are unit by contract: their inverses are conjugates. mid_local = start_model⁻¹ ·
  // mid_model = in.start_rotation⁻¹ · mid_turn · in.mid_rotation (the start turn cancels).
  out.start_local = unit(glm::conjugate(in.start_parent_rotation) * (start_turn * in.start_rotation));
  out.mid_local = unit(glm::conjugate(in.start_rotation) * (mid_turn * in.mid_rotation));
  return out;
}

}  // namespace gestura
