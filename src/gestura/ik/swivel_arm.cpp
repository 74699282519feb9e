#include "gestura/ik/swivel_arm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

// Weights of the swivel choice, in radians of range excess they are worth.
constexpr float kPositionExcessWeight = 4.0f;  // a clamped shoulder or elbow moves the hand
constexpr float kUnnaturalWeight = 0.8f;       // per (1 − cos) away from the natural swivel
constexpr float kContinuityWeight = 0.6f;      // per radian away from last frame's swivel
constexpr float kStraightMargin = deg(3.0f);   // the elbow never locks fully straight (the swivel
                                               // circle would vanish and with it the arm's roll)
constexpr int kSearchPasses = 1;               // flexion ↔ twist agreement (see the header): one
constexpr int kFinalPasses = 3;                // pass ranks swivel angles, three make the answer exact

float wrap_pi(float a) {
  while (a > kPi) a -= 2.0f * kPi;
  while (a <= -kPi) a += 2.0f * kPi;
  return a;
}

float excess(float a, float lo, float hi) { return std::max({0.0f, lo - a, a - hi}); }

vec3 unit_axis(int axis) {
  vec3 v(0.0f);
  v[axis] = 1.0f;
  return v;
}

// The free axes of a joint, outermost first.
std::vector<int> free_axes(const JointDofs& d) {
  std::vector<int> out;
  for (int a : axes_of(d.order))
    if (d.free(a)) out.push_back(a);
  return out;
}

quat frame_rotation(const vec3& x, const vec3& y) {
  const vec3 z = glm::cross(x, y);
  return glm::quat_cast(mat3(x, y, z));
}

// Orthonormal (x, y) from two non-parallel vectors, x along a.
bool orthonormal_pair(const vec3& a, const vec3& b, vec3& x, vec3& y) {
  x = glm::normalize(a);
  const vec3 p = b - x * glm::dot(x, b);
  const float len = glm::length(p);
  if (len < 1e-6f) return false;
  y = p / len;
  return true;
}

}  // namespace

SwivelArm make_swivel_arm(const Skeleton& skeleton, int shoulder, int elbow, int wrist) {
  const int n = static_cast<int>(skeleton.size());
  if (shoulder < 0 || elbow < 0 || wrist < 0 || shoulder >= n || elbow >= n || wrist >= n)
    throw Error("swivel arm: joint index out of range");
  // Rest transform of `to` in the frame of its ancestor `from`, across joints that cannot move.
  auto rest_between = [&](int from, int to, vec3& offset, quat& rotation, bool allow_rest_rotation) {
    offset = vec3(0.0f);
    rotation = quat(1, 0, 0, 0);
    for (int j = to; j != from; j = skeleton.parents[j]) {
      if (j < 0)
        throw Error("swivel arm: '" + skeleton.names[to] + "' does not descend from '" + skeleton.names[from] + "'");
      if (j != to && skeleton.dofs[j].axes)
        throw Error("swivel arm: '" + skeleton.names[j] + "' between '" + skeleton.names[from] + "' and '" +
                    skeleton.names[to] + "' can move");
      if (!allow_rest_rotation && std::abs(skeleton.rest_rotations[j].w) < 1.0f - 1e-5f)
        throw Error("swivel arm: '" + skeleton.names[j] + "' has a rest rotation");
      offset = skeleton.rest_translations[j] + skeleton.rest_rotations[j] * offset;
      rotation = skeleton.rest_rotations[j] * rotation;
    }
  };
  const std::vector<int> e = free_axes(skeleton.dofs[elbow]);
  const std::vector<int> w = free_axes(skeleton.dofs[wrist]);
  if (e.size() != 2) throw Error("swivel arm: '" + skeleton.names[elbow] + "' needs two free axes (flexion, then twist)");
  if (w.size() != 2) throw Error("swivel arm: '" + skeleton.names[wrist] + "' needs two free axes");
  SwivelArm arm;
  arm.shoulder = shoulder, arm.elbow = elbow, arm.wrist = wrist;
  rest_between(shoulder, elbow, arm.upper, arm.elbow_rest, true);
  quat none;
  rest_between(elbow, wrist, arm.fore, none, false);
  arm.hinge_axis = e[0], arm.twist_axis = e[1];
  const std::array<int, 3> hand{e[1], w[0], w[1]};
  bool found = false;
  for (RotationOrder o : kAllRotationOrders)
    if (axes_of(o) == hand) arm.hand_order = o, found = true;
  if (!found)
    throw Error("swivel arm: the twist of '" + skeleton.names[elbow] + "' and the axes of '" + skeleton.names[wrist] +
                "' must be three different axes");
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  arm.outward = model[static_cast<std::size_t>(elbow)][3].x >= 0.0f ? 1.0f : -1.0f;
  return arm;
}

