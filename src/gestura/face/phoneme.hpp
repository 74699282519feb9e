#pragma once
// English phonemes as eSpeak NG writes them in its ASCII mnemonics (Kirshenbaum-like: "T" = θ,
// "D" = ð, "S" = ʃ, "Z" = ʒ, "N" = ŋ, "@" = ə, "3" = ɚ, "0" = ɒ/ɑ, "V" = ʌ, "oU" = oʊ, ...), with
// what the face needs to know about each: is it a vowel, which viseme shows it, how round the lips
// are, how open the jaw is, and how long it lasts relative to others.
#include <string>
#include <string_view>

namespace gestura::face {

enum class PhonemeClass { vowel, stop, nasal, fricative, affricate, approximant, pause };
enum class Stress { none, secondary, primary };

struct Phoneme {
  std::string symbol;        // eSpeak mnemonic without stress marks: "oU", "tS", "@"
  PhonemeClass cls = PhonemeClass::pause;
  Stress stress = Stress::none;
  float duration = 1.0f;     // relative; a stressed vowel is longer than a consonant
};

// Articulation of one phoneme. `viseme` is a name from face_channels.hpp; `transparent` phonemes
// (h) have no lip shape of their own and take the next phoneme's viseme.
struct Articulation {
  PhonemeClass cls = PhonemeClass::pause;
  std::string_view viseme;
  float rounding = 0.0f;     // 0 spread/neutral .. 1 fully rounded (ou, w)
  float jaw = 0.0f;          // 0 closed .. 1 fully open (aa)
  float base_duration = 0.6f;
  bool transparent = false;
};

// Unknown symbols fall back on their first character, then on a neutral "pause".
Articulation articulation(std::string_view symbol);

// Relative duration for a phoneme of this articulation and stress.
float relative_duration(const Articulation& a, Stress stress);

}  // namespace gestura::face
