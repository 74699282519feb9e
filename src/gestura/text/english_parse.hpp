#pragma once
// English sentence structure from link-grammar (CMU's link grammar parser, Debian liblink-grammar
// with the English dictionary): each word's part of speech, which words are subjects, objects and
// verbs, which verbs are auxiliaries (do-support, perfect 'have', progressive or passive 'be'), and
// the constituent tree, which the gloss explanation shows.
//
// The parser is loaded once per process and parses one sentence at a time (a mutex guards it).
// When it finds no complete linkage in its time limit, or the sentence is too long, `parsed` is
// false and the translator falls back to its rule tables.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace gestura::english {

enum class PartOfSpeech { unknown, noun, verb, adjective, adverb, pronoun, preposition, determiner, number, wh };
std::string_view to_string(PartOfSpeech pos);

enum class Role { none, subject, object, verb };

struct ParsedWord {
  PartOfSpeech pos = PartOfSpeech::unknown;
  std::string tag;          // link-grammar's word with its subscript ("hurts.v", "coffee.n-u")
  Role role = Role::none;   // subject (left end of an S link), object (right end of O), verb (head of either)
  bool do_support = false;  // 'do' linked to a following verb by I (does she know, do not go)
  bool perfect = false;     // 'have' linked to a participle by PP (have eaten)
  int participle = -1;      // perfect 'have': the input index of its participle
  bool auxiliary_be = false;  // 'be' linked to -ing/participle by Pg/Pv (is going, was taken)
  bool passive_participle = false;  // the participle of a passive: 'be' links to it by Pv (was taken)
  bool modal = false;       // can, will, must... linked to a verb by I
};

struct ParsedSentence {
  bool parsed = false;
  std::vector<ParsedWord> words;  // one per input word, in order
  // Parts link-grammar split off an input word ("I'm" → I + 'm): parts[k] are the parts of input
  // word k after its first, in order.
  std::vector<std::vector<ParsedWord>> parts;
  std::string tree;               // constituent tree on one line: (S (NP my head) (VP hurts))
  std::string roles;              // "subject 'head' → verb 'hurts'; verb 'gave' → object 'book'"
  std::size_t clauses = 0;        // S and SBAR constituents in the tree
  double cost = 0;                // link-grammar's disjunct cost of the linkage taken (higher: less usual)
};

// Parses the words of one sentence (as written; punctuation may be given as words of its own).
ParsedSentence parse_sentence(std::span<const std::string> words);

// Whether the parser can be used here (its English dictionary found); false also when disabled with
// GESTURA_NO_PARSER=1 (rule tables only, e.g. to compare).
bool parser_available();

// Whether link-grammar's English dictionary lists `word` (as written, with its capital) among given
// names: its word lists entities.given-{male,female,bisex}.sing (John, Mary, Bill, Mark, Rose, Frank).
// The parser's tag for a word in context may be another reading (Mark.c, the currency); this is the
// list itself. False when the lists are not found.
bool is_given_name(std::string_view word);

}  // namespace gestura::english
