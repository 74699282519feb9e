#pragma once
// What one hand does over time, in the signer's space: a sequence of segments, each taking the hand
// from one state to the next with a minimum-jerk profile, optionally along a movement path
// (displacement added to the straight blend) and with oscillations of the wrist or fingers on top.
#include <algorithm>
#include <optional>
#include <vector>

#include "gestura/sign/hand.hpp"
#include "gestura/sign/movement_path.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

// Where the hand is, how it is turned and what shape it has.
struct HandState {
  vec3 position{0.0f};        // the palm centre, model space (metres)
  quat orientation{1, 0, 0, 0};  // hand frame: local +Y fingers, +Z palm normal (HandFrame::rotation)
  HandPosture shape;
  bool active = false;        // false: the hand rests at the side
  // The hand is at (or within a finger's width of) the body: its place is a point a signer
  // keeps. A place out in the signing space is a region, and the hand may give way a little
  // there to take the notated turn.
  bool at_body = false;
  // Sampled states only (sample_hand): how far the hand has settled onto the body, 0..1. It rises
  // over the last kSettleTime of an approach to the body and falls over the first of a departure,
  // so what the solver does differently at the body (the contact point kept in place, the turn
  // weighed less) eases in and out instead of switching in one frame.
  float body_weight = 0.0f;
};

// Seconds over which a hand arriving at (leaving) the body settles onto (off) it.
constexpr float kSettleTime = 0.15f;

// Oscillations performed on top of a segment.
enum class Oscillation : std::uint8_t { None, Nod, Swing, Twist, FingerPlay };

struct HandSegment {
  float start = 0.0f, end = 0.0f;  // seconds
  HandState from, to;
  std::vector<Movement> paths;     // displacements summed on top of the from→to blend (fused motions);
                                   // `to.position` already includes where they end
  Oscillation oscillation = Oscillation::None;
  float oscillation_cycles = 0.0f;
  FingerSet oscillating_fingers = 0;
  bool linear_blend = false;       // blend from→to at constant speed (paths drive the timing instead)
  vec3 detour{0.0f};               // the path bows out by this much halfway (sin π·progress), to pass
                                   // around the body instead of through it
  bool long_turn = false;          // turn from → to the long way round (the short way passes a
                                   // forearm twist or wrist bend beyond the arm's range)
};

struct HandTimeline {
  std::vector<HandSegment> segments;  // contiguous, increasing in time
  float end_time() const { return segments.empty() ? 0.0f : segments.back().end; }
  const HandState& final_state() const { return segments.back().to; }
};

// What both hands do: the dominant (right) and the non-dominant (left) hand's timelines.
struct SignPlan {
  HandTimeline right, left;
  float sign_start = 0.0f;  // when the hands reach the initial posture
  float sign_end = 0.0f;    // when the final hold ends (before any return to rest)
  float duration() const { return std::max(right.end_time(), left.end_time()); }
  HandTimeline& hand(Hand h) { return h == Hand::Right ? right : left; }
  const HandTimeline& hand(Hand h) const { return h == Hand::Right ? right : left; }
};

// The hand's state at time t (clamped to the timeline). Contract: the timeline is not empty.
HandState sample_hand(const HandTimeline& timeline, float t);

// The hand's turn a fraction `s` of the way from `from` to `to`, the short or the long way round.
quat blend_turn(const quat& from, const quat& to, float s, bool long_way);

}  // namespace gestura
