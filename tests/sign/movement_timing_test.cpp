#include <gtest/gtest.h>

#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/sign/movement_timing.hpp"

using namespace gestura;

namespace {

// Central differences of the progress curve, to check the analytic derivatives independently.
float numeric_velocity(VelocityProfile p, float t, float h = 1e-3f) {
  return (profile_progress(p, t + h) - profile_progress(p, t - h)) / (2 * h);
}

}  // namespace

TEST(MovementTiming, MinimumJerkStartsAndEndsAtRest) {
  EXPECT_EQ(minimum_jerk(0.0f), 0.0f);
  EXPECT_NEAR(minimum_jerk(1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(minimum_jerk(0.5f), 0.5f, 1e-6f);
  EXPECT_EQ(minimum_jerk_velocity(0.0f), 0.0f);
  EXPECT_NEAR(minimum_jerk_velocity(1.0f), 0.0f, 1e-6f);
  EXPECT_EQ(minimum_jerk_acceleration(0.0f), 0.0f);
  EXPECT_NEAR(minimum_jerk_acceleration(1.0f), 0.0f, 1e-6f);
  // Peak speed 1.875 at the midpoint (the textbook value 30/16).
  EXPECT_NEAR(minimum_jerk_velocity(0.5f), 1.875f, 1e-6f);
  // The polynomial by hand at t = 0.25: 10/64 − 15/256 + 6/1024.
  EXPECT_NEAR(minimum_jerk(0.25f), 10.0f / 64 - 15.0f / 256 + 6.0f / 1024, 1e-6f);
  // Clamped outside [0, 1] and robust to NaN.
  EXPECT_EQ(minimum_jerk(-1.0f), 0.0f);
  EXPECT_NEAR(minimum_jerk(3.0f), 1.0f, 1e-6f);
  EXPECT_EQ(minimum_jerk(std::nanf("")), 0.0f);
}

TEST(MovementTiming, ProfilesAreMonotonicWithConsistentDerivatives) {
  for (VelocityProfile p : {VelocityProfile::Linear, VelocityProfile::MinimumJerk, VelocityProfile::EaseInOut,
                            VelocityProfile::ConstantRamped}) {
    EXPECT_NEAR(profile_progress(p, 0.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(profile_progress(p, 1.0f), 1.0f, 1e-6f);
    float previous = 0.0f;
    for (int k = 1; k <= 100; ++k) {
      const float t = k / 100.0f, s = profile_progress(p, t);
      EXPECT_GE(s, previous - 1e-6f);
      previous = s;
    }
    for (float t : {0.1f, 0.3f, 0.5f, 0.7f, 0.9f}) {
      EXPECT_NEAR(profile_velocity(p, t), numeric_velocity(p, t), 2e-3f) << static_cast<int>(p) << " t=" << t;
      const float h = 1e-3f;
      const float numeric_acc = (profile_velocity(p, t + h) - profile_velocity(p, t - h)) / (2 * h);
      EXPECT_NEAR(profile_acceleration(p, t), numeric_acc, 2e-2f) << static_cast<int>(p) << " t=" << t;
    }
  }
  EXPECT_NEAR(profile_velocity(VelocityProfile::EaseInOut, 0.0f), 0.0f, 1e-6f);
  // The ramped profile cruises at constant speed in the middle.
  EXPECT_NEAR(profile_velocity(VelocityProfile::ConstantRamped, 0.3f), profile_velocity(VelocityProfile::ConstantRamped, 0.7f), 1e-6f);
  EXPECT_NEAR(profile_velocity(VelocityProfile::ConstantRamped, 0.0f), 0.0f, 1e-6f);
}

TEST(MovementTiming, DurationsFollowSizeAndSpeed) {
  // A normal straight movement (15 cm) lasts 0.5–0.8 s at normal speed.
  const float normal = straight_duration(0.15f);
  EXPECT_GE(normal, 0.5f);
  EXPECT_LE(normal, 0.8f);
  EXPECT_NEAR(normal, 0.3f + 0.15f / 0.45f, 1e-6f);
  EXPECT_LT(straight_duration(0.08f), normal);
  EXPECT_GT(straight_duration(0.25f), normal);
  EXPECT_LT(straight_duration(0.15f, MovementSpeed::Fast), normal);
  EXPECT_GT(straight_duration(0.15f, MovementSpeed::Slow), normal);
  EXPECT_LT(transition_duration(0.15f), normal);  // transitions are quicker than lexical movements
  EXPECT_THROW(straight_duration(-0.1f), Error);
  EXPECT_THROW(continuous_duration(std::nanf("")), Error);
  EXPECT_THROW(transition_duration(INFINITY), Error);
}

TEST(MovementTiming, PostureTransitionHoldsOutsideAndEasesInside) {
  PostureTransition tr{basic_handshape(BasicHandshape::Flat), basic_handshape(BasicHandshape::Fist), 1.0f, 0.4f};
  const float fist_mcp = tr.to.finger(Finger::Index).mcp;
  EXPECT_EQ(sample(tr, 0.5f).finger(Finger::Index).mcp, 0.0f);
  EXPECT_NEAR(sample(tr, 1.2f).finger(Finger::Index).mcp, 0.5f * fist_mcp, 1e-5f);
  EXPECT_NEAR(sample(tr, 1.1f).finger(Finger::Index).mcp, minimum_jerk(0.25f) * fist_mcp, 1e-5f);
  EXPECT_NEAR(sample(tr, 5.0f).finger(Finger::Index).mcp, fist_mcp, 1e-6f);

  PlacementTransition move;
  move.to_position = {0.1f, 0.2f, 0.0f};
  move.to_rotation = glm::angleAxis(1.0f, vec3{0, 1, 0});
  move.duration = 0.5f;
  const Placement mid = sample(move, 0.25f);
  EXPECT_NEAR(mid.position.x, 0.05f, 1e-6f);
  EXPECT_NEAR(glm::angle(mid.rotation), 0.5f, 1e-4f);
  const Placement end = sample(move, 0.5f);
  EXPECT_NEAR(end.position.y, 0.2f, 1e-6f);
  // Zero duration jumps at the start time.
  move.duration = 0.0f;
  EXPECT_NEAR(sample(move, -0.1f).position.y, 0.0f, 1e-6f);
  EXPECT_NEAR(sample(move, 0.0f).position.y, 0.2f, 1e-6f);
}
