#include "gestura/face/phoneme.hpp"

#include <array>

#include "gestura/face/face_channels.hpp"

namespace gestura::face {
namespace {

struct Entry {
  std::string_view symbol;
  Articulation a;
};

using C = PhonemeClass;

// Durations: short consonants ~0.5–0.7, lax vowels 1.0, tense/long vowels 1.3, diphthongs 1.5
// (relative proportions of English segment durations; stress scales vowels further).
// Jaw: aa fully open, mid vowels ~0.5, close vowels ~0.25, labial closure 0.
constexpr std::array kTable{
    // consonants
    Entry{"p", {C::stop, kPP, 0, 0, 0.5f}}, Entry{"b", {C::stop, kPP, 0, 0, 0.5f}},
    Entry{"m", {C::nasal, kPP, 0, 0, 0.6f}},
    Entry{"f", {C::fricative, kFF, 0, 0.1f, 0.7f}}, Entry{"v", {C::fricative, kFF, 0, 0.1f, 0.6f}},
    Entry{"T", {C::fricative, kTH, 0, 0.15f, 0.7f}}, Entry{"D", {C::fricative, kTH, 0, 0.15f, 0.5f}},
    Entry{"t", {C::stop, kDD, 0, 0.15f, 0.5f}}, Entry{"d", {C::stop, kDD, 0, 0.15f, 0.5f}},
    Entry{"t#", {C::stop, kDD, 0, 0.15f, 0.35f}}, Entry{"*", {C::stop, kDD, 0, 0.15f, 0.35f}},
    Entry{"k", {C::stop, kKK, 0, 0.2f, 0.5f}}, Entry{"g", {C::stop, kKK, 0, 0.2f, 0.5f}},
    Entry{"N", {C::nasal, kKK, 0, 0.2f, 0.6f}}, Entry{"x", {C::fricative, kKK, 0, 0.2f, 0.7f}},
    Entry{"?", {C::stop, kSil, 0, 0.1f, 0.3f}},
    Entry{"h", {C::fricative, kSil, 0, 0.2f, 0.5f, true}},
    Entry{"tS", {C::affricate, kCH, 0.5f, 0.1f, 0.8f}}, Entry{"dZ", {C::affricate, kCH, 0.5f, 0.1f, 0.7f}},
    Entry{"S", {C::fricative, kCH, 0.5f, 0.1f, 0.8f}}, Entry{"Z", {C::fricative, kCH, 0.5f, 0.1f, 0.7f}},
    Entry{"s", {C::fricative, kSS, 0, 0.05f, 0.8f}}, Entry{"z", {C::fricative, kSS, 0, 0.05f, 0.7f}},
    Entry{"n", {C::nasal, kNN, 0, 0.15f, 0.6f}}, Entry{"l", {C::approximant, kNN, 0, 0.2f, 0.6f}},
    Entry{"r", {C::approximant, kRR, 0.3f, 0.2f, 0.6f}}, Entry{"w", {C::approximant, kOU, 1.0f, 0.15f, 0.5f}},
    Entry{"j", {C::approximant, kIH, 0, 0.2f, 0.5f}},
    // vowels
    Entry{"a", {C::vowel, kAA, 0, 1.0f, 1.0f}}, Entry{"a#", {C::vowel, kAA, 0, 0.9f, 1.0f}},
    Entry{"A:", {C::vowel, kAA, 0, 1.0f, 1.3f}}, Entry{"A", {C::vowel, kAA, 0, 1.0f, 1.1f}},
    Entry{"A@", {C::vowel, kAA, 0.2f, 0.9f, 1.4f}}, Entry{"aI", {C::vowel, kAA, 0, 0.9f, 1.5f}},
    Entry{"aU", {C::vowel, kAA, 0.5f, 0.9f, 1.5f}}, Entry{"V", {C::vowel, kAA, 0, 0.7f, 1.0f}},
    Entry{"E", {C::vowel, kE, 0, 0.5f, 1.0f}}, Entry{"e", {C::vowel, kE, 0, 0.5f, 1.0f}},
    Entry{"eI", {C::vowel, kE, 0, 0.5f, 1.5f}}, Entry{"e@", {C::vowel, kE, 0, 0.55f, 1.4f}},
    Entry{"@", {C::vowel, kE, 0, 0.35f, 0.6f}}, Entry{"@2", {C::vowel, kE, 0, 0.35f, 0.5f}},
    Entry{"@5", {C::vowel, kE, 0, 0.35f, 0.5f}}, Entry{"@L", {C::vowel, kNN, 0, 0.3f, 0.8f}},
    Entry{"3", {C::vowel, kRR, 0.3f, 0.35f, 0.8f}}, Entry{"3:", {C::vowel, kRR, 0.3f, 0.4f, 1.3f}},
    Entry{"I", {C::vowel, kIH, 0, 0.25f, 0.9f}}, Entry{"I2", {C::vowel, kIH, 0, 0.25f, 0.7f}},
    Entry{"I#", {C::vowel, kIH, 0, 0.25f, 0.7f}}, Entry{"i", {C::vowel, kIH, 0, 0.25f, 0.9f}},
    Entry{"i:", {C::vowel, kIH, 0, 0.2f, 1.3f}}, Entry{"i@", {C::vowel, kIH, 0, 0.3f, 1.4f}},
    Entry{"i@3", {C::vowel, kIH, 0, 0.3f, 1.4f}},
    Entry{"0", {C::vowel, kOH, 0.6f, 0.75f, 1.0f}}, Entry{"O", {C::vowel, kOH, 0.7f, 0.6f, 1.0f}},
    Entry{"O:", {C::vowel, kOH, 0.7f, 0.6f, 1.3f}}, Entry{"O@", {C::vowel, kOH, 0.6f, 0.6f, 1.4f}},
    Entry{"OI", {C::vowel, kOH, 0.6f, 0.6f, 1.5f}}, Entry{"o@", {C::vowel, kOH, 0.6f, 0.6f, 1.4f}},
    Entry{"oU", {C::vowel, kOH, 0.9f, 0.5f, 1.5f}}, Entry{"o", {C::vowel, kOH, 0.8f, 0.5f, 1.1f}},
    Entry{"u:", {C::vowel, kOU, 1.0f, 0.25f, 1.3f}}, Entry{"u", {C::vowel, kOU, 1.0f, 0.25f, 1.0f}},
    Entry{"U", {C::vowel, kOU, 0.8f, 0.3f, 0.9f}}, Entry{"U@", {C::vowel, kOU, 0.8f, 0.35f, 1.4f}},
};

const Articulation* lookup(std::string_view symbol) {
  for (const Entry& e : kTable)
    if (e.symbol == symbol) return &e.a;
  return nullptr;
}

}  // namespace

Articulation articulation(std::string_view symbol) {
  if (const Articulation* a = lookup(symbol)) return *a;
  if (!symbol.empty())
    if (const Articulation* a = lookup(symbol.substr(0, 1))) return *a;
  return Articulation{C::pause, kSil, 0, 0, 0.5f};
}

float relative_duration(const Articulation& a, Stress stress) {
  if (a.cls != C::vowel) return a.base_duration;
  switch (stress) {
    case Stress::primary: return a.base_duration * 1.4f;
    case Stress::secondary: return a.base_duration * 1.2f;
    case Stress::none: return a.base_duration;
  }
  return a.base_duration;
}

}  // namespace gestura::face
