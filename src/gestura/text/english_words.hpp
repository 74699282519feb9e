#pragma once
// Closed-class English words and the ASL glossing conventions gestura uses for them. All lookups take
// lowercase words (see docs/text-to-gloss.md for the conventions).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gestura::english {

// "don't" → {"do", "not"}, "I'm" → {"i", "am"}, "can't" → {"can't"} (a sign of its own), "let's" →
// {"let", "us"}; "'s" after other words is possessive: "john's" → {"john", "'s"}. nullopt when the
// word is no contraction.
std::optional<std::vector<std::string>> expand_contraction(std::string_view word);

enum class DropReason { none, article, copula, preposition, filler };
// Words ASL does not sign at all (do-support depends on context and is decided by the translator).
DropReason dropped(std::string_view word);
std::string_view describe(DropReason reason);

// Personal and possessive pronouns become pointing: I/me → IX-1, you → IX-2, he/she/it → IX-3,
// they → IX-3-PL, my → POSS-1, your → POSS-2, his/its → POSS-3, their → POSS-3-PL, we/us → WE,
// our → OUR. "her" is decided by the translator (object IX-3 or possessive POSS-3).
std::optional<std::string_view> pronoun_gloss(std::string_view word);

bool is_wh_word(std::string_view word);
bool is_auxiliary_do(std::string_view word);   // do, does, did
bool is_auxiliary(std::string_view word);      // do-support, be, have, modals: question-initial words
// A form of "be" or a linking verb (seem, feel, look, get, become): what follows describes the subject.
bool is_linking_verb(std::string_view word);

// Time adverbs that open an ASL sentence: yesterday → YESTERDAY, monday → MONDAY, …
std::optional<std::string_view> time_gloss(std::string_view word);

// Month names: the gloss is fingerspelled as ASL signers do (the short ones whole, others abbreviated).
struct Month {
  int number;               // 1..12
  std::string_view letters; // "JAN", "MARCH", …
};
std::optional<Month> month(std::string_view word);
std::optional<Month> month(int number);

// Spoken number words: "twenty" → 20. Compounds are built by the translator ("twenty five" → 25).
std::optional<long long> number_word(std::string_view word);

// Synonyms tried when the sign inventory has no sign for a word: "mom" → "mother".
std::optional<std::string_view> synonym(std::string_view word);

// Multi-word expressions signed as fixed phrases. Matching is on lowercase words after contraction
// expansion, longest first.
enum class PhraseRole { plain, time, wh, negation };
struct Phrase {
  std::vector<std::string_view> words;
  std::vector<std::string_view> glosses;
  PhraseRole role;
};
// Phrases starting with `first_word`, longest first; empty span when none.
const std::vector<const Phrase*>& phrases_starting_with(std::string_view first_word);

}  // namespace gestura::english