namespace {

// The swivel circle's reference directions about the unit shoulder–wrist line n: e1 the elbow
// straight below the line (behind it when the line is vertical), e2 = n × e1.
std::pair<vec3, vec3> swivel_basis(const vec3& n) {
  vec3 e1 = vec3(0, -1, 0) - n * (-n.y);
  if (glm::length(e1) < 1e-3f) e1 = vec3(0, 0, -1) - n * (-n.z);
  e1 = glm::normalize(e1);
  return {e1, glm::cross(n, e1)};
}

SwivelSolution solve_at(const Skeleton& skeleton, const SwivelArm& arm, const vec3& shoulder_position,
                        const quat& shoulder_parent, const SwivelGoal& goal, float swivel,
                        const SwivelPreference& preference, int passes) {
  const JointDofs& ed = skeleton.dofs[arm.elbow];
  const JointDofs& wd = skeleton.dofs[arm.wrist];
  const JointDofs& sd = skeleton.dofs[arm.shoulder];
  const vec3 u = arm.upper, f = arm.fore;
  const quat re = arm.elbow_rest;
  const vec3 h = unit_axis(arm.hinge_axis), t = unit_axis(arm.twist_axis);
  const vec3 a = glm::inverse(re) * u;
  const float h_lo = ed.min_angle[arm.hinge_axis], h_hi = ed.max_angle[arm.hinge_axis];
  const float t_lo = ed.min_angle[arm.twist_axis], t_hi = ed.max_angle[arm.twist_axis];

  const vec3 to_wrist = goal.wrist_position - shoulder_position;
  const float d = std::max(glm::length(to_wrist), 1e-4f);
  const vec3 n = to_wrist / d;
  const auto [e1, e2] = swivel_basis(n);
  const vec3 elbow_dir = std::cos(swivel) * e1 + arm.outward * std::sin(swivel) * e2;

  SwivelSolution out;
  out.swivel = swivel;
  float tau = std::clamp(0.0f, t_lo, t_hi), theta = 0.0f;
  quat qs(1, 0, 0, 0);
  vec3 hand_angles(0.0f);
  for (int pass = 0; pass < passes; ++pass) {
    // Flexion: |u + re·H(θ)·g| = d with g the twisted forearm.
    const vec3 g = glm::angleAxis(tau, t) * f;
    const vec3 g_par = h * glm::dot(h, g), g_perp = g - g_par;
    const float A = glm::dot(a, g_perp), B = glm::dot(a, glm::cross(h, g_perp));
    const float K = 0.5f * (d * d - glm::dot(u, u) - glm::dot(g, g)) - glm::dot(a, g_par);
    const float R = std::max(std::sqrt(A * A + B * B), 1e-9f);
    const float straight = std::atan2(B, A);  // the flexion that stretches the arm most
    const float spread = std::acos(std::clamp(K / R, -1.0f, 1.0f));
    const float c1 = wrap_pi(straight + spread), c2 = wrap_pi(straight - spread);
    theta = excess(c1, h_lo, h_hi) <= excess(c2, h_lo, h_hi) ? c1 : c2;
    const float theta_wanted = theta;
    theta = std::clamp(theta, h_lo, h_hi);
    if (std::abs(wrap_pi(theta - straight)) < kStraightMargin) {
      const float toward = wrap_pi(0.5f * (h_lo + h_hi) - straight) >= 0.0f ? 1.0f : -1.0f;
      theta = std::clamp(straight + toward * kStraightMargin, h_lo, h_hi);
    }
    out.position_excess = std::abs(theta_wanted - theta) > kStraightMargin + 1e-4f ? std::abs(theta_wanted - theta) : 0.0f;
    const quat flexed = re * glm::angleAxis(theta, h);
    const vec3 v = u + flexed * g;  // the wrist in the shoulder's frame

    // Shoulder: u onto the elbow's place on the swivel circle, v onto the shoulder–wrist line.
    const float lu = glm::length(u), lv = glm::length(v);
    const float cos_g = std::clamp(glm::dot(u, v) / std::max(lu * lv, 1e-9f), -1.0f, 1.0f);
    const vec3 elbow = n * (lu * cos_g) + elbow_dir * (lu * std::sqrt(std::max(0.0f, 1.0f - cos_g * cos_g)));
    vec3 xl, yl, xt, yt;
    if (orthonormal_pair(u, v, xl, yl) && orthonormal_pair(elbow, n, xt, yt))
      qs = glm::normalize(frame_rotation(xt, yt) * glm::inverse(frame_rotation(xl, yl)));
    else
      qs = glm::rotation(glm::normalize(v), n);

    // Forearm twist and wrist: what is left of the hand rotation after shoulder and flexion.
    const quat rest_hand = glm::inverse(qs * flexed) * goal.wrist_rotation;
    // The decomposition with the middle (wrist) angle within ±90° is the one the wrist can take.
    hand_angles = quat_to_euler(rest_hand, arm.hand_order);
    tau = std::clamp(hand_angles[arm.twist_axis], t_lo, t_hi);
  }

  // Shoulder angles; a clamped shoulder moves the elbow and the hand with it.
  const quat ls = glm::inverse(shoulder_parent) * qs;
  const vec3 sa = joint_angles(skeleton, arm.shoulder, ls);
  out.shoulder = sa;
  for (int k = 0; k < 3; ++k) {
    if (!sd.free(k)) { out.shoulder[k] = 0.0f; continue; }
    out.shoulder[k] = std::clamp(sa[k], sd.min_angle[k], sd.max_angle[k]);
    out.position_excess += std::abs(sa[k] - out.shoulder[k]);
  }
  out.elbow = vec3(0.0f);
  out.elbow[arm.hinge_axis] = theta;
  out.elbow[arm.twist_axis] = tau;
  out.orientation_excess = excess(hand_angles[arm.twist_axis], t_lo, t_hi);
  out.wrist = vec3(0.0f);
  for (int k = 0; k < 3; ++k) {
    if (k == arm.twist_axis) continue;
    out.wrist[k] = std::clamp(hand_angles[k], wd.min_angle[k], wd.max_angle[k]);
    out.orientation_excess += std::abs(hand_angles[k] - out.wrist[k]);
  }

  out.cost = kPositionExcessWeight * out.position_excess + out.orientation_excess +
             kUnnaturalWeight * (1.0f - std::cos(swivel - preference.natural));
  if (preference.previous) out.cost += kContinuityWeight * std::abs(wrap_pi(swivel - *preference.previous));
  return out;
}

}  // namespace

