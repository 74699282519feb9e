#pragma once
// English text → ASL gloss sequence, by rules (docs/text-to-gloss.md lists the conventions):
// tokenize, expand contractions, match fixed phrases, turn numbers, times, dates and money into number
// glosses, drop what ASL does not sign (articles, copula, most prepositions, do-support), lemmatize
// against the sign inventory, fingerspell names and unknown words, then reorder each clause
// time – rest – negation – wh-word and mark sentence types and negation spans.
#include <string_view>

#include "gestura/text/gloss.hpp"
#include "gestura/text/sign_inventory.hpp"

namespace gestura {

// Throws gestura::Error only for text that is not valid UTF-8. Linear in the text length.
Translation translate_to_gloss(std::string_view english, SignInventory& inventory);

}  // namespace gestura
