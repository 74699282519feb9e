#include "gestura/face/nonmanual.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/face_channels.hpp"

using namespace gestura;
using namespace gestura::face;
using gestura::Expression;

namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

// n glosses of 0.5 s each, back to back from t = 0.
NonManualPlan plan_of(std::size_t n) {
  NonManualPlan plan;
  for (std::size_t i = 0; i < n; ++i)
    plan.glosses.push_back(TimedGloss{0.5f * static_cast<float>(i), 0.5f * static_cast<float>(i + 1), GlossKind::sign});
  return plan;
}

float at(Clip& clip, std::string_view channel, float t) {
  if (clip.find_channel(std::string(channel)) < 0) return 0.0f;
  return sample_track(clip.channel(std::string(channel)), t);
}

// Head angles (pitch, yaw, roll) of skullbase + vc4 at t, from the clip.
vec3 head(const Clip& clip, const Skeleton& sk, float t) {
  vec3 sum(0.0f);
  for (const char* name : {"vc4", "skullbase"}) {
    const auto j = static_cast<std::size_t>(sk.find(name));
    sum += quat_to_euler(sample_track(clip.rotations[j], t), sk.dofs[j].order);
  }
  return sum;
}

}  // namespace

TEST(FaceNonManual, HeadshakeOscillatesOnlyOverTheNegatedSpan) {
  const Skeleton sk = build_avatar_skeleton();
  NonManualPlan plan = plan_of(6);
  plan.spans.push_back({NonManualKind::negation, 2, 4});  // t in [1, 2]
  Clip clip;
  add_nonmanual_markers(plan, sk, clip);
  int sign_changes = 0;
  float previous = 0.0f, max_yaw = 0.0f;
  for (int i = 0; i <= 300; ++i) {
    const float t = 3.0f * static_cast<float>(i) / 300.0f;
    const float yaw = head(clip, sk, t).y;
    if (t < 1.0f || t > 2.0f) {
      EXPECT_NEAR(yaw, 0.0f, 1e-4f) << t;
      continue;
    }
    max_yaw = std::max(max_yaw, std::abs(yaw));
    if (yaw * previous < 0.0f) ++sign_changes;
    if (std::abs(yaw) > 1e-3f) previous = yaw;
  }
  EXPECT_GE(sign_changes, 4);              // 2.5 Hz over 1 s: ~5 crossings
  EXPECT_GT(max_yaw, 8.0f * kDeg);         // close to ±10°
  EXPECT_LE(max_yaw, 10.0f * kDeg + 1e-4f);
  EXPECT_GT(at(clip, kBrowDownL, 1.5f), 0.2f);
}

TEST(FaceNonManual, YesNoQuestionRaisesBrowsAndTiltsForward) {
  const Skeleton sk = build_avatar_skeleton();
  NonManualPlan plan = plan_of(4);
  plan.spans.push_back({NonManualKind::yes_no_question, 0, 4});
  Clip clip;
  add_nonmanual_markers(plan, sk, clip);
  EXPECT_NEAR(at(clip, kBrowInnerUpL, 1.0f), 0.8f, 1e-4f);
  EXPECT_NEAR(at(clip, kBrowOuterUpR, 1.0f), 0.8f, 1e-4f);
  EXPECT_NEAR(head(clip, sk, 1.0f).x, 8.0f * kDeg, 0.2f * kDeg);  // +x = forward
  EXPECT_NEAR(head(clip, sk, 1.0f).y, 0.0f, 1e-4f);
}

TEST(FaceNonManual, QuestionHoldLengthensTheLastSignAndShiftsTheRest) {
  NonManualPlan plan = plan_of(5);
  plan.spans.push_back({NonManualKind::yes_no_question, 0, 3});
  plan.boundaries = {1.5f, 2.5f};
  const NonManualPlan held = apply_question_holds(plan, 0.3f);
  EXPECT_FLOAT_EQ(held.glosses[2].start, 1.0f);
  EXPECT_FLOAT_EQ(held.glosses[2].end, 1.8f);
  EXPECT_FLOAT_EQ(held.glosses[3].start, 1.8f);
  EXPECT_FLOAT_EQ(held.glosses[4].end, 2.8f);
  EXPECT_FLOAT_EQ(held.glosses[1].end, 1.0f);
  EXPECT_FLOAT_EQ(held.boundaries[0], 1.8f);
  EXPECT_FLOAT_EQ(held.boundaries[1], 2.8f);
}

TEST(FaceNonManual, WhQuestionLowersBrows) {
  const Skeleton sk = build_avatar_skeleton();
  NonManualPlan plan = plan_of(4);
  plan.spans.push_back({NonManualKind::wh_question, 0, 4});
  Clip clip;
  add_nonmanual_markers(plan, sk, clip);
  EXPECT_NEAR(at(clip, kBrowDownR, 1.0f), 0.8f, 1e-4f);
  EXPECT_EQ(at(clip, kBrowInnerUpL, 1.0f), 0.0f);
  EXPECT_GT(std::abs(head(clip, sk, 1.0f).z), 3.0f * kDeg);
}

