// `gestura convert` between BVH and MPEG-4 BAP on the default avatar skeleton: a BVH → BAP → BVH
// round trip keeps every rotation to the BAP resolution (1e-5 rad per Euler angle).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/bap.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/skeleton/rotation_order.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace gestura {
namespace {

using test::CliRun;
using test::run_cli;

using gestura::test::shared_data;

// One second at 30 Hz: the root walks and turns, the spine, head and both arms move about every
// free axis, each angle a sine inside the middle half of its range.
Clip avatar_clip(const Skeleton& avatar) {
  Clip clip;
  clip.name = "bap_round_trip";
  clip.resize_joints(avatar.size());
  clip.duration = 1.0f;
  const char* moving[] = {"humanoid_root", "vl5", "vt6", "skullbase", "l_sternoclavicular", "l_shoulder", "l_elbow",
                          "r_shoulder", "r_elbow"};
  for (const char* name : moving) {
    const int j = avatar.find(name);
    EXPECT_GE(j, 0) << name;
    const JointDofs& d = avatar.dofs[static_cast<std::size_t>(j)];
    for (int f = 0; f <= 30; ++f) {
      const float t = static_cast<float>(f) / 30.0f;
      vec3 angles(0.0f);
      for (int axis = 0; axis < 3; ++axis) {
        if (!d.free(axis)) continue;
        const float mid = 0.5f * (d.min_angle[axis] + d.max_angle[axis]), half = 0.25f * (d.max_angle[axis] - d.min_angle[axis]);
        angles[axis] = mid + half * std::sin(6.0f * t + static_cast<float>(j + axis));
      }
      if (std::string(name) == "humanoid_root") angles = vec3(0.1f * std::sin(3.0f * t), 0.5f * t, 0.0f);
      clip.rotations[static_cast<std::size_t>(j)].add(t, euler_to_quat(angles, d.order));
    }
  }
  for (int f = 0; f <= 30; ++f) {
    const float t = static_cast<float>(f) / 30.0f;
    clip.translations[0].add(t, avatar.rest_translations[0] + vec3(0.2f * t, 0.01f * std::sin(9.0f * t), 0.3f * t));
  }
  return clip;
}

TEST(BapConvert, BvhToBapToBvhKeepsTheMotion) {
  const Skeleton avatar = build_avatar_skeleton();
  const std::string bvh = ::testing::TempDir() + "bap_in.bvh", bap = ::testing::TempDir() + "bap_mid.bap",
                    back = ::testing::TempDir() + "bap_back.bvh";
  save_bvh(bvh, make_bvh(avatar, avatar_clip(avatar), 1.0f / 30.0f));
  const CliRun to_bap = run_cli("convert " + bvh + " " + bap);
  ASSERT_EQ(to_bap.status, 0) << to_bap.output;
  EXPECT_EQ(load_bap(bap).frame_count(), 31);
  const CliRun to_bvh = run_cli("convert " + bap + " " + back);
  ASSERT_EQ(to_bvh.status, 0) << to_bvh.output;

  const BvhFile a = load_bvh(bvh), b = load_bvh(back);
  ASSERT_EQ(b.frame_count, 31);
  const Pose rest_a = rest_pose(a.skeleton), rest_b = rest_pose(b.skeleton);
  Pose pa = rest_a, pb = rest_b;
  float worst_angle = 0.0f, worst_shift = 0.0f;
  for (int f = 0; f <= 30; ++f) {
    const float t = static_cast<float>(f) / 30.0f;
    sample_clip(a.clip, t, WrapMode::Clamp, rest_a, pa);
    sample_clip(b.clip, t, WrapMode::Clamp, rest_b, pb);
    for (std::size_t j = 0; j < a.skeleton.size(); ++j) {
      const int k = b.skeleton.find(a.skeleton.names[j]);
      ASSERT_GE(k, 0) << a.skeleton.names[j];
      // The angle of the difference rotation from its vector part (acos of a dot near 1 has no
      // precision in float).
      const quat diff = glm::conjugate(pa.rotations[j]) * pb.rotations[static_cast<std::size_t>(k)];
      worst_angle = std::max(worst_angle, 2.0f * std::asin(std::min(1.0f, glm::length(vec3(diff.x, diff.y, diff.z)))));
    }
    worst_shift = std::max(worst_shift, glm::length(pa.translations[0] - pb.translations[0]));
  }
  // Three angles each rounded to 1e-5 rad move a rotation by at most 1.5e-5 rad; float
  // Euler ↔ quaternion conversions on the way add a few 1e-6 (measured, not derived).
  EXPECT_LT(worst_angle, 4e-5f);
  EXPECT_LT(worst_shift, 1e-5f);
  EXPECT_GT(worst_angle, 0.0f);  // the BAP really was quantised: not a copy of the BVH
}

TEST(BapConvert, BvhWithoutHanimJointsIsAClearError) {
  const std::string out = ::testing::TempDir() + "tpose.bap";
  const CliRun r = run_cli("convert " + shared_data() + "/makehuman/poses/tpose.bvh " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("H-Anim"), std::string::npos) << r.output;
}

TEST(BapConvert, MalformedBapNamesTheLine) {
  const std::string bad = ::testing::TempDir() + "bad.bap", out = ::testing::TempDir() + "bad_out.bvh";
  {
    std::FILE* f = std::fopen(bad.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("2.1 broken 30 1\n0 1 0\n", f);
    std::fclose(f);
  }
  const CliRun r = run_cli("convert " + bad + " " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find(bad + ":2:"), std::string::npos) << r.output;
  std::remove(bad.c_str());
}

}  // namespace
}  // namespace gestura
