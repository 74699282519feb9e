// The `gestura reach` command end to end on the default avatar: solves, reports, writes a BVH, and
// rejects bad flags.
#include <gtest/gtest.h>

#include "support/cli.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/skeleton/rotation_order.hpp"

namespace {

using gestura::test::CliRun;
using gestura::test::run_cli;

double residual_of(const std::string& output) {
  const auto at = output.find("residual ");
  return at == std::string::npos ? -1.0 : std::stod(output.substr(at + 9));
}

std::string point_arg(const gestura::vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "%.6f,%.6f,%.6f", p.x, p.y, p.z);
  return text;
}

// A reachable target: where the avatar's middle knuckle is in a posture inside the limits (upper arm
// 40° forward and 25° out, elbow bent 60°, forearm turned 20°).
gestura::vec3 reachable_target(const gestura::Skeleton& avatar, const std::string& side) {
  using namespace gestura;
  const float mirror = side == "l" ? 1.0f : -1.0f;
  Pose pose = rest_pose(avatar);
  const int shoulder = avatar.find(side + "_shoulder"), elbow = avatar.find(side + "_elbow");
  pose.rotations[shoulder] = euler_to_quat(vec3(deg(-40.0f), 0.0f, mirror * deg(25.0f)), avatar.dofs[shoulder].order);
  pose.rotations[elbow] = euler_to_quat(vec3(deg(-60.0f), mirror * deg(20.0f), 0.0f), avatar.dofs[elbow].order);
  EXPECT_TRUE(within_limits(avatar, shoulder, pose.rotations[shoulder]));
  EXPECT_TRUE(within_limits(avatar, elbow, pose.rotations[elbow]));
  std::vector<mat4> model(avatar.size());
  local_to_model(avatar, pose, model);
  return vec3(model[avatar.find(side + "_middle1")][3]);
}

TEST(IkReachCli, EachSolverReachesAPointOnTheAvatar) {
  const gestura::Skeleton avatar = gestura::build_avatar_skeleton();
  for (const char* side : {"l", "r"}) {
    const std::string target = point_arg(reachable_target(avatar, side));
    for (const char* solver : {"dls", "ccd", "combined"}) {
      const CliRun r = run_cli("reach --arm " + std::string(side) + " --target " + target + " --solver " + solver);
      ASSERT_EQ(r.status, 0) << r.output;
      const double residual = residual_of(r.output);
      EXPECT_GE(residual, 0.0) << r.output;
      EXPECT_LT(residual, 1e-4) << side << " " << solver << "\n" << r.output;
      EXPECT_NE(r.output.find("iterations"), std::string::npos);
    }
    // Two-bone aims the wrist only: the hand lands near the target, not on it.
    const CliRun r = run_cli("reach --arm " + std::string(side) + " --target " + target + " --solver two-bone");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_LT(residual_of(r.output), 0.05) << side << "\n" << r.output;
  }
}

// The written motion starts in the ready posture, ends on the target within 0.1 mm, and every
// frame keeps every joint inside its limits.
TEST(IkReachCli, WritesAMinimumJerkReachWithinLimits) {
  using namespace gestura;
  const Skeleton avatar = build_avatar_skeleton();
  const vec3 target = reachable_target(avatar, "r");
  const std::string path = ::testing::TempDir() + "reach_test.bvh";
  const CliRun r = run_cli("reach --arm r --target " + point_arg(target) + " --frames 10 -o " + path);
  ASSERT_EQ(r.status, 0) << r.output;
  const BvhFile bvh = load_bvh(path);
  ASSERT_EQ(bvh.frame_count, 11);
  const Skeleton& s = bvh.skeleton;
  std::vector<mat4> model(s.size());
  const Pose rest = rest_pose(s);
  Pose pose = rest;
  const int knuckle = s.find("r_middle1"), elbow = s.find("r_elbow");
  std::vector<float> elbow_angle;
  for (int f = 0; f <= 10; ++f) {
    sample_clip(bvh.clip, static_cast<float>(f) * bvh.frame_time, WrapMode::Clamp, rest, pose);
    for (std::size_t j = 0; j < s.size(); ++j) {
      const int a = avatar.find(s.names[j]);
      ASSERT_GE(a, 0) << s.names[j];
      EXPECT_TRUE(within_limits(avatar, a, pose.rotations[j])) << s.names[j] << " frame " << f;
    }
    elbow_angle.push_back(glm::angle(pose.rotations[elbow]));
  }
  local_to_model(s, pose, model);
  EXPECT_LT(glm::length(vec3(model[knuckle][3]) - target), 1e-4f);
  // Minimum jerk: slow start and end, fastest in the middle.
  EXPECT_LT(std::abs(elbow_angle[1] - elbow_angle[0]), std::abs(elbow_angle[6] - elbow_angle[5]));
  EXPECT_LT(std::abs(elbow_angle[10] - elbow_angle[9]), std::abs(elbow_angle[6] - elbow_angle[5]));
}

TEST(IkReachCli, UnreachableTargetReportsClosestReach) {
  const CliRun r = run_cli("reach --target 3,1,1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_GT(residual_of(r.output), 2.0) << r.output;
  EXPECT_NE(r.output.find("closest reach"), std::string::npos);
}

TEST(IkReachCli, BadFlagsAreClearErrors) {
  for (const char* args : {"reach", "reach --target 1,2", "reach --target a,b,c", "reach --target 0,1,0 --solver fabrik",
                           "reach --target 0,1,0 --frames -3", "reach --target 0,1,0 --bogus",
                           "reach --target 0,1,0 --arm x"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << ": a usage error";
    EXPECT_NE(r.output.find("gestura reach: "), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
