#include "gestura/ik/two_bone.hpp"

#include <algorithm>

namespace gestura {
namespace {

// Signed angle from u to v about the unit axis n, both taken in the plane perpendicular to n.
float signed_angle(const vec3& u, const vec3& v, const vec3& n) {
  const vec3 up = u - n * glm::dot(u, n), vp = v - n * glm::dot(v, n);
  return std::atan2(glm::dot(n, glm::cross(up, vp)), glm::dot(up, vp));
}

float wrap_pi(float a) {
  while (a > kPi) a -= 2.0f * kPi;
  while (a <= -kPi) a += 2.0f * kPi;
  return a;
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

  // Mid hinge: fold angle ψ = π − interior angle, positive about the hinge axis.
  const vec3 n = glm::normalize(in.mid_rotation * in.mid_axis);
  const float cos_interior = std::clamp((l1 * l1 + l2 * l2 - reach * reach) / (2.0f * l1 * l2), -1.0f, 1.0f);
  const float fold_wanted = kPi - std::acos(cos_interior);
  const float fold_now = wrap_pi(signed_angle(in.start - in.mid, in.end - in.mid, n) - kPi);
  const quat mid_turn = weighted(glm::angleAxis(fold_wanted - fold_now, n), in.weight);
  const vec3 end_after = in.mid + mid_turn * (in.end - in.mid);

  // Start: swing the limb onto the target line, then turn about that line toward the pole.
  quat start_turn(1.0f, 0.0f, 0.0f, 0.0f);
  const vec3 limb = end_after - in.start;
  if (d > 1e-6f && glm::length(limb) > 1e-6f) {
    const vec3 line = to_target / d;
    const quat swing = glm::rotation(glm::normalize(limb), line);
    const vec3 mid_dir = swing * (in.mid - in.start), pole_dir = in.pole - in.start;
    const vec3 mid_perp = mid_dir - line * glm::dot(mid_dir, line);
    const vec3 pole_perp = pole_dir - line * glm::dot(pole_dir, line);
    float turn = in.twist;
    if (glm::length(mid_perp) > 1e-6f && glm::length(pole_perp) > 1e-6f) turn += signed_angle(mid_perp, pole_perp, line);
    start_turn = weighted(glm::angleAxis(turn, line) * swing, in.weight);
  }

  const quat start_model = glm::normalize(start_turn * in.start_rotation);
  const quat mid_model = glm::normalize(start_turn * mid_turn * in.mid_rotation);
  out.start_local = glm::normalize(glm::inverse(in.start_parent_rotation) * start_model);
  out.mid_local = glm::normalize(glm::inverse(start_model) * mid_model);
  return out;
}

}  // namespace gestura
