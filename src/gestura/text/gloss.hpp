#pragma once
// The result of English → ASL gloss translation: glosses in signing order, each tied to the words it
// came from and a reason a person can read, plus the sentence types and the spans the face has to
// mark (raised brows for yes/no questions, lowered for wh-questions, headshake for negation).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

enum class GlossKind { sign, fingerspell, number, pause };
std::string_view to_string(GlossKind kind);

// A place in the signing space (docs/grammar.md): person 1 is the signer, 2 the addressee straight
// ahead, 3 a third-person referent's locus, lettered in order of introduction (3a on the signer's
// right, 3b on the left, then farther out). person 0: no place.
struct Locus {
  int person = 0;
  int index = 0;  // third person: 0 = 'a', 1 = 'b', …
  explicit operator bool() const { return person != 0; }
  std::string name() const;  // "1", "2", "3a", "3b"; "" for no place
  bool operator==(const Locus&) const = default;
};

struct GlossToken {
  std::string gloss;                 // "GO", "FS-JOHN", "25", "PAUSE"
  GlossKind kind = GlossKind::sign;
  std::size_t begin = 0, end = 0;    // byte span of the source words in the input text
  std::vector<std::string> letters;  // fingerspelling: one letter per element ("J", "O", "H", "N")
  std::string reason;                // "'went' → GO: irregular past"
  // Spatial grammar (text/referent_loci.hpp): the gloss then names its places ("IX-3a",
  // "GIVE:3a→3b", "IX-3-PL:3a+3b") and `lexeme` is the lexicon sign that is inflected ("IX-3", "GIVE").
  std::string lexeme;                // empty: the gloss itself is the lexicon sign
  Locus at;                          // a pointing sign (IX, POSS, SELF): the place it points at
  Locus from, to;                    // an agreement verb: from the subject's place to the object's
  std::vector<Locus> over;           // a plural pointing sign: the places its arc sweeps over

  const std::string& sign() const { return lexeme.empty() ? gloss : lexeme; }
};

// What became of one source word, in text order (dropped words included).
struct WordNote {
  std::string word;
  std::size_t begin = 0, end = 0;
  std::string reason;
};

enum class SentenceType { statement, yes_no_question, wh_question, exclamation };
std::string_view to_string(SentenceType type);

enum class MarkerKind { yes_no_question, wh_question, negation, exclamation };
std::string_view to_string(MarkerKind kind);

// A non-manual marker over glosses [first, last) of Translation::glosses.
struct Marker {
  MarkerKind kind;
  std::size_t first = 0, last = 0;
};

struct Sentence {
  SentenceType type = SentenceType::statement;
  bool negated = false;
  std::size_t first = 0, last = 0;  // glosses [first, last)
  std::size_t begin = 0, end = 0;   // byte span in the input
  // The English parse the translation rests on (link-grammar): the constituent tree and the
  // subject/verb/object links, e.g. "(S (NP my head) (VP hurts)); subject 'head' → verb 'hurts'".
  // Empty when the sentence did not parse and the rule tables alone were used.
  std::string parse;
};

// Quoted speech signed in role shift over glosses [first, last): the signer's shoulders, head and
// eyes turn toward the place of the person quoted.
struct RoleShift {
  std::size_t first = 0, last = 0;
  Locus toward;
};

struct Translation {
  std::vector<GlossToken> glosses;
  std::vector<WordNote> notes;
  std::vector<Sentence> sentences;
  std::vector<Marker> markers;
  std::vector<RoleShift> role_shifts;

  // The glosses joined by spaces ("YESTERDAY IX-1 GO STORE"), pauses as "/".
  std::string text() const;
};

}  // namespace gestura
