#pragma once
// How long a sign lasts in citation form, from what its notation contains (docs/sign-phonology.md,
// "Timing"): the holds at its start and end, each movement by its kind and size, repetitions
// (fast, each shorter than the one before), contact, and the manner written with a movement.
//
// The model follows the movement–hold description of signs (Liddell & Johnson 1989: a sign is holds
// and movements in sequence) and is scaled so that the built-in lexicon's median lies at ASL-LEX
// 2.0's median citation duration, 834 ms (IQR 634–1,034 ms over 2,723 signs; Sehyr et al. 2021).
// It is a pure function of the parsed notation: the planner may use it to time a sign, and the
// lexicon's distribution can be compared with the published one (tests/sign/citation_timing_test.cpp).
#include <vector>

#include "gestura/sign/hamnosys_model.hpp"

namespace gestura {

// The model's constants, seconds.
inline constexpr float kTimingHolds = 0.34f;          // first posture reached and settled + final hold
inline constexpr float kTimingStraight = 0.34f;       // one straight path movement, normal size
inline constexpr float kTimingCircle = 0.52f;         // one circle, normal size
inline constexpr float kTimingLocal = 0.39f;          // a wrist or finger movement (nod, twist, wiggle) as a set
inline constexpr float kTimingChange = 0.24f;         // a change of handshape or orientation in place
inline constexpr float kTimingContact = 0.07f;        // slowing into a contact
inline constexpr float kTimingRepeatShare = 0.62f;    // the first repeat takes this share of the movement
inline constexpr float kTimingRepeatDecay = 0.85f;    // each further repeat this share of the one before
inline constexpr float kTimingStaticMinimum = 0.60f;  // a sign without movement is held this long
inline constexpr float kTimingCompoundShare = 0.80f;  // each segment of a compound (compounds shorten)

struct CitationTiming {
  float seconds = 0.0f;      // the whole citation form
  float holds = 0.0f;        // initial and final holds (or the static minimum)
  float movement = 0.0f;     // the movements once each
  float repetition = 0.0f;   // the repeats
  float contact = 0.0f;
  int movements = 0;         // path, local and change movements counted
  std::vector<float> repeats;  // seconds of each repeat, in order (each shorter than the one before)
  bool is_static = false;    // no movement at all

  float moving() const { return movement + repetition + contact; }  // the sign without its holds
};

// Contract: a sign the parser produced (at least one segment).
CitationTiming citation_timing(const sign::HamSign& sign);

}  // namespace gestura
