#include <gtest/gtest.h>

#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/skeleton/skeleton.hpp"

using namespace gestura;

namespace {

// shoulder at (0.2, 1.4, 0); upper arm 0.3 m along −Y; forearm 0.25 m along −Y.
Skeleton arm() {
  Skeleton s;
  s.add_joint("l_shoulder", -1, vec3(0.2f, 1.4f, 0.0f));
  s.add_joint("l_elbow", 0, vec3(0.0f, -0.3f, 0.0f));
  s.add_joint("l_wrist", 1, vec3(0.0f, -0.25f, 0.0f));
  s.dofs[1] = JointDofs{RotationOrder::XYZ, 0b001, vec3(deg(-142), 0, 0), vec3(0, 0, 0)};  // elbow flexes about −X
  return s;
}

}  // namespace

TEST(Skeleton, ForwardKinematicsEqualsHandComputedChain) {
  const Skeleton s = arm();
  Pose pose = rest_pose(s);
  // Shoulder: 90° about +Z swings the arm from −Y to +X (abduction to the avatar's left side).
  pose.rotations[0] = glm::angleAxis(kPi / 2, vec3(0, 0, 1));
  // Elbow: 90° about +Z again, forearm then points +Y.
  pose.rotations[1] = glm::angleAxis(kPi / 2, vec3(0, 0, 1));
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  std::vector<vec3> p(s.size());
  model_positions(model, p);
  // By hand: elbow = shoulder + Rz90·(0,−0.3,0) = (0.2+0.3, 1.4, 0);
  // wrist = elbow + Rz180·(0,−0.25,0) = (0.5, 1.65, 0).
  EXPECT_NEAR(p[0].x, 0.2f, 1e-6f);
  EXPECT_NEAR(p[1].x, 0.5f, 1e-6f);
  EXPECT_NEAR(p[1].y, 1.4f, 1e-6f);
  EXPECT_NEAR(p[2].x, 0.5f, 1e-6f);
  EXPECT_NEAR(p[2].y, 1.65f, 1e-6f);
}

TEST(Skeleton, RootTransformAndScalePropagate) {
  Skeleton s = arm();
  Pose pose = rest_pose(s);
  pose.scales[0] = vec3(2.0f);
  std::vector<mat4> model(s.size());
  local_to_model(s.parents, pose.translations, pose.rotations, pose.scales, model,
                 glm::translate(mat4(1.0f), vec3(0, 0, 1)));
  EXPECT_NEAR(model[2][3].y, 1.4f - 2 * 0.55f, 1e-6f);
  EXPECT_NEAR(model[2][3].z, 1.0f, 1e-6f);
}

TEST(Skeleton, SegmentTransformKeepsTheJointCentreFixed) {
  // M = B·R·B⁻¹ rotates about the joint centre: the centre maps to itself, other points orbit it.
  const vec3 centre(0.1f, 1.0f, -0.2f);
  const mat4 m = segment_transform(centre, vec3(0, 0, kPi / 2), RotationOrder::XYZ);
  const vec3 c = vec3(m * vec4(centre, 1));
  EXPECT_NEAR(glm::length(c - centre), 0.0f, 1e-6f);
  const vec3 p = vec3(m * vec4(centre + vec3(1, 0, 0), 1));
  EXPECT_NEAR(p.x, centre.x, 1e-6f);
  EXPECT_NEAR(p.y, centre.y + 1, 1e-6f);
}

TEST(Skeleton, DenavitHartenbergMatchesItsDefinition) {
  const DenavitHartenberg dh{0.3f, kPi / 2, 0.1f, 0.0f};
  const mat4 m = dh.matrix(kPi / 2);
  // Rz(90)·Tz(0.1)·Tx(0.3)·Rx(90): origin goes to (0, 0.3, 0.1); local z maps to −x... compute by parts.
  const mat4 expected = glm::rotate(mat4(1), kPi / 2, vec3(0, 0, 1)) * glm::translate(mat4(1), vec3(0, 0, 0.1f)) *
                        glm::translate(mat4(1), vec3(0.3f, 0, 0)) * glm::rotate(mat4(1), kPi / 2, vec3(1, 0, 0));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], expected[c][r], 1e-6f);
  EXPECT_NEAR(m[3].y, 0.3f, 1e-6f);
  EXPECT_NEAR(m[3].z, 0.1f, 1e-6f);
}

TEST(Skeleton, LimitsClampOutOfRangeJoints) {
  const Skeleton s = arm();
  Pose pose = rest_pose(s);
  pose.rotations[1] = glm::angleAxis(deg(-170), vec3(1, 0, 0));  // past 142° flexion
  EXPECT_FALSE(within_limits(s, 1, pose.rotations[1]));
  EXPECT_EQ(clamp_to_limits(s, pose), 1);
  EXPECT_NEAR(joint_angles(s, 1, pose.rotations[1]).x, deg(-142), 1e-4f);
  EXPECT_TRUE(within_limits(s, 1, pose.rotations[1]));
  // A locked axis is forced to zero: twist about Y is not an elbow DoF.
  pose.rotations[1] = glm::angleAxis(deg(-30), vec3(1, 0, 0)) * glm::angleAxis(deg(20), vec3(0, 1, 0));
  clamp_to_limits(s, pose);
  const vec3 a = joint_angles(s, 1, pose.rotations[1]);
  EXPECT_NEAR(a.x, deg(-30), 1e-3f);
  EXPECT_NEAR(a.y, 0.0f, 1e-4f);
  // Within limits: untouched.
  EXPECT_EQ(clamp_to_limits(s, pose), 0);
}

TEST(Skeleton, ValidateNamesTheProblem) {
  Skeleton s = arm();
  s.names[2] = "l_elbow";
  try {
    s.validate();
    FAIL() << "duplicate accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos);
  }
  s = arm();
  s.parents[1] = 2;
  EXPECT_THROW(s.validate(), Error);
  s = arm();
  s.rest_translations[0].x = std::nanf("");
  EXPECT_THROW(s.validate(), Error);
  s = arm();
  s.dofs[1].min_angle.x = 1.0f;  // min > max
  EXPECT_THROW(s.validate(), Error);
  EXPECT_THROW(s.add_joint("x", 99, vec3(0)), Error);
  EXPECT_NO_THROW(arm().validate());
  EXPECT_EQ(arm().total_dofs(), 1);
  EXPECT_EQ(arm().find("l_wrist"), 2);
  EXPECT_EQ(arm().find("nope"), -1);
}
