#pragma once
// The hand on a rig as the planner and the performer see it: one set of points on its surface (both faces
// of the palm, the five fingertips, the four finger knuckles, the five middle joints) that the
// planner keeps off the body and puts at the places the notation names, and the performer
// measures on the posed skeleton. One set, so that what is planned clear of the body is what is
// measured clear of it.
#include <array>
#include <cstddef>
#include <span>

#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

inline constexpr std::size_t kHandPointCount = 16;
using HandPoints = std::array<vec3, kHandPointCount>;
// Where each kind of point starts in HandPoints.
inline constexpr std::size_t kPalmFacePoints = 0;    // the palm's side, then the back of the hand
inline constexpr std::size_t kTipPoints = 2;         // thumb .. little finger
inline constexpr std::size_t kKnucklePoints = 7;     // index .. little finger, at their base joints
inline constexpr std::size_t kMiddleJointPoints = 11;  // thumb .. little finger (thumb2, index2, …)

// The points in model space for posed joints (`model`: local_to_model of the pose).
void hand_surface_points(const SigningRig& rig, Hand hand, std::span<const mat4> model, HandPoints& out);

// The points of a planned hand state relative to its palm centre, in the signer's frame: the
// state's shape posed on the rig's fingers (in `scratch`, a pose of the rig's skeleton, clamped
// into the joint limits as the performer will) and turned as the state is turned.
HandPoints planned_hand_points(const SigningRig& rig, Hand hand, const HandState& state, Pose& scratch);

// How deep the hand's deepest point lies inside the collision body for posed joints (metres;
// negative: that far clear of it). `points` is scratch.
float hand_penetration(const SigningRig& rig, Hand hand, std::span<const mat4> model, HandPoints& points);

// The hand resting at the side, arm hanging (the rig's bind pose): where a sign starts and ends.
HandState rest_hand_state(const SigningRig& rig, Hand hand);
// The hand as it is in the rig's relaxed signing posture (rig.neutral: low, in front), active:
// where a hand waits between signs of a sentence.
HandState relaxed_hand_state(const SigningRig& rig, Hand hand);

// The model-space rotation of the wrist that turns the hand as `state` plans (HandState::orientation).
quat planned_wrist_rotation(const SigningRig& rig, Hand hand, const HandState& state);

}  // namespace gestura
