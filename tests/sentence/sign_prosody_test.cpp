// Running-signing timing of one sign (sentence/sign_prosody.hpp).
#include <gtest/gtest.h>

#include "gestura/sentence/sign_prosody.hpp"

namespace gestura {
namespace {

TEST(ProsodyTiming, StaticSignIsHeldAtLeastTheMinimum) {
  // No movement at all (MY: a flat hand on the chest): the posture is held, not flashed.
  const SignTiming t = running_sign_timing(0.0f, false, 0.0f, 1.0f);
  EXPECT_FLOAT_EQ(t.movement, 0.0f);
  EXPECT_GE(t.span(), 0.3f - 1e-6f);
  EXPECT_LE(t.span(), 0.5f);
  EXPECT_GT(t.final_hold, t.initial_hold);  // the extra time is a hold at the sign's posture
}

TEST(ProsodyTiming, LongerCitationMovementGivesALongerSign) {
  const SignTiming small = running_sign_timing(0.8f, false, 0.0f, 1.0f);
  const SignTiming large = running_sign_timing(2.0f, false, 0.0f, 1.0f);
  EXPECT_GT(large.span(), small.span() + 0.15f);
  EXPECT_LT(small.movement, 0.4f);  // running signing is faster than citation form
}

TEST(ProsodyTiming, PhraseFinalSignIsLengthened) {
  for (float m : {0.0f, 0.4f, 1.0f}) {
    const SignTiming inside = running_sign_timing(m, false, 0.0f, 1.0f);
    const SignTiming final = running_sign_timing(m, true, 0.0f, 1.0f);
    EXPECT_GT(final.span(), inside.span() + 0.09f) << m;
    EXPECT_GE(final.movement, inside.movement) << m;
    EXPECT_GE(final.span(), 0.4f - 1e-6f) << m;
  }
}

TEST(ProsodyTiming, SpeedScalesEveryPart) {
  const SignTiming normal = running_sign_timing(0.8f, true, 0.3f, 1.0f);
  const SignTiming slow = running_sign_timing(0.8f, true, 0.3f, 0.25f);
  const SignTiming fast = running_sign_timing(0.8f, true, 0.3f, 2.0f);
  EXPECT_NEAR(slow.span(), 4.0f * normal.span(), 1e-4f);
  EXPECT_NEAR(fast.span(), 0.5f * normal.span(), 1e-4f);
  EXPECT_NEAR(slow.movement, 4.0f * normal.movement, 1e-4f);
}

TEST(ProsodyTiming, QuestionHoldIsAddedToTheFinalHold) {
  const SignTiming plain = running_sign_timing(0.8f, true, 0.0f, 1.0f);
  const SignTiming question = running_sign_timing(0.8f, true, 0.3f, 1.0f);
  EXPECT_NEAR(question.final_hold - plain.final_hold, 0.3f, 1e-5f);
}

}  // namespace
}  // namespace gestura
