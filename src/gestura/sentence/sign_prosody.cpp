#include "gestura/sentence/sign_prosody.hpp"

#include <algorithm>

namespace gestura {

SignTiming running_sign_timing(float citation_movement, bool phrase_final, float extra_hold, float speed,
                               float citation_once, int repeats) {
  SignTiming t;
  t.tempo = speed * kRunningTempo / (phrase_final ? kPhraseFinalSlowing : 1.0f);
  const float effective = std::min(citation_movement, kLongMovementSeconds) +
                          0.5f * std::max(0.0f, citation_movement - kLongMovementSeconds);
  t.movement = effective / t.tempo;
  // Readable: not below a share of one movement's citation time, slowed at the end of a phrase too.
  const float slowing = phrase_final ? kPhraseFinalSlowing : 1.0f;
  t.movement = std::max(t.movement, kMinRunningShare * std::min(citation_once, citation_movement) * slowing / speed);
  if (repeats > 0 && citation_movement > 0.0f)
    t.movement = std::max(t.movement, kMinRepeatCycleSeconds * static_cast<float>(1 + repeats) * slowing / speed);
  // One uniform time scale for the whole movement (the plan's segments and the cached motion are
  // both mapped with it), so a long movement is played faster rather than cut.
  if (citation_movement > 0.0f) t.tempo = citation_movement / t.movement;
  t.initial_hold = kInitialHold / speed;
  t.final_hold = (phrase_final ? std::max(kFinalHold, kPhraseFinalHold) : kFinalHold) / speed;
  // A short sign is held, not rushed: the missing time goes to the final hold, where the hand
  // rests in the sign's last posture (a static sign is one held posture).
  const float minimum = (phrase_final ? kMinPhraseFinalSeconds : kMinSignSeconds) / speed;
  t.final_hold += std::max(0.0f, minimum - t.span());
  t.final_hold += extra_hold / speed;
  return t;
}

SignTiming recorded_sign_timing(float recorded_seconds, bool phrase_final, float extra_hold, float speed) {
  SignTiming t;
  t.tempo = speed / (phrase_final ? kPhraseFinalSlowing : 1.0f);
  t.movement = recorded_seconds / t.tempo;
  t.final_hold = phrase_final ? kPhraseFinalHold / speed : 0.0f;
  const float minimum = (phrase_final ? kMinPhraseFinalSeconds : kMinSignSeconds) / speed;
  t.final_hold += std::max(0.0f, minimum - t.span());
  t.final_hold += extra_hold / speed;
  return t;
}

}  // namespace gestura
