#pragma once
// One sign of a lexicon: its gloss in one sign language, how it is performed (HamNoSys text, a SiGML
// element, or a recorded clip) and the spoken-language words that lead to it. The notation is kept as
// text; parsing it is the job of gestura/sign.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

enum class NotationKind { hamnosys, sigml, clip };

std::string_view to_string(NotationKind kind);
// Throws gestura::Error for anything other than "hamnosys", "sigml" or "clip".
NotationKind notation_kind_from_string(std::string_view text);

// How a verb sign uses the signing space (docs/grammar.md): an agreement verb's movement runs from
// its subject's place to its object's (forward: GIVE, TELL) or from the object's to the subject's
// (backward: BORROW); plain signs keep their citation place.
enum class Agreement { none, forward, backward };

std::string_view to_string(Agreement agreement);
// Throws gestura::Error for anything other than "none", "forward" or "backward".
Agreement agreement_from_string(std::string_view text);

// A spoken-language word or phrase that this sign translates, with an optional gloss of its meaning
// ("bank" → "financial institution") to tell homonyms apart.
struct Keyword {
  std::string word;          // stored lowercase
  std::string language = "eng";  // spoken language, ISO 639-1/3
  std::string meaning;

  bool operator==(const Keyword&) const = default;
};

struct SignEntry {
  std::int64_t id = 0;          // row id; 0 until stored
  std::string gloss;            // e.g. "HOUSE"; lookups ignore ASCII case
  std::string language;         // sign language, ISO 639-3 (see sign_language_codes.hpp)
  int variant = 1;              // 1, 2, … for several signs sharing one gloss
  NotationKind notation_kind = NotationKind::hamnosys;
  std::string notation;         // HamNoSys (Unicode) or one SiGML <hns_sign> element; empty for clips
  std::vector<std::uint8_t> clip;  // encoded clip for NotationKind::clip
  std::vector<Keyword> keywords;
  Agreement agreement = Agreement::none;  // verbs that move between referents' places
  std::string source;           // where the entry came from (lexicon name, file)
  std::string licence;
  std::int64_t created = 0;     // Unix seconds, set by the store
  std::int64_t updated = 0;
};

}  // namespace gestura
