#pragma once
// What a signer's body does to the places and paths the notation asks for. Notation is written as
// if the hands could go anywhere; a signer's cannot:
//   - a hand never goes into the body: a place in it is moved out (keep_out), and a movement
//     toward the body from close to it stops at the surface (stop_at_surface);
//   - a path that would pass through the body bows out round it (detour_around_body), and a hand
//     rising from rest comes up in front of the body (come_up_in_front);
//   - a place out in the signing space is a region: the hand takes the place in it, nearest the
//     notated one, where the arm can make the notated turn (settle_in_space, settle_together);
//   - a large turn goes the way the forearm can follow (choose_turn_way).
// One pass per rule, over plain hand states and segments, on one avatar's collision body and
// reach. The planner applies them to every segment it makes (repair_end, repair_way).
#include <span>
#include <vector>

#include "gestura/sign/hand_geometry.hpp"

namespace gestura {

class BodyRepair {
 public:
  // Contract: `rig` outlives the pass.
  explicit BodyRepair(const SigningRig& rig);

  // Moves a planned state out of the body and marks whether the hand ends up at it
  // (HandState::at_body): within a finger's width of the collision body, or of a body site it
  // misses (the chin, the nose and the lips stand out of the capsules).
  void keep_out(Hand hand, HandState& state);

  // A movement that would take the hand deep into the body (notation asking for a movement toward
  // or across the body from a place already close to it) stops where it meets the surface, on
  // the side it came from.
  void stop_at_surface(Hand hand, const HandState& from, HandState& to);

  // A place out in the signing space is a region: the hand takes the place nearest the notated
  // one where the arm makes the notated turn, keeping to its side of the body and, when it ends a
  // `movement`, not giving way against it by more than half of it, and staying out in space (not
  // coming to the body, or near a site, where it would be a hand at a place the notation did not
  // name). A hand at the body, or held to the other hand (settle_together moves such pairs), stays.
  void settle_in_space(Hand hand, HandState& state, const HandState& other, const vec3& movement = vec3(0.0f));
  // The same for both hands of a posture: hands held together out in space move together. Only
  // the hands the posture places (`posed`) move.
  void settle_together(ByHand<HandState>& states, const ByHand<bool>& posed);

  // A path that would take the hand through the body bows out round it (HandSegment::detour), by
  // the smallest amount that keeps the hand along the way as far off the body as its ends are.
  void detour_around_body(Hand hand, HandSegment& segment);
  // A hand rising from rest (or sinking back to it) travels in front of the body, not straight up
  // its side.
  static void come_up_in_front(HandSegment& segment);
  // A large turn goes the long way round when the short way passes a forearm twist or wrist bend
  // the arm cannot make (HandSegment::long_turn).
  void choose_turn_way(Hand hand, HandSegment& segment);

  // The rules for a segment's end: stop at the surface, keep out.
  void repair_end(Hand hand, HandSegment& segment);
  // The rules for its way: detour, coming up in front, the way to turn (the detour judged again
  // for a hand that turns the long way, whose fingers sweep elsewhere).
  void repair_way(Hand hand, HandSegment& segment);

  // How far the hand's nearest point is from the body with its palm centre at `at`, for hand
  // points relative to the palm centre (planned_hand_points).
  float clearance(std::span<const vec3> points, const vec3& at) const;

 private:
  bool near_a_body_site(std::span<const vec3> points, const vec3& at) const;
  // Whether a hand with its palm centre at `at` is at the body, as keep_out marks it: within
  // kAtBody of the collision body (past the planned clearance) or near a body site.
  bool at_the_body(std::span<const vec3> points, const vec3& at) const;

  const SigningRig& rig_;
  Pose scratch_;
  std::vector<vec3> body_site_points_;  // bind-pose positions of the sites on the head and trunk
  HandTimeline one_segment_;            // scratch for sampling a segment alone
};

}  // namespace gestura
