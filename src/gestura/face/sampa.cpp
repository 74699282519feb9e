#include "gestura/face/sampa.hpp"

#include <array>
#include <utility>

namespace gestura::face {
namespace {

struct Symbol {
  std::string_view sampa;
  std::string_view first, second;  // eSpeak mnemonics; second is empty but for affricates read as two
};

// Longest symbols first, so a linear scan finds the longest match.
constexpr std::array kSymbols{
    // diphthongs and long vowels
    Symbol{"aI", "aI"}, Symbol{"aU", "aU"}, Symbol{"OI", "OI"}, Symbol{"Oy", "OI"}, Symbol{"eI", "eI"},
    Symbol{"@U", "oU"}, Symbol{"oU", "oU"}, Symbol{"I@", "i@"}, Symbol{"e@", "e@"}, Symbol{"E@", "e@"},
    Symbol{"U@", "U@"}, Symbol{"i:", "i:"}, Symbol{"u:", "u:"}, Symbol{"O:", "O:"}, Symbol{"A:", "A:"},
    Symbol{"3:", "3:"}, Symbol{"e:", "e"}, Symbol{"E:", "E"}, Symbol{"o:", "o"}, Symbol{"a:", "A:"},
    Symbol{"y:", "u:"}, Symbol{"2:", "o"}, Symbol{"9:", "O"},
    // affricates
    Symbol{"tS", "tS"}, Symbol{"dZ", "dZ"}, Symbol{"pf", "p", "f"}, Symbol{"ts", "t", "s"},
    // vowels
    Symbol{"i", "i"}, Symbol{"I", "I"}, Symbol{"e", "e"}, Symbol{"E", "E"}, Symbol{"{", "a"}, Symbol{"a", "a"},
    Symbol{"A", "A"}, Symbol{"Q", "0"}, Symbol{"O", "O"}, Symbol{"o", "o"}, Symbol{"U", "U"}, Symbol{"u", "u"},
    Symbol{"V", "V"}, Symbol{"@", "@"}, Symbol{"3", "3"}, Symbol{"6", "a#"}, Symbol{"y", "u"}, Symbol{"Y", "U"},
    Symbol{"2", "o"}, Symbol{"9", "O"},
    // consonants
    Symbol{"p", "p"}, Symbol{"b", "b"}, Symbol{"t", "t"}, Symbol{"d", "d"}, Symbol{"k", "k"}, Symbol{"g", "g"},
    Symbol{"f", "f"}, Symbol{"v", "v"}, Symbol{"T", "T"}, Symbol{"D", "D"}, Symbol{"s", "s"}, Symbol{"z", "z"},
    Symbol{"S", "S"}, Symbol{"Z", "Z"}, Symbol{"h", "h"}, Symbol{"m", "m"}, Symbol{"n", "n"}, Symbol{"N", "N"},
    Symbol{"l", "l"}, Symbol{"r", "r"}, Symbol{"R", "r"}, Symbol{"w", "w"}, Symbol{"j", "j"}, Symbol{"x", "x"},
    Symbol{"X", "x"}, Symbol{"C", "j"}, Symbol{"J", "n"}, Symbol{"L", "l"}, Symbol{"G", "g"}, Symbol{"4", "*"},
    Symbol{"?", "?"},
};

constexpr std::string_view kSeparators = ".-_=~', \t";

Phoneme make_phoneme(std::string_view mnemonic, Stress stress) {
  const Articulation a = articulation(mnemonic);
  Phoneme p;
  p.symbol = std::string(mnemonic);
  p.cls = a.cls;
  p.stress = a.cls == PhonemeClass::vowel ? stress : Stress::none;
  p.duration = relative_duration(a, p.stress);
  return p;
}

}  // namespace

SampaReading phonemes_from_sampa(std::string_view sampa) {
  SampaReading out;
  Stress pending = Stress::none;
  std::size_t i = 0;
  while (i < sampa.size()) {
    const char c = sampa[i];
    if (c == '"' || c == '%') {
      pending = c == '"' ? Stress::primary : Stress::secondary;
      ++i;
      continue;
    }
    if (kSeparators.find(c) != std::string_view::npos) {
      ++i;
      continue;
    }
    if (c == ':') {  // a length mark on a symbol that has no long form of its own
      if (!out.phonemes.empty()) out.phonemes.back().duration *= 1.4f;
      ++i;
      continue;
    }
    const Symbol* match = nullptr;
    for (const Symbol& s : kSymbols)
      if (sampa.substr(i, s.sampa.size()) == s.sampa) {
        match = &s;
        break;
      }
    if (!match) {
      out.unknown.push_back(c);
      ++i;
      continue;
    }
    Phoneme first = make_phoneme(match->first, pending);
    if (first.cls == PhonemeClass::vowel) pending = Stress::none;  // stress belongs to the next vowel
    out.phonemes.push_back(std::move(first));
    if (!match->second.empty()) out.phonemes.push_back(make_phoneme(match->second, Stress::none));
    i += match->sampa.size();
  }
  return out;
}

}  // namespace gestura::face
