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

struct GlossToken {
  std::string gloss;                 // "GO", "FS-JOHN", "25", "PAUSE"
  GlossKind kind = GlossKind::sign;
  std::size_t begin = 0, end = 0;    // byte span of the source words in the input text
  std::vector<std::string> letters;  // fingerspelling: one letter per element ("J", "O", "H", "N")
  std::string reason;                // "'went' → GO: irregular past"
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

struct Translation {
  std::vector<GlossToken> glosses;
  std::vector<WordNote> notes;
  std::vector<Sentence> sentences;
  std::vector<Marker> markers;

  // The glosses joined by spaces ("YESTERDAY IX-1 GO STORE"), pauses as "/".
  std::string text() const;
};

}  // namespace gestura
