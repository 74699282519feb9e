#pragma once
// Spatial grammar, the discourse half (docs/grammar.md): who is where in the signing space.
//
// A signer gives each third-person referent a place (a locus) to the side in front of them, in
// order of introduction — 3a on the right, 3b on the left, then farther out — and later points
// there instead of naming the referent again. This pass reads a translated utterance as a small
// discourse model:
//   - referents are the people the text names (names, nouns whose WordNet sense is a person) and
//     the third-person pronouns that have no antecedent; each gets a locus when introduced;
//   - a pronoun (he, she, him, her, it, they, his, their…) takes the place of the most salient earlier
//     referent that agrees with it in number and gender (an object pronoun never takes its own
//     clause's subject: "she gave her" is two people); IX-3 becomes IX-3a, POSS-3 POSS-3b;
//   - a noun or name whose place is used later is followed by an index that sets the place up
//     (BOY IX-3a), and a plural noun of people by an arc over its place (CHILD IX-3a-PL);
//   - "they" without a plural antecedent sweeps over the places of the people already placed;
//   - an agreement verb — a sign whose lexicon entry says `agreement` forward (GIVE, HELP, TELL, ASK,
//     SHOW, SEND, PAY…) or backward (BORROW) — moves from its subject's place to its object's (from
//     the object's to the subject's when backward; 1 = the signer, 2 = the addressee): GIVE:3a→3b;
//   - quoted speech is marked for role shift toward the place of the person quoted.
// It only rewrites glosses (gloss text, lexeme, places) and adds index glosses; how a place is
// signed is the performer's (sentence/signing_space.hpp).
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "gestura/text/english_parse.hpp"
#include "gestura/text/gloss.hpp"
#include "gestura/text/sign_inventory.hpp"

namespace gestura {

// What the translator knew of one source word.
struct SourceWord {
  std::size_t begin = 0, end = 0;  // byte span in the text
  std::string lower;               // as written, lower case
  english::PartOfSpeech pos = english::PartOfSpeech::unknown;
  english::Role role = english::Role::none;
  std::string tag;                 // link-grammar's tag: "John.m", "father.n-m" carry a gender
};

// Places the referents of `translation` (made from `text`, whose words are `words` in text order)
// as the header says; `inventory` says which signs are agreement verbs. Glosses inserted keep the
// sentences', markers' and role shifts' spans around the same glosses.
void place_referents(Translation& translation, std::string_view text, std::span<const SourceWord> words,
                     SignInventory& inventory);

}  // namespace gestura
