// `gestura convert` between BVH and MPEG-4 BAP on the default avatar skeleton: a BVH → BAP → BVH
// round trip keeps every rotation to the BAP resolution (1e-5 rad per Euler angle).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/bap.hpp"
#include "gestura/io/bap_bvh.hpp"
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

// A T-posed upper body under one naming convention whose left forearm bends 90° forward over one
// second; the right arm stays still.
std::string bent_elbow_bvh(const std::string& file, const std::vector<std::string>& names) {
  // names: root, spine, neck, l_arm, l_forearm, l_hand, r_arm, r_forearm, r_hand
  Skeleton s;
  s.add_joint(names[0], -1, vec3(0.0f, 1.0f, 0.0f));
  s.add_joint(names[1], 0, vec3(0.0f, 0.25f, 0.0f));
  s.add_joint(names[2], 1, vec3(0.0f, 0.25f, 0.0f));
  s.add_joint(names[3], 1, vec3(0.18f, 0.2f, 0.0f));
  s.add_joint(names[4], 3, vec3(0.3f, 0.0f, 0.0f));
  s.add_joint(names[5], 4, vec3(0.25f, 0.0f, 0.0f));
  s.add_joint(names[6], 1, vec3(-0.18f, 0.2f, 0.0f));
  s.add_joint(names[7], 6, vec3(-0.3f, 0.0f, 0.0f));
  s.add_joint(names[8], 7, vec3(-0.25f, 0.0f, 0.0f));
  Clip clip;
  clip.resize_joints(s.size());
  clip.duration = 1.0f;
  for (int f = 0; f <= 30; ++f) {
    const float t = static_cast<float>(f) / 30.0f;
    clip.rotations[4].add(t, glm::angleAxis(0.5f * kPi * t, vec3(0.0f, 1.0f, 0.0f)));  // +X forearm turns to -Z... or +Z
  }
  save_bvh(file, make_bvh(s, clip, 1.0f / 30.0f));
  return file;
}

// The angle between upper arm and forearm of the avatar at the end of a BAP file's motion.
float avatar_elbow_angle(const std::string& bap_path, const char* side) {
  const BvhFile motion = bap_to_bvh(load_bap(bap_path));
  const Skeleton& s = motion.skeleton;
  Pose pose = rest_pose(s);
  sample_clip(motion.clip, motion.clip.duration, WrapMode::Clamp, rest_pose(s), pose);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const auto at = [&](const std::string& name) { return vec3(model[static_cast<std::size_t>(s.find(name))][3]); };
  const std::string p(side);
  const vec3 upper = at(p + "_elbow") - at(p + "_shoulder"), fore = at(p + "_wrist") - at(p + "_elbow");
  return std::acos(glm::dot(glm::normalize(upper), glm::normalize(fore)));
}

TEST(BapConvert, OtherJointNamesAreMappedToHanimByTheTables) {
  const std::vector<std::vector<std::string>> conventions{
      {"Hips", "Spine", "Neck", "LeftArm", "LeftForeArm", "LeftHand", "RightArm", "RightForeArm", "RightHand"},  // CMU
      {"hips", "spine", "neck", "leftUpperArm", "leftLowerArm", "leftHand", "rightUpperArm", "rightLowerArm", "rightHand"},  // VRM
      {"root", "spine03", "neck01", "upperarm01.L", "lowerarm01.L", "wrist.L", "upperarm01.R", "lowerarm01.R", "wrist.R"}};  // MakeHuman
  for (const auto& names : conventions) {
    const std::string bvh = bent_elbow_bvh(::testing::TempDir() + "names_" + names[3] + ".bvh", names);
    const std::string bap = ::testing::TempDir() + "names_" + names[3] + ".bap";
    const CliRun r = run_cli("convert '" + bvh + "' '" + bap + "'");
    ASSERT_EQ(r.status, 0) << names[3] << "\n" << r.output;
    EXPECT_NE(r.output.find("mapped to H-Anim"), std::string::npos) << r.output;
    // The forearm bent a right angle; the avatar's does too, the other arm keeps its rest bend.
    EXPECT_NEAR(to_degrees(avatar_elbow_angle(bap, "l")), 90.0, 8.0) << names[3];
    const float rest = avatar_elbow_angle(bap, "r");
    EXPECT_LT(to_degrees(rest), 30.0) << names[3];
    std::remove(bvh.c_str());
    std::remove(bap.c_str());
  }
}

TEST(BapConvert, MakeHumanBvhConvertsToBap) {
  const std::string out = ::testing::TempDir() + "standing01.bap";
  const CliRun r = run_cli("convert " + shared_data() + "/makehuman/poses/standing01.bvh " + out + " --scale 0.1 --z-up");
  ASSERT_EQ(r.status, 0) << r.output;
  const BapFile bap = load_bap(out);
  EXPECT_GT(bap.frame_count(), 0);
  EXPECT_NE(std::find_if(bap.values.begin(), bap.values.end(), [](std::int32_t v) { return v != 0; }), bap.values.end());
  std::remove(out.c_str());
}

TEST(BapConvert, BvhWithoutKnownJointNamesIsAClearError) {
  const std::string bvh = bent_elbow_bvh(::testing::TempDir() + "unknown_names.bvh",
                                         {"a", "b", "c", "d", "e", "f", "g", "h", "i"});
  const CliRun r = run_cli("convert '" + bvh + "' " + ::testing::TempDir() + "unknown_names.bap");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("H-Anim"), std::string::npos) << r.output;
  std::remove(bvh.c_str());
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
