#include "gestura/body/avatar_skeleton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gestura/core/error.hpp"

using namespace gestura;

TEST(AvatarSkeleton, HasEnoughJointsAndDofsWithLimitsEverywhere) {
  const Skeleton s = build_avatar_skeleton();
  EXPECT_NO_THROW(s.validate());
  EXPECT_GE(s.size(), 60u);
  EXPECT_GE(s.total_dofs(), 120);
  for (std::size_t j = 0; j < s.size(); ++j)
    for (int a = 0; a < 3; ++a)
      if (s.dofs[j].free(a)) {
        EXPECT_LT(s.dofs[j].min_angle[a], s.dofs[j].max_angle[a]) << s.names[j] << " axis " << a;
        EXPECT_LE(s.dofs[j].max_angle[a] - s.dofs[j].min_angle[a], 2.0f * kPi + 1e-4f) << s.names[j];
      }
}

TEST(AvatarSkeleton, NamesFollowHAnimAndTipsAreLeafSites) {
  const Skeleton s = build_avatar_skeleton();
  for (const char* name : {"humanoid_root", "sacroiliac", "vl5", "vt12", "vt6", "vt1", "vc4", "skullbase",
                           "temporomandibular", "l_eyeball_joint", "r_eyeball_joint", "l_sternoclavicular",
                           "l_shoulder", "l_elbow", "l_wrist", "r_wrist", "l_hip", "l_knee", "l_ankle",
                           "l_subtalar", "l_metatarsal", "r_toe_tip"})
    EXPECT_GE(s.find(name), 0) << name;
  for (const char* side : {"l_", "r_"})
    for (const char* finger : kFingerNames) {
      for (int k = 1; k <= 3; ++k)
        EXPECT_GE(s.find(std::string(side) + finger + std::to_string(k)), 0) << side << finger << k;
      const int tip = s.find(std::string(side) + finger + "_tip");
      ASSERT_GE(tip, 0) << side << finger;
      EXPECT_EQ(s.dofs[static_cast<std::size_t>(tip)].count(), 0);
      for (std::size_t j = 0; j < s.size(); ++j) EXPECT_NE(s.parents[j], tip) << "tip has a child";
    }
}

TEST(AvatarSkeleton, HandsHaveAboutTwentyFiveDofs) {
  const Skeleton s = build_avatar_skeleton();
  int hand = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    int a = static_cast<int>(j);
    while (a >= 0 && s.names[static_cast<std::size_t>(a)] != "l_wrist") a = s.parents[static_cast<std::size_t>(a)];
    if (a >= 0) hand += s.dofs[j].count();
  }
  EXPECT_GE(hand, 22);
  EXPECT_LE(hand, 30);
}

TEST(AvatarSkeleton, RestPoseStandsOnTheFloorFacingPlusZWithLeftOnPlusX) {
  AvatarParams p;
  p.height = 1.80f;
  const Skeleton s = build_avatar_skeleton(p);
  const auto pos = rest_joint_positions(s);
  auto at = [&](const char* n) { return pos[static_cast<std::size_t>(s.find(n))]; };
  EXPECT_NEAR(at("skull_tip").y, 1.80f, 1e-4f);
  EXPECT_GT(at("l_shoulder").x, 0.1f);
  EXPECT_LT(at("r_shoulder").x, -0.1f);
  EXPECT_GT(at("l_toe_tip").z, at("l_ankle").z + 0.1f);  // feet point forward
  EXPECT_GT(at("l_eyeball_joint").z, at("skullbase").z);  // eyes in front
  EXPECT_GT(at("l_thumb_tip").z, at("l_pinky_tip").z);    // thumbs forward
  EXPECT_LT(at("l_middle_tip").y, at("l_wrist").y - 0.1f);  // arms hang down
  EXPECT_GT(at("l_ankle").y, 0.0f);
  EXPECT_LT(at("l_ankle").y, 0.12f);
  // Mirror symmetry.
  EXPECT_NEAR(at("l_index_tip").x, -at("r_index_tip").x, 1e-5f);
}

TEST(AvatarSkeleton, LeftElbowFlexionBringsTheForearmForward) {
  const Skeleton s = build_avatar_skeleton();
  for (const char* side : {"l_", "r_"}) {
    Pose pose = rest_pose(s);
    const int elbow = s.find(std::string(side) + "elbow");
    pose.rotations[static_cast<std::size_t>(elbow)] = joint_rotation(s, elbow, vec3(deg(-90.0f), 0, 0));
    EXPECT_TRUE(within_limits(s, elbow, pose.rotations[static_cast<std::size_t>(elbow)]));
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    const vec3 wrist(model[static_cast<std::size_t>(s.find(std::string(side) + "wrist"))][3]);
    const vec3 el(model[static_cast<std::size_t>(elbow)][3]);
    EXPECT_GT(wrist.z - el.z, 0.2f) << side;
  }
}

TEST(AvatarSkeleton, ShoulderAbductionRaisesEachArmSideways) {
  const Skeleton s = build_avatar_skeleton();
  for (const char* side : {"l_", "r_"}) {
    const int sh = s.find(std::string(side) + "shoulder");
    const float sign = side[0] == 'l' ? 1.0f : -1.0f;
    Pose pose = rest_pose(s);
    pose.rotations[static_cast<std::size_t>(sh)] = joint_rotation(s, sh, vec3(0, 0, sign * deg(80.0f)));
    EXPECT_TRUE(within_limits(s, sh, pose.rotations[static_cast<std::size_t>(sh)]));
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    const vec3 elbow(model[static_cast<std::size_t>(s.find(std::string(side) + "elbow"))][3]);
    const vec3 shoulder(model[static_cast<std::size_t>(sh)][3]);
    EXPECT_GT(sign * (elbow.x - shoulder.x), 0.25f) << side;
    EXPECT_NEAR(elbow.y, shoulder.y, 0.06f) << side;
  }
}

TEST(AvatarParams, RejectsNegativeNanAndAbsurdValuesByName) {
  auto message = [](AvatarParams p) {
    try {
      p.validate();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  AvatarParams p;
  EXPECT_EQ(message(p), "");
  p.height = -1.0f;
  EXPECT_NE(message(p).find("height"), std::string::npos);
  EXPECT_NE(message(p).find("not positive"), std::string::npos);
  p = {};
  p.build = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(message(p).find("build"), std::string::npos);
  EXPECT_NE(message(p).find("not a number"), std::string::npos);
  p = {};
  p.hand_size = 40.0f;
  EXPECT_NE(message(p).find("hand_size"), std::string::npos);
  p = {};
  p.finger_thickness = std::numeric_limits<float>::infinity();
  EXPECT_NE(message(p).find("finger_thickness"), std::string::npos);
  p = {};
  p.height = 9.0f;
  EXPECT_THROW(build_avatar_skeleton(p), Error);
  EXPECT_THROW(parse_sex("robot"), Error);
  EXPECT_EQ(parse_sex("Female"), Sex::Female);
}
