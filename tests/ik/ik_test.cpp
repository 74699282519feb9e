// IK solvers on the 7-DoF reference arm. Targets come from forward kinematics of poses drawn inside
// the limits, and every result is measured independently through local_to_model.
#include <gtest/gtest.h>

#include <glm/gtx/string_cast.hpp>

#include <cstdint>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/ik/aim.hpp"
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/ik/reference_arm.hpp"
#include "gestura/ik/two_bone.hpp"

namespace gestura {
namespace {

// Small deterministic generator (the standard distributions differ between libraries).
struct Lcg {
  std::uint64_t state;
  float uniform() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  }
};

struct ArmFixture : ::testing::Test {
  Skeleton arm = reference_arm_skeleton();
  IkChain chain = arm_chain(arm);
  IkWorkspace ws{chain};
  int shoulder = arm.find("l_shoulder"), elbow = arm.find("l_elbow"), wrist = arm.find("l_wrist"),
      site = arm.find("l_hand_site");

  std::vector<mat4> model(const Pose& pose) const {
    std::vector<mat4> m(arm.size());
    local_to_model(arm, pose, m);
    return m;
  }
  // A pose with every joint angle drawn inside its limits (kept away from the bounds by `margin`).
  Pose random_pose(Lcg& rng, float margin = 0.1f) const {
    Pose pose = rest_pose(arm);
    for (int j : {shoulder, elbow, wrist}) {
      vec3 a(0.0f);
      for (int axis = 0; axis < 3; ++axis)
        if (arm.dofs[j].free(axis)) {
          const float lo = arm.dofs[j].min_angle[axis], hi = arm.dofs[j].max_angle[axis];
          const float span = hi - lo;
          a[axis] = lo + span * (margin + (1.0f - 2.0f * margin) * rng.uniform());
        }
      pose.rotations[j] = joint_rotation(arm, j, a);
    }
    return pose;
  }
  void expect_within_limits(const Pose& pose) const {
    for (std::size_t j = 0; j < arm.size(); ++j) {
      EXPECT_TRUE(within_limits(arm, static_cast<int>(j), pose.rotations[j], deg(0.01f)))
          << arm.names[j] << " angles " << glm::to_string(joint_angles(arm, static_cast<int>(j), pose.rotations[j]));
      EXPECT_TRUE(is_finite(pose.rotations[j])) << arm.names[j];
    }
  }
};

using Solver = IkResult (*)(const Skeleton&, const IkChain&, const mat4&, const IkTarget&, const IkSettings&,
                            IkWorkspace&, Pose&);

void reaches_positions(ArmFixture& f, Solver solve) {
  Lcg rng{7};
  for (int trial = 0; trial < 40; ++trial) {
    const Pose goal = f.random_pose(rng);
    const vec3 target = vec3(f.model(goal)[f.site][3]);
    Pose pose = arm_ready_pose(f.arm);
    const IkResult r = solve(f.arm, f.chain, mat4(1.0f), IkTarget{target}, IkSettings{}, f.ws, pose);
    const float error = glm::length(vec3(f.model(pose)[f.site][3]) - target);
    EXPECT_LT(error, 1e-4f) << "trial " << trial << " iterations " << r.iterations;
    EXPECT_NEAR(r.position_error, error, 1e-5f);
    EXPECT_GT(r.iterations, 0);
    f.expect_within_limits(pose);
  }
}

TEST_F(ArmFixture, IkCcdReachesReachableTargetsWithinLimits) { reaches_positions(*this, solve_ccd); }
TEST_F(ArmFixture, IkDlsReachesReachableTargetsWithinLimits) { reaches_positions(*this, solve_dls); }
IkResult combined(const Skeleton& s, const IkChain& c, const mat4& b, const IkTarget& t, const IkSettings& st, IkWorkspace& ws,
                  Pose& p) {
  return solve_combined(s, c, b, t, st, ws, p);
}
TEST_F(ArmFixture, IkCombinedReachesReachableTargetsWithinLimits) { reaches_positions(*this, combined); }

void meets_orientations(ArmFixture& f, Solver solve, float position_tolerance, float angle_tolerance) {
  Lcg rng{11};
  IkSettings settings;
  settings.max_iterations = 400;
  int met = 0;
  const int trials = 30;
  for (int trial = 0; trial < trials; ++trial) {
    const Pose goal = f.random_pose(rng, 0.15f);
    const mat4 m = f.model(goal)[f.site];
    const IkTarget target{vec3(m[3]), glm::normalize(glm::quat_cast(mat3(m))), true};
    Pose pose = arm_ready_pose(f.arm);
    solve(f.arm, f.chain, mat4(1.0f), target, settings, f.ws, pose);
    const mat4 got = f.model(pose)[f.site];
    const float position_error = glm::length(vec3(got[3]) - target.position);
    const float angle_error = glm::length(rotation_error(glm::quat_cast(mat3(got)), target.orientation));
    if (position_error < position_tolerance && angle_error < angle_tolerance) ++met;
    f.expect_within_limits(pose);
  }
  // Starting from rest, a local solver may stall against a limit for a few goals; most must be met.
  EXPECT_GE(met, trials * 9 / 10);
}

TEST_F(ArmFixture, IkCcdMeetsOrientationTargets) { meets_orientations(*this, solve_ccd, 1e-3f, deg(1.0f)); }
TEST_F(ArmFixture, IkDlsMeetsOrientationTargets) { meets_orientations(*this, solve_dls, 1e-4f, deg(0.1f)); }
TEST_F(ArmFixture, IkCombinedMeetsOrientationTargets) { meets_orientations(*this, combined, 1e-4f, deg(0.1f)); }

void degrades_gracefully(ArmFixture& f, Solver solve) {
  const vec3 shoulder(0.18f, 1.40f, 0.0f);
  const float reach = 0.30f + 0.26f + 0.09f;
  for (const vec3 target : {vec3(2.0f, 1.4f, 0.5f), vec3(0.3f, 3.0f, 0.4f), vec3(0.5f, 1.2f, -1.5f)}) {
    Pose pose = arm_ready_pose(f.arm);
    const IkResult r = solve(f.arm, f.chain, mat4(1.0f), IkTarget{target}, IkSettings{}, f.ws, pose);
    const float error = glm::length(vec3(f.model(pose)[f.site][3]) - target);
    EXPECT_FALSE(r.converged);
    EXPECT_TRUE(std::isfinite(r.position_error));
    // The closest reach is the straight arm pointing at the target, if the limits allow that direction.
    EXPECT_LT(error, glm::length(target - shoulder) - reach + 0.02f) << target.x << "," << target.y << "," << target.z;
    f.expect_within_limits(pose);
  }
}

TEST_F(ArmFixture, IkCcdUnreachableTargetsGiveClosestReach) { degrades_gracefully(*this, solve_ccd); }
TEST_F(ArmFixture, IkDlsUnreachableTargetsGiveClosestReach) { degrades_gracefully(*this, solve_dls); }

TEST_F(ArmFixture, IkDlsNullSpaceMovesTowardPreferredPosture) {
  Lcg rng{3};
  const Pose goal = random_pose(rng);
  const vec3 target = vec3(model(goal)[site][3]);
  // Preferred: elbow tucked, shoulder twisted: a posture that the task alone would not choose.
  std::vector<float> preferred(chain.dof_count(), 0.0f);
  preferred[1] = deg(40.0f);
  auto distance_to_preferred = [&](const Pose& p) {
    IkWorkspace probe(chain);
    load_angles(arm, chain, p, probe);
    float d = 0.0f;
    for (std::size_t i = 0; i < chain.dof_count(); ++i) d += (probe.angles[i] - preferred[i]) * (probe.angles[i] - preferred[i]);
    return d;
  };
  IkSettings plain;
  Pose without = arm_ready_pose(arm);
  solve_dls(arm, chain, mat4(1.0f), IkTarget{target}, plain, ws, without);
  IkSettings guided;
  guided.preferred_angles = preferred;
  guided.null_space_gain = 0.5f;
  guided.max_iterations = 400;
  Pose with = arm_ready_pose(arm);
  const IkResult r = solve_dls(arm, chain, mat4(1.0f), IkTarget{target}, guided, ws, with);
  EXPECT_LT(glm::length(vec3(model(with)[site][3]) - target), 1e-4f) << r.iterations;
  EXPECT_LT(distance_to_preferred(with), distance_to_preferred(without));
}

TEST_F(ArmFixture, IkDlsRejectsPreferredAnglesOfWrongLength) {
  std::vector<float> preferred(3, 0.0f);
  IkSettings s;
  s.preferred_angles = preferred;
  Pose pose = rest_pose(arm);
  EXPECT_THROW(solve_dls(arm, chain, mat4(1.0f), IkTarget{vec3(0.3f, 1.0f, 0.2f)}, s, ws, pose), Error);
}

TEST_F(ArmFixture, IkSolversRejectAWorkspaceOfAnotherChain) {
  const IkChain shorter = make_chain(arm, shoulder, elbow);
  IkWorkspace other(shorter);
  Pose pose = arm_ready_pose(arm);
  EXPECT_THROW(solve_ccd(arm, chain, mat4(1.0f), IkTarget{vec3(0.3f, 1.0f, 0.2f)}, IkSettings{}, other, pose), Error);
  EXPECT_THROW(solve_dls(arm, chain, mat4(1.0f), IkTarget{vec3(0.3f, 1.0f, 0.2f)}, IkSettings{}, other, pose), Error);
}

TEST_F(ArmFixture, IkChainRejectsJointsNotOnOnePath) {
  Skeleton s = arm;
  s.add_joint("r_shoulder", 0, vec3(-0.18f, 1.4f, 0.0f));
  EXPECT_THROW(make_chain(s, s.find("r_shoulder"), s.find("l_wrist")), Error);
  EXPECT_THROW(make_chain(s, 0, 99), Error);
}

// Two-bone on the arm with its limits removed: the analytic solution must be exact.
TEST_F(ArmFixture, IkTwoBoneReachesTargetsAndBendsTowardPole) {
  Skeleton free_arm = arm;
  for (JointDofs& d : free_arm.dofs) d.axes = 0;
  Lcg rng{5};
  for (int trial = 0; trial < 30; ++trial) {
    const Pose goal = random_pose(rng);
    const vec3 target = vec3(model(goal)[wrist][3]);
    const vec3 pole(0.5f, 1.0f, -1.0f);  // elbow out and back, as a signer's elbow
    Pose pose = random_pose(rng);
    const LimbIkResult r = solve_limb(free_arm, pose, shoulder, elbow, wrist, vec3(-1, 0, 0), target, pole);
    const auto m = model(pose);
    const vec3 s(m[shoulder][3]), e(m[elbow][3]), w(m[wrist][3]);
    EXPECT_TRUE(r.reached);
    EXPECT_LT(glm::length(w - target), 1e-4f) << "trial " << trial;
    EXPECT_NEAR(r.position_error, glm::length(w - target), 1e-5f);
    // The elbow lies on the pole's side of the shoulder→target line.
    const vec3 line = glm::normalize(target - s);
    const vec3 elbow_off = (e - s) - line * glm::dot(e - s, line);
    const vec3 pole_off = (pole - s) - line * glm::dot(pole - s, line);
    if (glm::length(elbow_off) > 1e-3f) {
      EXPECT_GT(glm::dot(elbow_off, pole_off), 0.0f) << "trial " << trial;
    }
  }
}

TEST_F(ArmFixture, IkTwoBoneSofteningStopsShortOfFullExtension) {
  TwoBoneInput in;
  in.start = vec3(0.0f), in.mid = vec3(0, -0.3f, 0), in.end = vec3(0, -0.56f, 0.0f);
  in.start_rotation = in.mid_rotation = quat(1, 0, 0, 0);
  in.mid_axis = vec3(-1, 0, 0);
  in.pole = vec3(0, 0, -1);
  in.soften = 0.9f;
  float previous = 0.0f;
  for (float d : {0.45f, 0.52f, 0.56f, 0.60f, 1.0f}) {
    in.target = vec3(0.0f, 0.0f, d);
    const TwoBoneResult r = solve_two_bone(in);
    ASSERT_TRUE(is_finite(r.start_local) && is_finite(r.mid_local));
    const vec3 mid = r.start_local * vec3(0, -0.3f, 0);
    const vec3 end = mid + r.start_local * r.mid_local * vec3(0, -0.26f, 0);
    const float reach = glm::length(end);
    EXPECT_LT(reach, d < 0.7f ? 0.56f - 1e-3f : 0.56f) << d;  // never snaps straight
    EXPECT_GT(reach, previous) << d;               // but keeps following the target outward
    EXPECT_GT(glm::dot(glm::normalize(end), vec3(0, 0, 1)), 0.9999f) << d;  // on the target line
    if (d <= 0.5f) {
      EXPECT_NEAR(reach, d, 1e-4f);  // below the softening band: exact
    }
    previous = reach;
  }
}

TEST_F(ArmFixture, IkLimbStaysWithinLimits) {
  Lcg rng{9};
  for (int trial = 0; trial < 20; ++trial) {
    const vec3 target(0.2f + 0.8f * (rng.uniform() - 0.5f), 1.3f + 0.8f * (rng.uniform() - 0.5f), 0.8f * (rng.uniform() - 0.5f));
    Pose pose = rest_pose(arm);
    const LimbIkResult r = solve_limb(arm, pose, shoulder, elbow, wrist, vec3(-1, 0, 0), target, vec3(0.6f, 1.0f, -0.5f));
    expect_within_limits(pose);
    EXPECT_TRUE(std::isfinite(r.position_error));
  }
}

TEST(IkAim, PointsForwardAxisAtTargetAndKeepsUp) {
  Lcg rng{1};
  for (int trial = 0; trial < 50; ++trial) {
    AimInput in;
    in.position = vec3(rng.uniform(), 1.5f + rng.uniform(), rng.uniform());
    in.parent_rotation = glm::normalize(quat(1.0f, rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
    in.rotation = glm::normalize(quat(1.0f, rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
    in.forward = glm::normalize(vec3(0.2f, 0.1f, 1.0f));
    in.up = vec3(0, 1, 0);
    in.target = vec3(4.0f * rng.uniform() - 2.0f, 4.0f * rng.uniform() - 2.0f, 4.0f * rng.uniform() - 2.0f);
    const quat model = in.parent_rotation * aim_local_rotation(in);
    const vec3 dir = glm::normalize(in.target - in.position);
    EXPECT_GT(glm::dot(model * in.forward, dir), 1.0f - 1e-5f) << trial;
    // Up stays in the vertical plane through the aim line, on the upper side.
    const vec3 up_world = model * glm::normalize(in.up - in.forward * glm::dot(in.up, in.forward));
    EXPECT_NEAR(glm::dot(up_world, glm::normalize(glm::cross(dir, vec3(0, 1, 0)))), 0.0f, 1e-4f) << trial;
    EXPECT_GT(glm::dot(up_world, vec3(0, 1, 0)), 0.0f) << trial;
  }
}

TEST(IkAim, DegenerateTargetsKeepTheJointFinite) {
  AimInput in;
  in.position = vec3(0, 1, 0);
  in.rotation = glm::angleAxis(0.3f, vec3(0, 1, 0));
  in.target = in.position;  // on the joint: unchanged
  EXPECT_GT(std::abs(glm::dot(aim_local_rotation(in), in.rotation)), 1.0f - 1e-6f);
  in.target = vec3(0, 3, 0);  // straight up, along world_up
  const quat q = aim_local_rotation(in);
  EXPECT_TRUE(is_finite(q));
  EXPECT_GT(glm::dot(q * in.forward, vec3(0, 1, 0)), 1.0f - 1e-5f);
}

TEST(IkAim, ChainSharesTheTurnAndTheEndLooksAtTarget) {
  // neck → head → eye, all facing +Z; target up and to the left.
  std::vector<vec3> positions{vec3(0, 1.5f, 0), vec3(0, 1.62f, 0.02f), vec3(0.03f, 1.68f, 0.09f)};
  std::vector<quat> rotations(3, quat(1, 0, 0, 0));
  const std::vector<float> weights{0.3f, 0.5f, 1.0f};
  std::vector<quat> local(3);
  const vec3 target(1.0f, 2.0f, 1.5f);
  aim_chain(positions, rotations, quat(1, 0, 0, 0), weights, vec3(0, 0, 1), vec3(0, 1, 0), target, vec3(0, 1, 0), local);
  const quat neck = local[0], head = neck * local[1], eye = head * local[2];
  EXPECT_GT(glm::dot(eye * vec3(0, 0, 1), glm::normalize(target - positions[2])), 1.0f - 1e-5f);
  // The neck and head took part of the turn, but not all of it.
  const float neck_turn = glm::angle(neck), head_turn = glm::angle(local[1]);
  EXPECT_GT(neck_turn, deg(5.0f));
  EXPECT_GT(head_turn, deg(5.0f));
  EXPECT_LT(neck_turn, glm::angle(eye) - deg(5.0f));
}

}  // namespace
}  // namespace gestura

namespace gestura {
namespace {

// joint_angles picks, of the two Euler solutions of a rotation, the one inside the limits: with
// shoulder flexion spanning 249° the solution nearest the middle of the limits can lie outside.
TEST(IkLimits, WideLimitsRecogniseEitherEulerSolution) {
  const Skeleton arm = reference_arm_skeleton();
  const int shoulder = arm.find("l_shoulder");
  const vec3 angles(deg(58.0f), deg(-80.0f), deg(-45.0f));  // extended, twisted, adducted
  const quat q = joint_rotation(arm, shoulder, angles);
  EXPECT_TRUE(within_limits(arm, shoulder, q));
  const vec3 back = joint_angles(arm, shoulder, q);
  EXPECT_NEAR(back.x, angles.x, 1e-3f);
  EXPECT_NEAR(back.y, angles.y, 1e-3f);
  EXPECT_NEAR(back.z, angles.z, 1e-3f);
}

}  // namespace
}  // namespace gestura

namespace gestura {
namespace {

// The arm chain on a two-armed skeleton with fingers: right side, effector at a knuckle two joints
// below the wrist; DLS still reaches.
TEST(IkArmChain, WorksOnTheRightArmOfAFullSkeleton) {
  Skeleton s;
  s.add_joint("humanoid_root", -1, vec3(0.0f, 1.0f, 0.0f));
  for (const char* side : {"l", "r"}) {
    const float x = side[0] == 'l' ? 1.0f : -1.0f;
    const std::string p = std::string(side) + "_";
    const int shoulder = s.add_joint(p + "shoulder", 0, vec3(0.18f * x, 0.4f, 0.0f));
    const int elbow = s.add_joint(p + "elbow", shoulder, vec3(0.0f, -0.3f, 0.0f));
    const int wrist = s.add_joint(p + "wrist", elbow, vec3(0.0f, -0.26f, 0.0f));
    const int palm = s.add_joint(p + "middle0", wrist, vec3(0.0f, -0.04f, 0.0f));
    s.add_joint(p + "middle1", palm, vec3(0.0f, -0.05f, 0.01f));
    s.dofs[shoulder] = JointDofs{RotationOrder::ZXY, 0b111, vec3(deg(-188.0f), deg(-90.0f), deg(-134.0f)), vec3(deg(61.0f), deg(90.0f), deg(48.0f))};
    s.dofs[elbow] = JointDofs{RotationOrder::XYZ, 0b011, vec3(deg(-142.0f), deg(-113.0f), 0.0f), vec3(0.0f, deg(77.0f), 0.0f)};
    s.dofs[wrist] = JointDofs{RotationOrder::ZXY, 0b101, vec3(deg(-90.0f), 0.0f, deg(-27.0f)), vec3(deg(99.0f), 0.0f, deg(47.0f))};
  }
  const IkChain chain = arm_chain(s, "r");
  EXPECT_EQ(chain.joints.size(), 3u);
  EXPECT_EQ(chain.dof_count(), 3u + 2u + 2u);
  EXPECT_NEAR(glm::length(chain.effector_offset - vec3(0.0f, -0.09f, 0.01f)), 0.0f, 1e-6f);
  IkWorkspace ws(chain);
  Pose pose = arm_ready_pose(s, "r");
  const vec3 target(-0.25f, 1.1f, 0.3f);
  const int shoulder = s.find("r_shoulder");
  const IkResult r = solve_dls(s, chain, parent_model_matrix(s, pose, shoulder), IkTarget{target}, IkSettings{}, ws, pose);
  std::vector<mat4> m(s.size());
  local_to_model(s, pose, m);
  EXPECT_LT(glm::length(vec3(m[s.find("r_middle1")][3]) - target), 1e-4f) << r.iterations;
  EXPECT_THROW(arm_chain(s, "r", "l_middle1"), Error);
  EXPECT_THROW(arm_chain(s, "x"), Error);
}

}  // namespace
}  // namespace gestura

namespace gestura {
namespace {

TEST(IkTwoBone, WeightBlendsFromTheInputPoseAndTwistTurnsAboutTheTargetLine) {
  TwoBoneInput in;
  in.start = vec3(0.0f), in.mid = vec3(0, -0.3f, 0), in.end = vec3(0, -0.56f, 0);
  in.start_rotation = in.mid_rotation = quat(1, 0, 0, 0);
  in.mid_axis = vec3(-1, 0, 0);
  in.target = vec3(0.1f, -0.2f, 0.3f);
  in.pole = vec3(0.0f, 0.0f, -1.0f);
  in.weight = 0.0f;
  const TwoBoneResult none = solve_two_bone(in);
  EXPECT_GT(std::abs(glm::dot(none.start_local, quat(1, 0, 0, 0))), 1.0f - 1e-6f);
  EXPECT_GT(std::abs(glm::dot(none.mid_local, quat(1, 0, 0, 0))), 1.0f - 1e-6f);
  auto solved_mid = [&](float twist) {
    in.weight = 1.0f;
    in.twist = twist;
    const TwoBoneResult r = solve_two_bone(in);
    const vec3 mid = r.start_local * vec3(0, -0.3f, 0);
    const vec3 end = mid + r.start_local * r.mid_local * vec3(0, -0.26f, 0);
    EXPECT_LT(glm::length(end - in.target), 1e-4f) << twist;
    return mid;
  };
  const vec3 line = glm::normalize(in.target);
  const vec3 m0 = solved_mid(0.0f), m1 = solved_mid(kPi / 2.0f);
  // Twisting keeps the elbow on the same circle about the target line, a quarter turn further.
  EXPECT_NEAR(glm::dot(m0, line), glm::dot(m1, line), 1e-5f);
  const vec3 p0 = m0 - line * glm::dot(m0, line), p1 = m1 - line * glm::dot(m1, line);
  EXPECT_NEAR(glm::dot(glm::normalize(p0), glm::normalize(p1)), 0.0f, 1e-4f);
  EXPECT_GT(glm::dot(glm::cross(p0, p1), line), 0.0f);
}

}  // namespace
}  // namespace gestura
