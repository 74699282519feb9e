// The builder every hand timeline is made with: clocks per hand, holds, sync, shifted recordings.
#include <gtest/gtest.h>

#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

using namespace gestura;

namespace {

HandState at(float x, bool active = true) {
  HandState s;
  s.position = vec3(x, 1.0f, 0.2f);
  s.active = active;
  return s;
}

ByHand<HandState> both_at(float right, float left) { return ByHand<HandState>{{at(right), at(left)}}; }

// Segments of a timeline are contiguous: each starts where the one before ended, in time and state.
void expect_contiguous(const HandTimeline& t) {
  for (std::size_t i = 1; i < t.segments.size(); ++i) {
    EXPECT_FLOAT_EQ(t.segments[i].start, t.segments[i - 1].end) << "segment " << i;
    EXPECT_EQ(t.segments[i].from.position, t.segments[i - 1].to.position) << "segment " << i;
  }
}

}  // namespace

TEST(TwoHandTimeline, EachHandKeepsItsOwnClockUntilTheyMeet) {
  TwoHandTimeline t(both_at(-0.2f, 0.2f));
  t.move_to(Hand::Right, at(-0.1f), 0.5f);
  t.move_to(Hand::Left, at(0.1f), 0.2f);
  EXPECT_FLOAT_EQ(t.clock(Hand::Right), 0.5f);
  EXPECT_FLOAT_EQ(t.clock(Hand::Left), 0.2f);
  EXPECT_FLOAT_EQ(t.now(), 0.5f);
  t.sync();  // the left hand holds where it is until the right one is done
  EXPECT_FLOAT_EQ(t.clock(Hand::Left), 0.5f);
  const HandSegment& wait = t.timeline(Hand::Left).segments.back();
  EXPECT_FLOAT_EQ(wait.start, 0.2f);
  EXPECT_EQ(wait.from.position, wait.to.position);
  EXPECT_EQ(t.state(Hand::Left).position, at(0.1f).position);
  t.sync();  // in step: nothing more
  EXPECT_EQ(t.timeline(Hand::Left).segments.size(), 2u);
}

TEST(TwoHandTimeline, HoldBothWaitsForTheLaterHandFirst) {
  TwoHandTimeline t(both_at(-0.2f, 0.2f));
  t.move_to(Hand::Right, at(-0.1f), 0.3f);
  t.hold_both(0.2f);
  EXPECT_FLOAT_EQ(t.clock(Hand::Right), 0.5f);
  EXPECT_FLOAT_EQ(t.clock(Hand::Left), 0.5f);
  for (Hand h : kBothHands) expect_contiguous(t.timeline(h));
}

TEST(TwoHandTimeline, MinimumSegmentLengthensGivenLengthsButNotWaits) {
  TwoHandTimeline t(both_at(-0.2f, 0.2f), 0.0f, 1e-3f);
  t.hold(Hand::Right, 0.0f);  // a hold of no time still marks an instant
  EXPECT_FLOAT_EQ(t.clock(Hand::Right), 1e-3f);
  t.move_to(Hand::Left, at(0.1f), 0.5f);
  t.hold_until(Hand::Right, 0.5f + 4e-4f);  // waits end exactly where they are asked to
  EXPECT_FLOAT_EQ(t.clock(Hand::Right), 0.5f + 4e-4f);
  t.sync();
  EXPECT_FLOAT_EQ(t.clock(Hand::Left), t.clock(Hand::Right));
}

TEST(TwoHandTimeline, AppendShiftedPlacesARecordingOnTheClockAndScalesItsTime) {
  // A recording on its own clock: 0–0.4 s out to the side, 0.4–1.0 s back.
  HandTimeline recorded;
  HandSegment out, back;
  out.from = at(0.0f), out.to = at(0.1f), out.start = 0.0f, out.end = 0.4f;
  back.from = at(0.1f), back.to = at(0.0f), back.start = 0.4f, back.end = 1.0f;
  recorded.segments = {out, back};
  TwoHandTimeline t(both_at(0.0f, 0.3f));
  t.move_to(Hand::Right, at(0.0f), 0.25f);
  t.append_shifted(Hand::Right, recorded, 1.0f, 2.0f);  // waits until 1 s, plays twice as fast
  const auto& segs = t.timeline(Hand::Right).segments;
  ASSERT_EQ(segs.size(), 4u);  // the move, the wait, the recording's two segments
  EXPECT_FLOAT_EQ(segs[1].start, 0.25f);
  EXPECT_FLOAT_EQ(segs[1].end, 1.0f);
  EXPECT_FLOAT_EQ(segs[2].start, 1.0f);
  EXPECT_FLOAT_EQ(segs[2].end, 1.2f);
  EXPECT_FLOAT_EQ(segs[3].end, 1.5f);
  EXPECT_FLOAT_EQ(t.clock(Hand::Right), 1.5f);
  EXPECT_EQ(t.state(Hand::Right).position, at(0.0f).position);  // where the recording ends
  expect_contiguous(t.timeline(Hand::Right));
  EXPECT_TRUE(t.timeline(Hand::Left).segments.empty());  // the other hand is untouched
}

TEST(TwoHandTimeline, EndLastAtMovesTheEndOfTheLastSegment) {
  TwoHandTimeline t(both_at(-0.2f, 0.2f));
  t.move_to(Hand::Right, at(-0.1f), 0.3f);
  t.end_last_at(Hand::Right, at(-0.12f));
  EXPECT_EQ(t.timeline(Hand::Right).final_state().position, at(-0.12f).position);
  EXPECT_EQ(t.state(Hand::Right).position, at(-0.12f).position);
  t.move_to(Hand::Right, at(-0.2f), 0.3f);  // the next segment starts there
  EXPECT_EQ(t.timeline(Hand::Right).segments.back().from.position, at(-0.12f).position);
}

TEST(TwoHandTimeline, MoveBothToStartsTogetherAndFinishHandsOverThePlan) {
  TwoHandTimeline t(both_at(-0.2f, 0.2f));
  t.move_to(Hand::Left, at(0.25f), 0.1f);
  t.move_both_to(both_at(-0.3f, 0.3f), 0.4f);
  EXPECT_FLOAT_EQ(t.timeline(Hand::Right).segments.front().end, 0.1f);  // waited for the left hand
  EXPECT_FLOAT_EQ(t.now(), 0.5f);
  const SignPlan plan = t.finish(0.1f, 0.5f);
  EXPECT_FLOAT_EQ(plan.duration(), 0.5f);
  EXPECT_FLOAT_EQ(plan.sign_start, 0.1f);
  EXPECT_EQ(plan.hand(Hand::Left).final_state().position, at(0.3f).position);
}

TEST(TwoHandTimeline, TransitionTimeIsTheTransitionAndASettleAtTheTempo) {
  const HandState a = at(0.0f), b = at(0.3f);
  EXPECT_NEAR(transition_time(a, b, 1.0f), transition_duration(0.3f) + 0.1f, 1e-6f);
  EXPECT_NEAR(transition_time(a, b, 2.0f), 0.5f * transition_time(a, b, 1.0f), 1e-6f);
  EXPECT_NEAR(transition_time(a, a, 1.0f), transition_duration(0.0f) + 0.1f, 1e-6f);
}
