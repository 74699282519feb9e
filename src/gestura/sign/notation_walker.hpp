#pragma once
// Reading a parsed HamNoSys sign into its citation schedule (citation_schedule.hpp): what each
// hand does, in the notation's order and timing, without a body. The walker reads like the
// notation: each manual segment's posture sets handshape, orientation and location per hand
// (symmetry operators give the other hand a copy of the dominant hand's, mirrored or parallel; a
// dominant hand placed on the other hand makes that hand a base); then each action — movements,
// replacements, contacts, repetitions, simultaneous and fused groups, the two hands' separate
// branches — becomes steps for the hands it drives. The dominant hand is the right hand.
//
// No rest: the schedule starts at the first posture and ends with the last hold. How a sign is
// entered and left (from rest, or from the previous sign of a sentence) is the caller's.
#include "gestura/sign/citation_schedule.hpp"
#include "gestura/sign/hamnosys_model.hpp"

namespace gestura {

struct ScheduleOptions {
  float speed = 1.0f;          // tempo: 2 = twice as fast
  float posture_hold = 0.10f;  // seconds each segment's posture is held before its actions
  float final_hold = 0.20f;    // seconds the last posture is held
};

// Contract: speed > 0. Does not throw for any parsed sign.
CitationSchedule read_citation_schedule(const sign::HamSign& sign, const ScheduleOptions& options = {});

// The hand posture a notated handshape makes (its basic form, thumb and bendings).
HandPosture hand_posture_of(const sign::HandshapeForm& form);
// hambetween: halfway between the two forms.
HandPosture hand_posture_of(const sign::Handshape& handshape);

}  // namespace gestura