SwivelSolution solve_swivel_arm_at(const Skeleton& skeleton, const SwivelArm& arm, const vec3& shoulder_position,
                                   const quat& shoulder_parent, const SwivelGoal& goal, float swivel,
                                   const SwivelPreference& preference) {
  return solve_at(skeleton, arm, shoulder_position, shoulder_parent, goal, wrap_pi(swivel), preference, kFinalPasses);
}

SwivelSolution solve_swivel_arm(const Skeleton& skeleton, const SwivelArm& arm, const vec3& shoulder_position,
                                const quat& shoulder_parent, const SwivelGoal& goal, const SwivelPreference& preference) {
  auto at = [&](float phi) {
    return solve_at(skeleton, arm, shoulder_position, shoulder_parent, goal, wrap_pi(phi), preference, kSearchPasses);
  };
  // Refines around a start by halving steps (the cost is smooth in φ between range boundaries).
  auto refine = [&](SwivelSolution best, float step) {
    for (; step > deg(1.0f); step *= 0.5f) {
      for (float s : {-step, step}) {
        const SwivelSolution c = at(best.swivel + s);
        if (c.cost < best.cost) best = c;
      }
    }
    return best;
  };
  // Continuing from the last frame: a local search keeps the arm on its solution; only when that
  // solution has to clamp a joint is the whole circle searched for a better one.
  constexpr float kSettled = deg(2.0f);
  auto exact = [&](const SwivelSolution& best) {
    return solve_at(skeleton, arm, shoulder_position, shoulder_parent, goal, best.swivel, preference, kFinalPasses);
  };
  if (preference.previous) {
    const SwivelSolution local = refine(at(*preference.previous), deg(8.0f));
    if (local.position_excess + local.orientation_excess < kSettled || !preference.search_circle) return exact(local);
    SwivelSolution global = local;
    for (int k = 0; k < 12; ++k) {
      const SwivelSolution c = at(deg(30.0f) * static_cast<float>(k) - kPi);
      if (c.cost < global.cost) global = c;
    }
    return exact(global.swivel == local.swivel ? local : refine(global, deg(15.0f)));
  }
  SwivelSolution best = at(preference.natural);
  for (int k = 0; k < 24; ++k) {
    const SwivelSolution c = at(deg(15.0f) * static_cast<float>(k) - kPi);
    if (c.cost < best.cost) best = c;
  }
  return exact(refine(best, deg(7.5f)));
}

void apply_swivel_solution(const Skeleton& skeleton, const SwivelArm& arm, const SwivelSolution& solution, Pose& pose) {
  pose.rotations[static_cast<std::size_t>(arm.shoulder)] = joint_rotation(skeleton, arm.shoulder, solution.shoulder);
  pose.rotations[static_cast<std::size_t>(arm.elbow)] = joint_rotation(skeleton, arm.elbow, solution.elbow);
  pose.rotations[static_cast<std::size_t>(arm.wrist)] = joint_rotation(skeleton, arm.wrist, solution.wrist);
}

float measure_swivel(const SwivelArm& arm, const vec3& shoulder, const vec3& elbow, const vec3& wrist) {
  const vec3 n = glm::normalize(wrist - shoulder);
  const auto [e1, e2] = swivel_basis(n);
  const vec3 out = elbow - shoulder;
  return std::atan2(arm.outward * glm::dot(out, e2), glm::dot(out, e1));
}

}  // namespace gestura
