#include <gtest/gtest.h>

#include "gestura/body/avatar.hpp"
#include "gestura/core/error.hpp"
#include "gestura/ik/chain.hpp"
#include "gestura/ik/swivel_arm.hpp"

using namespace gestura;

namespace {

struct Arm {
  Avatar avatar = build_avatar();
  const Skeleton& s = avatar.skeleton;
  int shoulder = s.find("r_shoulder"), elbow = s.find("r_elbow"), wrist = s.find("r_wrist");
  SwivelArm arm = make_swivel_arm(s, shoulder, elbow, wrist);
};
const Arm& fx() {
  static const Arm a;
  return a;
}

struct Frame {
  vec3 position;
  quat rotation;
};
Frame wrist_frame(const Pose& pose) {
  std::vector<mat4> m(fx().s.size());
  local_to_model(fx().s, pose, m);
  const mat4& w = m[static_cast<std::size_t>(fx().wrist)];
  return {vec3(w[3]), glm::normalize(glm::quat_cast(mat3(w)))};
}

// Solves for the wrist frame of `pose` and writes the answer into a copy of it.
Pose solve(const Pose& pose, const Frame& goal, SwivelSolution* out = nullptr, SwivelPreference pref = {}) {
  const mat4 parent = parent_model_matrix(fx().s, pose, fx().shoulder);
  const vec3 at = vec3(parent * vec4(fx().s.rest_translations[static_cast<std::size_t>(fx().shoulder)], 1.0f));
  const SwivelSolution r = solve_swivel_arm(fx().s, fx().arm, at, glm::normalize(glm::quat_cast(mat3(parent))),
                                            SwivelGoal{goal.position, goal.rotation}, pref);
  Pose solved = pose;
  apply_swivel_solution(fx().s, fx().arm, r, solved);
  if (out) *out = r;
  return solved;
}

}  // namespace

// Poses made by hand inside the joint ranges: the solver finds a posture putting the wrist at the
// same place with the same turn (the elbow may swivel elsewhere), every angle within its limits.
TEST(IkSwivelArm, ReachesAnyWristFrameTheArmCanMake) {
  const Skeleton& s = fx().s;
  const vec3 shoulders[] = {{-30, 0, 20}, {-60, 20, 10}, {-80, -10, -5}, {-20, 30, 40}};  // degrees, mirrored limits
  const vec3 elbows[] = {{-60, -20, 0}, {-100, 30, 0}, {-40, -60, 0}, {-120, 0, 0}};
  const vec3 wrists[] = {{10, 0, 20}, {-20, 0, -40}, {0, 0, 60}, {15, 0, -70}};
  for (int k = 0; k < 4; ++k) {
    Pose pose = rest_pose(s);
    auto set = [&](int j, vec3 d) { pose.rotations[static_cast<std::size_t>(j)] = joint_rotation(s, j, vec3(deg(d.x), deg(d.y), deg(d.z))); };
    set(fx().shoulder, vec3(shoulders[k].x, -shoulders[k].y, -shoulders[k].z));  // right arm: y, z mirrored
    set(fx().elbow, vec3(elbows[k].x, -elbows[k].y, 0));
    set(fx().wrist, wrists[k]);
    clamp_to_limits(s, pose);  // the arm can make this wrist frame
    const Frame goal = wrist_frame(pose);
    SwivelSolution r;
    const Pose solved = solve(rest_pose(s), goal, &r);
    const Frame got = wrist_frame(solved);
    EXPECT_LT(glm::distance(got.position, goal.position), 0.003f) << k;
    EXPECT_LT(to_degrees(glm::length(rotation_error(got.rotation, goal.rotation))), 2.0f) << k;
    EXPECT_LT(r.position_excess + r.orientation_excess, deg(0.5f)) << k;
    for (int j : {fx().shoulder, fx().elbow, fx().wrist}) EXPECT_TRUE(within_limits(s, j, solved.rotations[static_cast<std::size_t>(j)])) << k;
  }
}

// A turn no wrist can make (the hand bent 150° back) leaves the wrist at its place, within its
// limits, turned as far as it goes — and the elbow stays below the shoulder, not flung up behind.
TEST(IkSwivelArm, AnImpossibleTurnStopsAtTheLimitsInsteadOfContortingTheArm) {
  const Skeleton& s = fx().s;
  Pose pose = rest_pose(s);
  pose.rotations[static_cast<std::size_t>(fx().shoulder)] = joint_rotation(s, fx().shoulder, vec3(deg(-40), 0, deg(-15)));
  pose.rotations[static_cast<std::size_t>(fx().elbow)] = joint_rotation(s, fx().elbow, vec3(deg(-80), 0, 0));
  const Frame reachable = wrist_frame(pose);
  Frame goal = reachable;
  goal.rotation = glm::normalize(reachable.rotation * glm::angleAxis(deg(150.0f), vec3(0, 0, 1)));
  SwivelSolution r;
  const Pose solved = solve(rest_pose(s), goal, &r);
  EXPECT_GT(r.orientation_excess, deg(20.0f));
  const Frame got = wrist_frame(solved);
  EXPECT_LT(glm::distance(got.position, goal.position), 0.01f);
  for (int j : {fx().shoulder, fx().elbow, fx().wrist}) EXPECT_TRUE(within_limits(s, j, solved.rotations[static_cast<std::size_t>(j)]));
  std::vector<mat4> m(s.size());
  local_to_model(s, solved, m);
  EXPECT_LT(m[static_cast<std::size_t>(fx().elbow)][3].y, m[static_cast<std::size_t>(fx().shoulder)][3].y);
}

TEST(IkSwivelArm, RejectsChainsItCannotSolve) {
  const Skeleton& s = fx().s;
  EXPECT_THROW(make_swivel_arm(s, fx().wrist, fx().elbow, fx().shoulder), Error);
  EXPECT_THROW(make_swivel_arm(s, fx().shoulder, s.find("r_thumb1"), fx().wrist), Error);
}

// measure_swivel reads back the swivel angle a solution placed the elbow at: what lets a solve
// continue from a given arm posture.
TEST(IkSwivelArm, MeasuredSwivelOfASolvedArmIsTheSolutionsSwivel) {
  const Skeleton& s = fx().s;
  const Pose rest = rest_pose(s);
  const mat4 parent = parent_model_matrix(s, rest, fx().shoulder);
  const vec3 at = vec3(parent * vec4(s.rest_translations[static_cast<std::size_t>(fx().shoulder)], 1.0f));
  const quat parent_rotation = glm::normalize(glm::quat_cast(mat3(parent)));
  // A wrist 35 cm in front of the chest, palm left: reachable with the elbow anywhere from low to out.
  const SwivelGoal goal{at + vec3(0.12f, -0.20f, 0.25f), glm::angleAxis(deg(90.0f), vec3(0, 0, 1))};
  for (float swivel : {deg(-10.0f), deg(20.0f), deg(50.0f)}) {
    const SwivelSolution r = solve_swivel_arm_at(s, fx().arm, at, parent_rotation, goal, swivel, SwivelPreference{});
    Pose pose = rest;
    apply_swivel_solution(s, fx().arm, r, pose);
    std::vector<mat4> m(s.size());
    local_to_model(s, pose, m);
    auto p = [&](int j) { return vec3(m[static_cast<std::size_t>(j)][3]); };
    EXPECT_NEAR(measure_swivel(fx().arm, p(fx().shoulder), p(fx().elbow), p(fx().wrist)), r.swivel, deg(2.0f))
        << "asked for " << swivel;
  }
}
