#pragma once
// Building what both hands do over time, one segment at a time. Each hand has its own clock: a
// segment starts where the hand's last one ended, from the state it left the hand in. The hands
// meet again at sync(): the hand that is behind holds until the other catches up.
//
//   TwoHandTimeline t(ByHand<HandState>{rest_right, rest_left});
//   t.move_to(Hand::Right, first_posture, transition_time(rest_right, first_posture, speed));
//   t.sync();                                  // the left hand holds at rest meanwhile
//   t.append_shifted(Hand::Right, cached.right, t.now(), tempo);  // a sign recorded on its own clock
//   t.hold_both(0.2f);
//   SignPlan plan = t.finish(sign_start, sign_end);
//
// Every builder of hand timelines uses it: the sign planner (a sign from its notation), the Signer
// (signs and fingerspelled words joined into an utterance), the fingerspelling performance and the
// sentence motion cache (a citation form approached from the relaxed posture).
#include "gestura/sign/hand.hpp"
#include "gestura/sign/hand_timeline.hpp"

namespace gestura {

// How long a hand takes to move from one state to another between the postures of a sign, at a
// tempo (2 = twice as fast): a transition over the distance (movement_timing.hpp) and 0.1 s to
// settle. Single signs enter from rest and leave to it at this pace, and so does fingerspelling.
float transition_time(const HandState& from, const HandState& to, float speed);

class TwoHandTimeline {
 public:
  // The hands start in `start`, both clocks at `at` seconds. Segments given a length shorter than
  // `min_segment` seconds are lengthened to it (the planner's zero-second holds still take a
  // millisecond, so a timeline is never empty); holds that wait for a time (hold_until, sync)
  // end exactly there.
  explicit TwoHandTimeline(const ByHand<HandState>& start, float at = 0.0f, float min_segment = 0.0f);

  float clock(Hand hand) const { return clock_[hand]; }
  // The later hand's clock: when both hands have done what they were given.
  float now() const { return std::max(clock_[Hand::Right], clock_[Hand::Left]); }
  const HandState& state(Hand hand) const { return state_[hand]; }
  const HandTimeline& timeline(Hand hand) const { return timeline_[hand]; }

  // Appends `segment` (its `from` is the hand's state; its length is end − start) at the hand's clock.
  void append(Hand hand, HandSegment segment);
  // From the hand's state to `to` in `seconds`, minimum-jerk, straight.
  void move_to(Hand hand, const HandState& to, float seconds);
  void hold(Hand hand, float seconds);
  // Holds the hand until its clock reads `t` exactly (nothing when it is there already, or less
  // than a microsecond short of it).
  void hold_until(Hand hand, float t);
  // The hand that is behind holds until the other's clock: the clocks read the same afterwards.
  void sync();
  // sync(), then both hands hold for `seconds`.
  void hold_both(float seconds);
  // Both hands to `to` together, starting at now(), in `seconds`.
  void move_both_to(const ByHand<HandState>& to, float seconds);
  // Appends a timeline recorded on its own clock (a cached sign, spelled letters): its time 0 falls
  // at `at` (the hand holds until then) and its times are divided by `tempo`. The hand is left in
  // its final state. Contract: `at` >= the hand's clock; `recorded` starts at time 0.
  void append_shifted(Hand hand, const HandTimeline& recorded, float at, float tempo = 1.0f);
  // Changes where the hand's last segment ends (and so the hand's state): the planner settles two
  // hands' ends together once both have moved. Contract: the hand has a segment.
  void end_last_at(Hand hand, const HandState& to);

  // The timelines as a plan; the builder is left empty.
  SignPlan finish(float sign_start, float sign_end);

 private:
  void place(Hand hand, HandSegment segment);  // at the hand's clock, as long as it is

  ByHand<HandTimeline> timeline_;
  ByHand<HandState> state_;
  ByHand<float> clock_;
  float min_segment_;
};

}  // namespace gestura
