// solve_two_bone (square roots only, angles carried as cos/sin pairs) against the textbook solve with
// acos, atan2 and axis-angle quaternions, written out here: the same rotations on random limbs,
// targets inside and beyond reach, bent either way, with partial weights and twists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gestura/ik/two_bone.hpp"

namespace gestura {
namespace {

float signed_angle(const vec3& u, const vec3& v, const vec3& n) {
  const vec3 up = u - n * glm::dot(u, n), vp = v - n * glm::dot(v, n);
  return std::atan2(glm::dot(n, glm::cross(up, vp)), glm::dot(up, vp));
}

quat weighted(const quat& q, float weight) {
  return weight >= 1.0f ? q : glm::slerp(quat(1.0f, 0.0f, 0.0f, 0.0f), q, std::max(weight, 0.0f));
}

// two_bone.hpp's contract, solved with trigonometry.
TwoBoneResult reference(const TwoBoneInput& in) {
  const float l1 = glm::length(in.mid - in.start), l2 = glm::length(in.end - in.mid);
  const vec3 to_target = in.target - in.start;
  const float d = glm::length(to_target);
  const float longest = l1 + l2, shortest = std::abs(l1 - l2);
  float reach = std::clamp(d, shortest, longest);
  const float soft_start = std::clamp(in.soften, 0.0f, 1.0f) * longest;
  if (in.soften < 1.0f && d > soft_start) {
    const float band = longest - soft_start;
    reach = soft_start + band * (1.0f - std::exp(-(d - soft_start) / band));
  }
  const vec3 n = glm::normalize(in.mid_rotation * in.mid_axis);
  const float fold_wanted = kPi - std::acos(std::clamp((l1 * l1 + l2 * l2 - reach * reach) / (2.0f * l1 * l2), -1.0f, 1.0f));
  const float fold_now = signed_angle(in.start - in.mid, in.end - in.mid, n) - kPi;
  const quat mid_turn = weighted(glm::angleAxis(fold_wanted - fold_now, n), in.weight);
  const vec3 end_after = in.mid + mid_turn * (in.end - in.mid);
  quat start_turn(1, 0, 0, 0);
  const vec3 line = to_target / d;
  const quat swing = glm::rotation(glm::normalize(end_after - in.start), line);
  const vec3 mid_dir = swing * (in.mid - in.start), pole_dir = in.pole - in.start;
  const vec3 mid_perp = mid_dir - line * glm::dot(mid_dir, line), pole_perp = pole_dir - line * glm::dot(pole_dir, line);
  float turn = in.twist;
  if (glm::length(mid_perp) > 1e-6f && glm::length(pole_perp) > 1e-6f) turn += signed_angle(mid_perp, pole_perp, line);
  start_turn = weighted(glm::angleAxis(turn, line) * swing, in.weight);
  const quat start_model = glm::normalize(start_turn * in.start_rotation);
  const quat mid_model = glm::normalize(start_turn * mid_turn * in.mid_rotation);
  TwoBoneResult out;
  out.start_local = glm::normalize(glm::inverse(in.start_parent_rotation) * start_model);
  out.mid_local = glm::normalize(glm::inverse(start_model) * mid_model);
  return out;
}

quat random_rotation(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return glm::normalize(quat(g(rng), g(rng), g(rng), g(rng)));
}

}  // namespace

TEST(IkTwoBone, MatchesTheTrigonometricSolve) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), length(0.15f, 0.4f), angle(0.2f, 2.8f);
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    TwoBoneInput in;
    in.start_parent_rotation = random_rotation(rng);
    in.start_rotation = random_rotation(rng);
    in.mid_rotation = random_rotation(rng);
    // Bones along the joints' local −y, the hinge their local −x, bent by a random angle either way.
    const float l1 = length(rng), l2 = length(rng), bend = (trial % 2 ? 1.0f : -1.0f) * angle(rng);
    in.start = vec3(u(rng), 1.0f + u(rng), u(rng));
    in.mid = in.start + in.start_rotation * vec3(0, -l1, 0);
    in.mid_rotation = in.start_rotation * glm::angleAxis(bend, vec3(-1, 0, 0));
    in.end = in.mid + in.mid_rotation * vec3(0, -l2, 0);
    in.mid_axis = vec3(-1, 0, 0);
    const vec3 direction = glm::normalize(vec3(u(rng), u(rng), u(rng)));
    in.target = in.start + direction * (l1 + l2) * (0.2f + 1.1f * std::abs(u(rng)));  // some out of reach
    in.pole = in.start + vec3(u(rng), u(rng), u(rng));
    in.soften = trial % 3 == 0 ? 0.95f : 1.0f;
    in.weight = trial % 5 == 0 ? 0.5f : 1.0f;
    in.twist = trial % 7 == 0 ? 0.7f : 0.0f;
    // Stay away from the degenerate configurations, where rounding decides: a pole on the target line,
    // or a limb (nearly) straight or folded flat after the solve, which leaves no side for the mid
    // joint to turn to.
    const vec3 line = glm::normalize(in.target - in.start), pole_dir = in.pole - in.start;
    if (glm::length(pole_dir - line * glm::dot(pole_dir, line)) < 0.05f) continue;
    const float longest = l1 + l2, d = glm::length(in.target - in.start);
    if ((in.soften >= 1.0f && d > 0.995f * longest) || d < 1.005f * std::abs(l1 - l2)) continue;
    const TwoBoneResult a = solve_two_bone(in), b = reference(in);
    EXPECT_GT(std::abs(glm::dot(a.start_local, b.start_local)), 1.0f - 2e-6f) << "trial " << trial;
    EXPECT_GT(std::abs(glm::dot(a.mid_local, b.mid_local)), 1.0f - 2e-6f) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

}  // namespace gestura
