#pragma once
// Fingerspelling performed by the hands: a spelling plan (sign/fingerspelling_plan.hpp) becomes what
// each hand does over time (HandTimeline) on one avatar. The Signer uses the timelines for the
// fingerspelled words of a sentence; `gestura fingerspell` performs a whole text alone, from rest to
// rest, with the eyes on the spelling hand.
//
// ASL (one-handed): the dominant (right) hand forms each letter 30 cm in front of and 8 cm below its
// shoulder; the other hand rests. J and Z trace their letters after the shape is formed (J: the I
// hand drops and hooks toward the midline while the forearm supinates, so the little finger draws
// the J; Z: the index hand draws a Z with stops at the corners). A doubled static letter slides 4 cm
// toward the dominant side; a doubled moving letter dips 1.5 cm on its way back to the start.
//
// BSL (two-handed): the non-dominant (left) hand presents its configuration in front of the chest
// at the midline, turned 30° toward the dominant side; the dominant hand forms its configuration
// and puts the part of it that touches (index tip, finger pads, fist, ...) on the letter's site of
// the non-dominant hand (a fingertip, the palm, the index, ...), found from the two hands' actual
// finger geometry on this avatar. One-handed C leaves the non-dominant hand where it was. H
// brushes and J traces after the contact. A doubled letter taps twice: the dominant hand lifts
// 2 cm off the site and comes back.
//
// Time: each letter's transition, hold and movement are the plan's, divided by `speed`; the gap
// between words is held.
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"
#include "gestura/sign/sign_planner.hpp"

namespace gestura {

// The hands spelling a plan. Time 0 is the moment the first letter is formed (how the hands get
// there is the caller's: from rest, or from the previous sign of a sentence).
struct SpelledHands {
  HandTimeline right, left;           // dominant, non-dominant; both end at `duration`
  std::vector<LetterTarget> letters;  // the plan's letters with times on this clock
  float duration = 0.0f;              // end of the last letter's hold

  const HandTimeline& hand(Hand h) const { return h == Hand::Right ? right : left; }
  const HandState& first(Hand h) const { return hand(h).segments.front().from; }
};

// Contract: rig built for the avatar that will perform. Throws gestura::Error for an empty plan or
// a speed outside 0.25–4.
SpelledHands spell_with_hands(const SpellingPlan& plan, const SigningRig& rig, float speed = 1.0f);

struct FingerspellingOptions {
  float speed = 1.0f;  // 0.25–4, scales every time (approach, letters, return)
  float fps = 30.0f;
  bool gaze = true;    // eyes on the spelling hand while spelling (face/eye_gaze.hpp)
};

struct FingerspellingPerformance {
  Clip clip;                          // on rig.skeleton(): arms, fingers, gaze_hands channel, eyes
  std::vector<LetterTarget> letters;  // letter times on the clip's clock
  float spelling_start = 0.0f;        // the first letter is formed
  float spelling_end = 0.0f;          // the last letter's hold ends; then the hands return to rest
};

// The whole text alone: hands from rest to the first letter, the letters, back to rest.
// Throws gestura::Error for an empty plan, speed outside 0.25–4 or fps outside 1–240.
FingerspellingPerformance perform_fingerspelling(const SpellingPlan& plan, const SigningRig& rig,
                                                 const FingerspellingOptions& options = {});

}  // namespace gestura
