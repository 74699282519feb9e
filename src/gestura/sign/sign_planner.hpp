#pragma once
// From the notation to a plan in space and time: turns a parsed HamNoSys sign into what each hand
// does (HandTimeline), on a particular avatar (SigningRig). The planner reads like the notation:
// the initial posture sets handshape, orientation and location; then each action of the sign —
// movements, replacements, contacts, repetitions, simultaneous and fused groups, the two hands'
// separate branches — extends the timelines. The dominant hand is the right hand; symmetry
// operators give the other hand a mirrored (or parallel) copy of the dominant hand's actions.
#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

struct PlanOptions {
  float speed = 1.0f;          // global tempo: 2 = twice as fast (0.25–4)
  bool from_rest = true;       // start with the hands at rest and move in
  bool to_rest = true;         // end by returning to rest
  float initial_hold = 0.10f;  // seconds the first posture is held before the movement
  float final_hold = 0.20f;    // seconds the last posture is held
};

struct SignPlan {
  HandTimeline right, left;    // the dominant (right) and non-dominant (left) hand
  float sign_start = 0.0f;     // when the hands reach the initial posture
  float sign_end = 0.0f;       // when the final hold ends (before the return to rest)
  float duration() const { return std::max(right.end_time(), left.end_time()); }
};

// Throws gestura::Error (with the symbol index) for notation it cannot perform, and naming
// sign::kMaxSignSeconds for a sign that would last longer (sign/sign_limits.hpp).
SignPlan plan_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& options = {});

// The hand states at rest (arms hanging), used before and after signing.
HandState rest_hand_state(const SigningRig& rig, Hand hand);

// Helpers the planner is built from, exposed for tests and for sentence-level planning.
HandPosture hand_posture_of(const sign::HandshapeForm& form);
HandPosture hand_posture_of(const sign::Handshape& handshape);

}  // namespace gestura
