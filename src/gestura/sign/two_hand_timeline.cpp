#include "gestura/sign/two_hand_timeline.hpp"

#include <algorithm>

#include "gestura/sign/movement_timing.hpp"

namespace gestura {

namespace {

constexpr float kSettleSeconds = 0.1f;  // added to a transition between postures
constexpr float kSyncTolerance = 1e-6f;  // seconds: clocks this close count as together

}  // namespace

float transition_time(const HandState& from, const HandState& to, float speed) {
  return (transition_duration(glm::distance(from.position, to.position)) + kSettleSeconds) / speed;
}

TwoHandTimeline::TwoHandTimeline(const ByHand<HandState>& start, float at, float min_segment)
    : state_(start), clock_{{at, at}}, min_segment_(min_segment) {}

void TwoHandTimeline::append(Hand hand, HandSegment segment) {
  segment.end = segment.start + std::max(segment.end - segment.start, min_segment_);
  place(hand, std::move(segment));
}

void TwoHandTimeline::place(Hand hand, HandSegment segment) {
  const float seconds = segment.end - segment.start;
  segment.start = clock_[hand];
  segment.end = clock_[hand] + seconds;
  clock_[hand] = segment.end;
  state_[hand] = segment.to;
  timeline_[hand].segments.push_back(std::move(segment));
}

void TwoHandTimeline::move_to(Hand hand, const HandState& to, float seconds) {
  HandSegment segment;
  segment.from = state_[hand];
  segment.to = to;
  segment.end = seconds;
  append(hand, std::move(segment));
}

void TwoHandTimeline::hold(Hand hand, float seconds) { move_to(hand, state_[hand], seconds); }

void TwoHandTimeline::hold_until(Hand hand, float t) {
  if (clock_[hand] >= t - kSyncTolerance) return;
  HandSegment segment;
  segment.from = segment.to = state_[hand];
  segment.end = t - clock_[hand];
  place(hand, std::move(segment));
  timeline_[hand].segments.back().end = clock_[hand] = t;  // exactly: the hands meet at one instant
}

void TwoHandTimeline::sync() {
  const float t = now();
  for (Hand hand : kBothHands) hold_until(hand, t);
}

void TwoHandTimeline::hold_both(float seconds) {
  sync();
  for (Hand hand : kBothHands) hold(hand, seconds);
}

void TwoHandTimeline::move_both_to(const ByHand<HandState>& to, float seconds) {
  sync();
  for (Hand hand : kBothHands) move_to(hand, to[hand], seconds);
}

void TwoHandTimeline::append_shifted(Hand hand, const HandTimeline& recorded, float at, float tempo) {
  hold_until(hand, at);
  for (HandSegment segment : recorded.segments) {
    segment.start = at + segment.start / tempo;
    segment.end = at + segment.end / tempo;
    clock_[hand] = segment.end;
    state_[hand] = segment.to;
    timeline_[hand].segments.push_back(std::move(segment));
  }
}

void TwoHandTimeline::end_last_at(Hand hand, const HandState& to) {
  timeline_[hand].segments.back().to = to;
  state_[hand] = to;
}

SignPlan TwoHandTimeline::finish(float sign_start, float sign_end) {
  SignPlan plan;
  plan.right = std::move(timeline_[Hand::Right]);
  plan.left = std::move(timeline_[Hand::Left]);
  plan.sign_start = sign_start;
  plan.sign_end = sign_end;
  timeline_ = {};
  return plan;
}

}  // namespace gestura
