// Binding a clip to another skeleton by joint names: rotations carried over, translations re-based
// on the target's rest offsets, joints without a namesake reported (only when they animate).
#include <gtest/gtest.h>

#include "gestura/anim/clip_by_name.hpp"

namespace gestura {
namespace {

// root → shoulder → elbow, with the given shoulder height.
Skeleton arm(float shoulder_height, const char* extra = nullptr) {
  Skeleton s;
  s.add_joint("humanoid_root", -1, vec3(0.0f, 0.9f * shoulder_height / 1.4f, 0.0f));
  const int shoulder = s.add_joint("l_shoulder", 0, vec3(0.18f, shoulder_height - 0.9f * shoulder_height / 1.4f, 0.0f));
  s.add_joint("l_elbow", shoulder, vec3(0.0f, -0.3f, 0.0f));
  if (extra) s.add_joint(extra, 0, vec3(0.0f, 0.1f, 0.0f));
  return s;
}

TEST(ClipByName, RotationsMoveOverAndTranslationsKeepTheTargetsProportions) {
  const Skeleton source = arm(1.40f), target = arm(1.55f);
  Clip clip;
  clip.duration = 1.0f;
  clip.resize_joints(source.size());
  const quat bend = glm::angleAxis(deg(60.0f), vec3(1.0f, 0.0f, 0.0f));
  clip.rotations[2].add(0.0f, quat(1.0f, 0.0f, 0.0f, 0.0f));
  clip.rotations[2].add(1.0f, bend);
  clip.translations[0].add(0.0f, source.rest_translations[0]);
  clip.translations[0].add(1.0f, source.rest_translations[0] + vec3(0.0f, 0.0f, 0.25f));  // steps forward
  clip.channel_names.push_back("aa");
  clip.channels.emplace_back().add(0.5f, 0.7f);

  const JointNameMatch match = match_joints_by_name(source, clip, target);
  EXPECT_TRUE(match.unmatched.empty());
  const Clip bound = clip_for_skeleton(source, clip, target, match);
  ASSERT_EQ(bound.joint_count(), target.size());
  EXPECT_EQ(bound.duration, 1.0f);
  ASSERT_EQ(bound.rotations[2].size(), 2u);
  EXPECT_EQ(bound.rotations[2].values[1], bend);
  ASSERT_EQ(bound.translations[0].size(), 2u);
  EXPECT_NEAR(glm::length(bound.translations[0].values[0] - target.rest_translations[0]), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(bound.translations[0].values[1] - (target.rest_translations[0] + vec3(0, 0, 0.25f))), 0.0f, 1e-6f);
  EXPECT_TRUE(bound.rotations[1].empty()) << "the shoulder was not animated: it stays at rest";
  ASSERT_EQ(bound.channel_names, clip.channel_names);
  EXPECT_EQ(bound.channels[0].values[0], 0.7f);
}

TEST(ClipByName, OnlyAnimatedJointsWithoutANamesakeAreUnmatched) {
  const Skeleton source = arm(1.40f, "Hips"), target = arm(1.40f);
  Clip clip;
  clip.duration = 1.0f;
  clip.resize_joints(source.size());
  EXPECT_TRUE(match_joints_by_name(source, clip, target).unmatched.empty()) << "an unanimated extra joint is harmless";
  clip.rotations[3].add(0.0f, quat(1.0f, 0.0f, 0.0f, 0.0f));
  const JointNameMatch match = match_joints_by_name(source, clip, target);
  ASSERT_EQ(match.unmatched, std::vector<std::string>{"Hips"});
  EXPECT_EQ(match.target_of[3], -1);
  EXPECT_EQ(match.target_of[1], target.find("l_shoulder"));
}

}  // namespace
}  // namespace gestura
