#include "gestura/sign/fingerspelling_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"
#include "gestura/sign/movement_timing.hpp"

namespace gestura {

namespace {

constexpr std::size_t kMaxInput = 256;
constexpr float kSlide = 0.04f;   // m, toward the dominant side (−X for a right-handed signer)
constexpr float kBounce = 0.015f;  // m, depth of the dip before a repeated letter

struct LetterInfo {
  bool known = false;
  bool has_movement = false;
};

LetterInfo info(ManualAlphabet alphabet, char c) {
  if (alphabet == ManualAlphabet::Asl) {
    const AslLetter* letter = find_asl_letter(c);
    return letter ? LetterInfo{true, letter->movement.has_value()} : LetterInfo{};
  }
  const BslLetter* letter = find_bsl_letter(c);
  return letter ? LetterInfo{true, letter->movement.has_value()} : LetterInfo{};
}

SourceLocation at(int index) {
  SourceLocation where;
  where.index = index;
  return where;
}

// "'ß' (U+00DF)"; control characters by their code alone.
std::string describe(char32_t cp) {
  char code[16];
  std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(cp));
  if (cp < 0x20 || cp == 0x7F) return code;
  std::string shown = "'";
  utf8::append(shown, cp);
  return cp < 0x80 ? shown + "'" : shown + "' (" + code + ")";
}

}  // namespace

float default_spelling_rate(ManualAlphabet alphabet, SpellingStyle style) {
  if (alphabet == ManualAlphabet::Asl) return style == SpellingStyle::Fluent ? 6.0f : 4.0f;
  return style == SpellingStyle::Fluent ? 5.0f : 3.5f;
}

SpellingPlan plan_spelling(std::string_view text, ManualAlphabet alphabet, SpellingStyle style,
                           const SpellingOptions& options) {
  if (text.size() > kMaxInput)
    throw Error("fingerspelling input has " + std::to_string(text.size()) + " characters; the limit is " +
                std::to_string(kMaxInput));
  const float rate = options.letters_per_second > 0.0f ? options.letters_per_second : default_spelling_rate(alphabet, style);
  if (!std::isfinite(rate) || rate > 20.0f || options.letters_per_second < 0.0f)
    throw Error("fingerspelling rate must be a positive number of letters per second up to 20");
  if (!(options.transition_fraction > 0.0f && options.transition_fraction < 1.0f) ||
      !(options.movement_letter_slots >= 1.0f && options.movement_letter_slots <= 4.0f) ||
      !(options.final_hold >= 0.0f && options.final_hold <= 2.0f) || !(options.word_pause >= 0.0f && options.word_pause <= 2.0f))
    throw Error("fingerspelling options out of range (transition fraction in (0,1), movement slots 1..4, holds 0..2 s)");

  SpellingPlan plan;
  plan.alphabet = alphabet;
  plan.letters_per_second = rate;
  const float slot = 1.0f / rate;
  float clock = 0.0f;
  int word = 0;
  bool in_word = false;
  float slide = 0.0f;
  int index = -1;  // of the character, counted in code points
  for (std::size_t pos = 0; pos < text.size();) {
    char32_t cp = 0;
    if (!utf8::decode(text, pos, cp)) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[pos])));
      throw Error(at(index + 1), std::string("cannot fingerspell byte ") + byte + " (the text is not UTF-8)");
    }
    ++index;
    // A letter with diacritics is spelled as its base letter (José as J-O-S-E); a combining accent
    // typed after its letter belongs to that letter.
    if (utf8::is_mark(cp)) continue;
    const char32_t base = utf8::base_letter(cp);
    const char c = base < 0x80 ? static_cast<char>(base) : '\0';
    if (c == ' ') {
      if (in_word) {
        plan.letters.back().end += options.final_hold;
        clock = plan.letters.back().end + options.word_pause;
        ++word;
        in_word = false;
        slide = 0.0f;
      }
      continue;
    }
    const LetterInfo letter = c ? info(alphabet, c) : LetterInfo{};
    if (!letter.known) {
      const char* allowed = alphabet == ManualAlphabet::Asl ? "A-Z and 0-9" : "A-Z";
      throw Error(at(index), "cannot fingerspell " + describe(cp) + " in " +
                                 (alphabet == ManualAlphabet::Asl ? "ASL" : "BSL") + " (letters " + allowed + ")");
    }
    LetterTarget target;
    target.letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    target.index = index;
    target.word = word;
    target.has_movement = letter.has_movement;
    const bool doubled = in_word && plan.letters.back().letter == target.letter;
    if (doubled) {
      const bool slide_it = alphabet == ManualAlphabet::Asl && !letter.has_movement;
      target.doubled = slide_it ? DoubleMark::Slide : DoubleMark::Bounce;
      if (slide_it) slide += kSlide;
    } else {
      slide = 0.0f;
    }
    target.offset = vec3{-slide, 0.0f, 0.0f};
    const float length = slot * (letter.has_movement ? options.movement_letter_slots : 1.0f);
    target.start = clock;
    // A moving letter's shape forms as fast as any other's; its extra slot goes to the movement.
    target.reached = clock + options.transition_fraction * slot;
    target.end = clock + length;
    target.movement_end = target.end;
    clock = target.end;
    plan.letters.push_back(target);
    in_word = true;
  }
  if (plan.letters.empty()) throw Error("fingerspelling input has no letters");
  if (in_word) plan.letters.back().end += options.final_hold;
  plan.duration = plan.letters.back().end;
  return plan;
}

SpellingSample sample_spelling(const SpellingPlan& plan, float time) {
  if (plan.letters.empty()) throw Error("cannot sample an empty fingerspelling plan");
  if (!std::isfinite(time)) time = 0.0f;
  const std::vector<LetterTarget>& letters = plan.letters;
  // The letter whose slot contains the time (the last one whose transition has started).
  std::size_t k = 0;
  while (k + 1 < letters.size() && time >= letters[k + 1].start) ++k;
  const LetterTarget& to = letters[k];
  SpellingSample out;
  out.to = static_cast<int>(k);
  // Between words the hand holds the last letter until the next word's first transition.
  const bool first_of_word = k == 0 || letters[k - 1].word != to.word;
  out.from = k == 0 ? -1 : static_cast<int>(k - 1);
  const float transition = to.reached - to.start;
  const float u = transition > 0.0f ? std::clamp((time - to.start) / transition, 0.0f, 1.0f) : 1.0f;
  out.blend = minimum_jerk(u);
  const vec3 previous_offset = k == 0 || first_of_word ? vec3{0.0f} : letters[k - 1].offset;
  out.offset = previous_offset + (to.offset - previous_offset) * out.blend;
  if (to.doubled == DoubleMark::Bounce) out.offset.y -= kBounce * std::sin(kPi * u);
  if (to.has_movement && to.movement_end > to.reached)
    out.movement_progress = std::clamp((time - to.reached) / (to.movement_end - to.reached), 0.0f, 1.0f);
  return out;
}

}  // namespace gestura