TEST(FaceNonManual, OverlappingMarkersComposeWithinZeroOne) {
  const Skeleton sk = build_avatar_skeleton();
  NonManualPlan plan = plan_of(8);
  plan.spans.push_back({NonManualKind::topic, 0, 3});            // brows 0.7 over [0, 1.5]
  plan.spans.push_back({NonManualKind::yes_no_question, 2, 8});  // brows 0.8 over [1, 4]
  plan.spans.push_back({NonManualKind::affect, 0, 8, Expression::Surprise, 1.0f});  // brows 0.9
  Clip clip;
  add_nonmanual_markers(plan, sk, clip);
  for (const FloatTrack& tr : clip.channels)
    for (float v : tr.values) {
      EXPECT_LE(v, 1.0f);
      EXPECT_GE(v, 0.0f);
    }
  EXPECT_NEAR(at(clip, kBrowInnerUpL, 1.25f), 1.0f, 1e-5f);
  EXPECT_NEAR(at(clip, kEyeWideL, 3.0f), 1.0f, 1e-5f);  // 0.3 + 0.9 clamped
  EXPECT_NO_THROW(validate(clip, sk));
  // Head pitch adds: topic −3° and question +8° overlap over [1, 1.5].
  EXPECT_NEAR(head(clip, sk, 1.3f).x, 5.0f * kDeg, 0.3f * kDeg);
}

TEST(FaceNonManual, BlinksAtBoundariesAndEveryFewSeconds) {
  NonManualPlan plan = plan_of(40);  // 20 s
  plan.boundaries = {3.0f, 7.25f, 12.0f};
  const std::vector<float> blinks = blink_times(plan);
  for (float b : plan.boundaries) EXPECT_NE(std::find(blinks.begin(), blinks.end(), b), blinks.end()) << b;
  ASSERT_GE(blinks.size(), 6u);
  EXPECT_LE(blinks.front(), 5.0f);
  for (std::size_t i = 1; i < blinks.size(); ++i) {
    EXPECT_LE(blinks[i] - blinks[i - 1], 5.0f);
    EXPECT_GE(blinks[i] - blinks[i - 1], 0.5f);
  }
  EXPECT_GE(blinks.back(), 15.0f);
  // Deterministic, and a different seed blinks elsewhere.
  EXPECT_EQ(blink_times(plan), blinks);
  NonManualPlan other = plan;
  other.seed = 7;
  EXPECT_NE(blink_times(other), blinks);

  const Skeleton sk = build_avatar_skeleton();
  Clip clip;
  add_nonmanual_markers(plan, sk, clip);
  EXPECT_NEAR(at(clip, kEyeBlinkL, 7.25f), 1.0f, 1e-5f);
  EXPECT_NEAR(at(clip, kEyeBlinkR, 7.25f), 1.0f, 1e-5f);
  EXPECT_NEAR(at(clip, kEyeBlinkL, 7.25f + kBlinkSeconds), 0.0f, 1e-5f);
}

TEST(FaceNonManual, EyesFollowTheHandsWhileFingerspelling) {
  NonManualPlan plan = plan_of(3);
  plan.glosses[1].kind = GlossKind::fingerspell;  // [0.5, 1.0]
  const NonManualActions actions = plan_nonmanual(plan);
  EXPECT_NEAR(channel_weight(actions.face, kGazeHands, 0.75f), 1.0f, 1e-6f);
  EXPECT_EQ(channel_weight(actions.face, kGazeHands, 0.4f), 0.0f);
  EXPECT_EQ(channel_weight(actions.face, kGazeHands, 1.1f), 0.0f);
  EXPECT_TRUE(actions.head.empty());
}

TEST(FaceNonManual, BadPlansNameTheCulprit) {
  NonManualPlan plan = plan_of(3);
  plan.spans.push_back({NonManualKind::negation, 1, 5});
  try {
    plan_nonmanual(plan);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("span 0"), std::string::npos) << e.what();
  }
  plan = plan_of(3);
  plan.glosses[2].end = NAN;
  try {
    plan_nonmanual(plan);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gloss 2"), std::string::npos) << e.what();
  }
  plan = plan_of(3);
  plan.spans.push_back({NonManualKind::topic, 2, 2});
  EXPECT_THROW(plan_nonmanual(plan), Error);
  plan = plan_of(3);
  plan.glosses[2].end = 1e9f;  // would mean millions of idle blinks
  EXPECT_THROW(plan_nonmanual(plan), Error);
}
