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

// A circle (citation model 0.52 s = 0.96 planner s) was played in 0.25 s; it keeps ≥ 55 % of its
// model time. A straight movement (0.63 planner s) keeps its plain compression.
TEST(ProsodyTiming, OneMovementIsNotCompressedBelowItsShare) {
  const float circle = 0.96f, straight = 0.63f;
  const SignTiming plain_circle = running_sign_timing(circle, false, 0.0f, 1.0f);
  const SignTiming read_circle = running_sign_timing(circle, false, 0.0f, 1.0f, circle);
  EXPECT_LT(plain_circle.movement, 0.26f);
  EXPECT_GE(read_circle.movement, 0.28f);
  EXPECT_NEAR(running_sign_timing(straight, false, 0.0f, 1.0f, straight).movement,
              running_sign_timing(straight, false, 0.0f, 1.0f).movement, 1e-6f);
  // At twice the speed, half as long; at the end of a phrase, slowed like the rest.
  EXPECT_NEAR(running_sign_timing(circle, false, 0.0f, 2.0f, circle).movement, 0.5f * read_circle.movement, 1e-5f);
  EXPECT_GT(running_sign_timing(circle, true, 0.0f, 1.0f, circle).movement, read_circle.movement);
}

// A repeated movement: each cycle at least 0.15 s (MUST's two strokes took 0.13 s each); the repeats
// are still faster than their citation time.
TEST(ProsodyTiming, EachCycleOfARepetitionLastsLongEnoughToBeSeen) {
  const float must = 1.63f, once = 0.63f;  // planner seconds: one stroke and its repeat
  const SignTiming t = running_sign_timing(must, false, 0.0f, 1.0f, once, 1);
  EXPECT_GE(t.movement, 2 * 0.15f - 1e-6f);
  EXPECT_LT(t.movement, must / 2.0f);
  const SignTiming three = running_sign_timing(must, false, 0.0f, 1.0f, once, 3);
  EXPECT_GE(three.movement, 4 * 0.15f - 1e-6f);
}

}  // namespace
}  // namespace gestura
