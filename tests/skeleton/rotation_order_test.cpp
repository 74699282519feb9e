#include <gtest/gtest.h>

#include <random>

#include "gestura/skeleton/rotation_order.hpp"

using namespace gestura;

namespace {

// Independent reference: compose axis rotations as matrices with glm::rotate, outermost first.
mat3 reference_matrix(const vec3& angles, const char* order) {
  mat4 m(1.0f);
  for (int i = 0; i < 3; ++i) {
    const int axis = order[i] - 'X';
    vec3 a(0.0f);
    a[axis] = 1.0f;
    m = glm::rotate(m, angles[axis], a);
  }
  return mat3(m);
}

float rotation_distance(const quat& a, const quat& b) { return 1.0f - std::abs(glm::dot(glm::normalize(a), glm::normalize(b))); }

}  // namespace

TEST(RotationOrder, MatchesMatrixCompositionForAllSixOrders) {
  const vec3 angles(0.3f, -0.7f, 1.1f);
  for (RotationOrder o : kAllRotationOrders) {
    const std::string name(to_string(o));
    const mat3 expected = reference_matrix(angles, name.c_str());
    const mat3 got = glm::mat3_cast(euler_to_quat(angles, o));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-5f) << name;
  }
}

TEST(RotationOrder, BvhZxyMeansRzRxRy) {
  // A BVH channel list "Zrotation Xrotation Yrotation" is R = Rz · Rx · Ry.
  const vec3 a(deg(30), deg(45), deg(60));
  const quat expected = glm::angleAxis(a.z, vec3(0, 0, 1)) * glm::angleAxis(a.x, vec3(1, 0, 0)) *
                        glm::angleAxis(a.y, vec3(0, 1, 0));
  EXPECT_LT(rotation_distance(euler_to_quat(a, RotationOrder::ZXY), expected), 1e-6f);
}

TEST(RotationOrder, AllSixOrdersRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> any(-kPi, kPi), middle(-1.5f, 1.5f);
  for (RotationOrder o : kAllRotationOrders) {
    for (int i = 0; i < 500; ++i) {
      vec3 a(any(rng), any(rng), any(rng));
      a[axes_of(o)[1]] = middle(rng);  // the middle angle's principal range
      const vec3 back = quat_to_euler(euler_to_quat(a, o), o);
      EXPECT_NEAR(back.x, a.x, 1e-3f) << to_string(o);
      EXPECT_NEAR(back.y, a.y, 1e-3f) << to_string(o);
      EXPECT_NEAR(back.z, a.z, 1e-3f) << to_string(o);
    }
  }
}

TEST(RotationOrder, GimbalLockStillRoundTripsTheRotation) {
  for (RotationOrder o : kAllRotationOrders) {
    vec3 a(0.4f, 0.4f, 0.4f);
    a[axes_of(o)[1]] = kPi / 2;
    const quat q = euler_to_quat(a, o);
    const quat back = euler_to_quat(quat_to_euler(q, o), o);
    EXPECT_LT(rotation_distance(q, back), 1e-5f) << to_string(o);
  }
}

TEST(RotationOrder, NearSolutionFollowsThePreviousFrameWithoutFlips) {
  // Spin about Y past 180°: plain decomposition wraps to −180°, the near form keeps counting.
  vec3 previous(0.0f);
  for (int step = 0; step <= 40; ++step) {
    const float angle = deg(10.0f * static_cast<float>(step));
    const quat q = euler_to_quat(vec3(0, angle, 0), RotationOrder::XYZ);
    const vec3 got = quat_to_euler_near(q, RotationOrder::XYZ, previous);
    EXPECT_LT(rotation_distance(euler_to_quat(got, RotationOrder::XYZ), q), 1e-5f);
    EXPECT_LT(glm::length(got - previous), deg(10.5f)) << "step " << step;
    previous = got;
  }
  EXPECT_NEAR(previous.y, deg(400.0f), 1e-3f);
}

TEST(RotationOrder, ParsesNames) {
  EXPECT_EQ(parse_rotation_order("zxy"), RotationOrder::ZXY);
  EXPECT_EQ(parse_rotation_order("YZX"), RotationOrder::YZX);
  EXPECT_FALSE(parse_rotation_order("XXY").has_value());
  EXPECT_FALSE(parse_rotation_order("").has_value());
}
