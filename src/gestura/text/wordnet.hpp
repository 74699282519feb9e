#pragma once
// WordNet (Princeton WordNet 3.0 through Debian's libwordnet and wordnet-base): lemmas of inflected
// words by part of speech (left as a verb → leave, as an adjective → left) and the synonyms of a
// lemma's senses, most frequent sense first. A mutex guards the library, which keeps global state.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/text/english_parse.hpp"

namespace gestura::wordnet {

// Whether the WordNet database was found (false also with GESTURA_NO_WORDNET=1).
bool available();

// Base forms WordNet knows for `word` as `pos` (noun, verb, adjective, adverb), best first: for a verb
// its base forms before the word itself (saw → see, saw), for other parts of speech the word first
// when WordNet lists it (glasses, glass). Empty for other parts of speech or unknown words.
std::vector<std::string> lemmas(std::string_view word, english::PartOfSpeech pos);

// The other words of the first `senses` senses of `lemma` as `pos`, most frequent sense first,
// multi-word lemmas with spaces ("look_at" → "look at").
std::vector<std::string> synonyms(std::string_view lemma, english::PartOfSpeech pos, int senses = 3);

// Whether the most frequent noun sense of `lemma` is a kind of person (its hypernyms reach WordNet's
// person.n.01): teacher, mother, child, doctor, friend — the nouns whose referents a signer places
// in space. False for unknown words and without the database.
bool names_a_person(std::string_view lemma);

// Whether the most frequent noun sense of `word` (a sense seen in WordNet's tagged texts) names one
// thing written with a capital: God, Easter, Sunday, China, German — so a capitalised "Easter" is
// the holiday, while "Bill", "Rose" or "Mark", whose first senses are common nouns, may be names.
bool first_sense_is_proper(std::string_view word);

// WordNet's lexicographer file of the most frequent noun sense of `word`: "noun.plant" (rose),
// "noun.communication" (bill), "noun.feeling" (hope), "noun.time" (summer); empty when unknown.
std::string first_noun_sense_class(std::string_view word);

}  // namespace gestura::wordnet
