#pragma once
// The spelling planner: a word → timed letter targets for the ASL or BSL manual alphabet.
//
// Rate (our choice, reasoning in docs/sign-phonology.md): fluent ASL fingerspelling of familiar
// words runs at roughly 5–7 letters per second; we use 6 letters/s (a letter every ~167 ms).
// Names and unfamiliar words are spelled more carefully: 4 letters/s. BSL letters are two-handed
// and the dominant hand travels between contact sites, so its fluent default is 5 letters/s.
// Each letter's slot is split into a transition (45 %) and a hold (55 %); letters with their own
// movement (ASL J, Z; BSL H, J) take two slots, formed in one slot's transition and moving for
// the rest; the last letter of a word is held 0.25 s longer, and words are separated by a 0.35 s
// pause.
#include <cstdint>
#include <string_view>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

enum class ManualAlphabet : std::uint8_t { Asl, Bsl };
enum class SpellingStyle : std::uint8_t { Fluent, Careful };

struct SpellingOptions {
  float letters_per_second = 0.0f;  // 0 = the alphabet/style default (ASL 6 or 4, BSL 5 or 3.5)
  float transition_fraction = 0.45f;
  float movement_letter_slots = 2.0f;
  float final_hold = 0.25f;
  float word_pause = 0.35f;
};

// How a doubled letter (the same letter twice in a row within a word) is marked.
enum class DoubleMark : std::uint8_t {
  None,    // not doubled
  Slide,   // ASL, static letters: the repeat slides 4 cm toward the dominant side
  Bounce,  // ASL letters with movement, and BSL: the hand dips 1.5 cm and re-forms the letter
};

struct LetterTarget {
  char letter = 0;         // upper-case letter or digit
  int index = 0;           // position of the character in the input (0-based)
  int word = 0;            // which word (0-based)
  float start = 0.0f;      // the transition into this letter begins (s)
  float reached = 0.0f;    // the configuration is reached; the hold (or the letter's movement) begins
  float end = 0.0f;        // the next transition begins
  DoubleMark doubled = DoubleMark::None;
  vec3 offset{0.0f};       // displacement of the hand from the spelling location (slides accumulate)
  bool has_movement = false;
  float movement_end = 0.0f;  // letters with movement: it runs over [reached, movement_end]
};

struct SpellingPlan {
  ManualAlphabet alphabet = ManualAlphabet::Asl;
  float letters_per_second = 0.0f;
  std::vector<LetterTarget> letters;
  float duration = 0.0f;  // end of the last hold
};

float default_spelling_rate(ManualAlphabet alphabet, SpellingStyle style);

// Throws gestura::Error (with the character index) for characters outside the alphabet (ASL: A–Z,
// a–z, 0–9; BSL: A–Z, a–z), and for empty input, input over 256 characters, or a bad rate.
// Spaces separate words.
SpellingPlan plan_spelling(std::string_view text, ManualAlphabet alphabet,
                           SpellingStyle style = SpellingStyle::Fluent, const SpellingOptions& options = {});

// The state of the spelling hand at a time: which letter it is leaving and which it is forming,
// the minimum-jerk blend between their configurations, the progress of the current letter's own
// movement, and the hand's displacement (slides blend with the configuration; a bounce dips
// 1.5 cm, sin-shaped, during the transition into the repeated letter).
struct SpellingSample {
  int from = -1;  // index into plan.letters of the letter being left; −1 before the first letter
  int to = 0;     // index of the letter being formed or held
  float blend = 0.0f;  // 0 = `from`'s configuration (or the rest before the first), 1 = `to`'s
  float movement_progress = 0.0f;  // 0..1 for letters with movement, else 0
  vec3 offset{0.0f};
};
// Times before the plan hold the first transition's start, after it the last letter's end.
// Throws gestura::Error for an empty plan.
SpellingSample sample_spelling(const SpellingPlan& plan, float time);

}  // namespace gestura
