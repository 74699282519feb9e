#include "gestura/face/face_action.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "gestura/core/error.hpp"

using namespace gestura;
using namespace gestura::face;

namespace {
constexpr float kPi = 3.14159265358979f;
float cosine_ramp(float x) { return 0.5f - 0.5f * std::cos(kPi * x); }
}  // namespace

TEST(FaceAction, DefaultRampIsTenPercentAtLeast80msAtMostHalf) {
  EXPECT_FLOAT_EQ(default_ramp(2.0f), 0.2f);
  EXPECT_FLOAT_EQ(default_ramp(0.5f), 0.08f);
  EXPECT_FLOAT_EQ(default_ramp(0.1f), 0.05f);
}

TEST(FaceAction, RampsAreSinusoidalAndReachFullWeightInsideTheSpan) {
  const FaceAction a = make_action("browDown_L", 1.0f, 3.0f, 0.8f);  // ramps of 0.2 s
  for (float x : {0.1f, 0.25f, 0.5f, 0.75f, 0.9f}) {
    EXPECT_NEAR(action_weight(a, 1.0f + 0.2f * x), 0.8f * cosine_ramp(x), 1e-5f) << x;
    EXPECT_NEAR(action_weight(a, 3.0f - 0.2f * x), 0.8f * cosine_ramp(x), 1e-5f) << x;
  }
  EXPECT_FLOAT_EQ(action_weight(a, 1.2f), 0.8f);
  EXPECT_FLOAT_EQ(action_weight(a, 2.0f), 0.8f);
  EXPECT_FLOAT_EQ(action_weight(a, 2.8f), 0.8f);
  EXPECT_EQ(action_weight(a, 0.99f), 0.0f);
  EXPECT_EQ(action_weight(a, 3.01f), 0.0f);
}

TEST(FaceAction, WrittenKeysFollowTheSinusoid) {
  Clip clip;
  const FaceAction a = make_action("browDown_L", 1.0f, 3.0f, 1.0f);
  write_face_channels(std::span(&a, 1), clip);
  const FloatTrack& tr = clip.channel("browDown_L");
  ASSERT_GE(tr.size(), 4u);
  EXPECT_FLOAT_EQ(tr.times.front(), 1.0f);
  EXPECT_FLOAT_EQ(tr.times.back(), 3.0f);
  for (int i = 0; i <= 100; ++i) {
    const float t = 0.9f + 2.2f * static_cast<float>(i) / 100.0f;
    float expected = 0.0f;
    if (t > 1.0f && t < 3.0f) expected = cosine_ramp(std::min({(t - 1.0f) / 0.2f, (3.0f - t) / 0.2f, 1.0f}));
    EXPECT_NEAR(sample_track(tr, t), expected, 0.02f) << t;
  }
  EXPECT_GE(clip.duration, 3.0f);
}

TEST(FaceAction, OverlappingActionsAddAndNeverExceedOne) {
  const std::vector<FaceAction> actions{make_action("eyeWide_L", 0.0f, 2.0f, 0.7f),
                                        make_action("eyeWide_L", 1.0f, 3.0f, 0.7f),
                                        make_action("eyeWide_R", 1.0f, 3.0f, 0.2f)};
  Clip clip;
  write_face_channels(actions, clip);
  const FloatTrack& tr = clip.channel("eyeWide_L");
  for (float v : tr.values) {
    EXPECT_LE(v, 1.0f);
    EXPECT_GE(v, 0.0f);
  }
  EXPECT_NEAR(sample_track(tr, 0.5f), 0.7f, 1e-5f);   // first only
  EXPECT_NEAR(sample_track(tr, 1.5f), 1.0f, 1e-5f);   // 0.7 + 0.7 clamped
  EXPECT_NEAR(sample_track(tr, 2.5f), 0.7f, 1e-5f);   // second only
  EXPECT_NEAR(sample_track(clip.channel("eyeWide_R"), 2.0f), 0.2f, 1e-5f);  // channels independent
  // Where only one ramp overlaps, the values add: 0.7 (held) + the other's ramp start.
  const float t = 1.0f + 0.1f;  // second action's ramp is 0.2 s
  EXPECT_NEAR(channel_weight(actions, "eyeWide_L", t), std::min(1.0f, 0.7f + 0.7f * cosine_ramp(0.5f)), 1e-5f);
}

TEST(FaceAction, BadActionsAreRefusedWithTheirIndex) {
  Clip clip;
  const std::vector<FaceAction> reversed{make_action("a", 0, 1, 1), FaceAction{"b", 2.0f, 1.0f, 1.0f, 0, 0}};
  try {
    write_face_channels(reversed, clip);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("face action 1"), std::string::npos) << e.what();
  }
  const FaceAction nan{"a", 0.0f, NAN, 1.0f, 0, 0};
  EXPECT_THROW(write_face_channels(std::span(&nan, 1), clip), Error);
  const FaceAction long_ramps{"a", 0.0f, 1.0f, 1.0f, 0.6f, 0.6f};
  EXPECT_THROW(write_face_channels(std::span(&long_ramps, 1), clip), Error);
}
