#pragma once
// From the notation to a plan in space and time: what each hand does (HandTimeline) when one
// avatar (SigningRig) signs a parsed HamNoSys sign. The planner is three passes over plain data:
//
//   notation walker   sign → citation schedule: the hands' shapes, turns, named places, paths
//                     and timing, in the notation's order (notation_walker.hpp)
//   place resolver    named places → points on this avatar (place_resolver.hpp)
//   body repair       the body's say: keep-out, stops at the surface, detours, settling in
//                     space, the way to turn (body_repair.hpp)
//
// laid out in time by one TwoHandTimeline. plan_citation is the sign alone, from its first posture
// to the end of its last hold: what the sentence motion cache stores. plan_sign adds the way in
// from rest and back, for a sign performed on its own.
#include "gestura/sign/citation_schedule.hpp"
#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/notation_walker.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

struct PlanOptions {
  float speed = 1.0f;          // global tempo: 2 = twice as fast (0.25–4)
  bool from_rest = true;       // start with the hands at rest and move in
  bool to_rest = true;         // end by returning to rest
  float initial_hold = 0.10f;  // seconds each segment's first posture is held before its actions
  float final_hold = 0.20f;    // seconds the last posture is held
};

// The sign on its own: moved into from rest, and back to rest, as `options` say; sign_start and
// sign_end bracket the citation form. Throws gestura::Error for a speed outside 0.25–4, a sign
// without a manual part, notation it cannot perform (with the symbol index), and naming
// sign::kMaxSignSeconds for a citation form that would last longer (sign/sign_limits.hpp).
SignPlan plan_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& options = {});

// The sign in citation form: time 0 at its first posture (sign_start = 0), sign_end at the end of
// its final hold. Same errors as plan_sign.
SignPlan plan_citation(const sign::HamSign& sign, const SigningRig& rig, const ScheduleOptions& options = {});

// A schedule laid out on the rig: places resolved, the body's rules applied, timed. Throws
// gestura::Error for a schedule that does not start with a PostureStep (read_citation_schedule's
// all do), has no tempo, or would last longer than sign::kMaxSignSeconds.
SignPlan plan_schedule(const CitationSchedule& schedule, const SigningRig& rig);

// `citation` moved into from rest at its first posture and back to rest after its end, each hand
// over a transition (two_hand_timeline.hpp's transition_time at `speed`) that comes up in front of
// the body and goes round it; sign_start and sign_end are where the citation form lies.
SignPlan from_rest_to_rest(const SignPlan& citation, const SigningRig& rig, float speed, bool from_rest = true,
                           bool to_rest = true);

}  // namespace gestura
