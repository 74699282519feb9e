#pragma once
// Where in the signing space an arm can turn the hand as notated. A place out in space is a
// region, not a point: a signer holding the fingers straight up raises the hand, one turning the
// palm in brings it closer. The planner asks for the nearest place to the notated one from which
// the arm makes the turn within its joint ranges, judged by the analytic swivel arm (the clavicle
// relaxed, as the hand solver seeds it).
#include <functional>
#include <span>

#include "gestura/sign/signing_rig.hpp"

namespace gestura {

// Radians the analytic arm has to clamp (shoulder and elbow ×4, as they move the hand; forearm
// twist and wrist) to put the palm centre of `hand` at `palm_position` turned to `orientation`
// (hand frame, HandState::orientation). 0 when the joint ranges allow it.
float arm_reach_excess(const SigningRig& rig, Hand hand, const vec3& palm_position, const quat& orientation);

// A hand's place and turn (HandState position and orientation).
struct HandTurn {
  Hand hand = Hand::Right;
  vec3 palm{0.0f};
  quat orientation{1, 0, 0, 0};
};

struct ReachableShift {
  vec3 offset{0.0f};    // to add to every hand's place
  float excess = 0.0f;  // arm_reach_excess there, summed over the hands
};

// The smallest shift within `max_shift` metres (searched on shells 3 cm apart, 26 directions
// each), moving all `hands` together (hands held to each other stay so), after which their
// summed arm_reach_excess is below `settled` radians; when there is none, the one that trades
// excess against distance best (a radian of clamped turn weighs like 25 cm, as in the hand
// solver). No shift when the hands are already settled. Shifts for which `allowed` (when given)
// is false are passed over: the planner keeps hands out in space clear of the body.
ReachableShift nearest_reachable_shift(const SigningRig& rig, std::span<const HandTurn> hands, float max_shift,
                                       float settled, const std::function<bool(const vec3&)>& allowed = {});

}  // namespace gestura
