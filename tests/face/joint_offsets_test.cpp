#include "gestura/face/joint_offsets.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;
using namespace gestura::face;

namespace {

const Skeleton& skeleton() {
  static const Skeleton s = build_avatar_skeleton();
  return s;
}

vec3 angles_at(const Clip& clip, const char* joint, float t) {
  const int j = skeleton().find(joint);
  return joint_angles(skeleton(), j, sample_track(clip.rotations[static_cast<std::size_t>(j)], t));
}

// A clip that holds the left clavicle raised 5° from 0 to 3 s (two keys, as an IK pass would key it).
Clip held_clavicle() {
  Clip clip;
  clip.resize_joints(skeleton().size());
  const int j = skeleton().find("l_sternoclavicular");
  QuatTrack& tr = clip.rotations[static_cast<std::size_t>(j)];
  const quat raised = joint_rotation(skeleton(), j, vec3(0, 0, deg(5.0f)));
  tr.add(0.0f, raised);
  tr.add(3.0f, raised);
  clip.duration = 3.0f;
  return clip;
}

}  // namespace

TEST(FaceJointOffsets, AddToWhatTheTrackHoldsOnlyInsideTheirSpan) {
  Clip clip = held_clavicle();
  const JointOffset raise = make_offset("l_sternoclavicular", vec3(0, 0, deg(10.0f)), 1.0f, 2.0f);
  EXPECT_TRUE(add_joint_offsets({&raise, 1}, skeleton(), clip).empty());
  EXPECT_NEAR(angles_at(clip, "l_sternoclavicular", 1.5f).z, deg(15.0f), deg(0.1f));
  EXPECT_NEAR(angles_at(clip, "l_sternoclavicular", 0.5f).z, deg(5.0f), deg(0.1f));
  EXPECT_NEAR(angles_at(clip, "l_sternoclavicular", 2.5f).z, deg(5.0f), deg(0.1f));
  // Halfway up the sinusoidal ramp (10% of the span, but at least 80 ms → 0.1 s): half the offset.
  EXPECT_NEAR(angles_at(clip, "l_sternoclavicular", 1.05f).z, deg(10.0f), deg(0.3f));
}

TEST(FaceJointOffsets, StayWithinTheJointLimits) {
  Clip clip = held_clavicle();
  const JointOffset too_far = make_offset("l_sternoclavicular", vec3(deg(30.0f), 0, deg(80.0f)), 1.0f, 2.0f);
  add_joint_offsets({&too_far, 1}, skeleton(), clip);
  const vec3 a = angles_at(clip, "l_sternoclavicular", 1.5f);
  EXPECT_NEAR(a.z, deg(40.0f), deg(0.1f));  // the clavicle's upper limit
  EXPECT_NEAR(a.x, 0.0f, 1e-5f);            // x is not a degree of freedom of the clavicle
}

TEST(FaceJointOffsets, OscillateAndStartFromRestOnUndrivenJoints) {
  Clip clip;
  const JointOffset sway = make_offset("vt6", vec3(0, deg(6.0f), 0), 0.0f, 2.0f, 2.0f);
  add_joint_offsets({&sway, 1}, skeleton(), clip);
  ASSERT_EQ(clip.joint_count(), skeleton().size());
  EXPECT_NEAR(angles_at(clip, "vt6", 0.625f).y, deg(6.0f), deg(0.3f));   // sin peak, ramps done
  EXPECT_NEAR(angles_at(clip, "vt6", 0.875f).y, -deg(6.0f), deg(0.3f));  // half a cycle later
  EXPECT_NEAR(angles_at(clip, "vt6", 2.0f).y, 0.0f, 1e-5f);
  EXPECT_GE(clip.duration, 2.0f);
}

TEST(FaceJointOffsets, ReportMissingJointsAndRejectBadOffsets) {
  Clip clip;
  const JointOffset tail = make_offset("tail", vec3(0.1f), 0.0f, 1.0f);
  const auto missing = add_joint_offsets({&tail, 1}, skeleton(), clip);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0], "tail");
  const JointOffset reversed = make_offset("vt6", vec3(0.1f), 1.0f, 0.5f);
  EXPECT_THROW(add_joint_offsets({&reversed, 1}, skeleton(), clip), Error);
  JointOffset nan = make_offset("vt6", vec3(0.1f), 0.0f, 1.0f);
  nan.angles.y = std::nanf("");
  EXPECT_THROW(add_joint_offsets({&nan, 1}, skeleton(), clip), Error);
  Clip other;
  other.resize_joints(3);
  const JointOffset ok = make_offset("vt6", vec3(0.1f), 0.0f, 1.0f);
  EXPECT_THROW(add_joint_offsets({&ok, 1}, skeleton(), other), Error);
}

TEST(FaceJointOffsets, ChildrenCanKeepTheirOrientation) {
  Clip clip = held_clavicle();
  const int clavicle = skeleton().find("l_sternoclavicular"), shoulder = skeleton().find("l_shoulder");
  // The upper arm bent 30° forward, keyed as the IK would.
  const quat arm = joint_rotation(skeleton(), shoulder, vec3(deg(30.0f), 0, 0));
  clip.rotations[static_cast<std::size_t>(shoulder)].add(0.0f, arm);
  clip.rotations[static_cast<std::size_t>(shoulder)].add(3.0f, arm);
  auto upper_arm_in_trunk = [&](const Clip& c, float t) {
    return sample_track(c.rotations[static_cast<std::size_t>(clavicle)], t) *
           sample_track(c.rotations[static_cast<std::size_t>(shoulder)], t);
  };
  const quat before = upper_arm_in_trunk(clip, 1.5f);
  JointOffset raise = make_offset("l_sternoclavicular", vec3(0, 0, deg(12.0f)), 1.0f, 2.0f);
  raise.children_keep_orientation = true;
  add_joint_offsets({&raise, 1}, skeleton(), clip);
  EXPECT_NEAR(angles_at(clip, "l_sternoclavicular", 1.5f).z, deg(17.0f), deg(0.1f));  // the clavicle rose
  EXPECT_GT(std::abs(glm::dot(before, upper_arm_in_trunk(clip, 1.5f))), 0.99999f);     // the arm did not turn
  EXPECT_GT(std::abs(glm::dot(arm, sample_track(clip.rotations[static_cast<std::size_t>(shoulder)], 0.5f))), 0.99999f);
}
