#pragma once
// The affect of a sentence, for facial expression during signing. The expressions themselves (the
// six MPEG-4 basic expressions and neutral as morph weights) are the avatar's table in
// body/face_morphs.hpp: gestura::Expression and gestura::expression_weights.
#include <string_view>

#include "gestura/body/face_morphs.hpp"

namespace gestura::face {

// The affect a sentence shows, from its words and final punctuation: a small word list (happy,
// love, sorry, angry, afraid, disgusting, wow, ...; case-insensitive, whole words) decides; a
// sentence ending in '!' without such a word is surprise; otherwise neutral.
Expression affect_from_text(std::string_view sentence);

}  // namespace gestura::face
