#pragma once
// The six MPEG-4 basic expressions (joy, sadness, anger, fear, disgust, surprise) and neutral, as
// weights over the avatar's expression morph targets (face_channels.hpp). Weights are full-intensity
// poses; callers scale them. Neutral is the empty set (every morph at 0).
#include <span>
#include <string_view>

namespace gestura::face {

enum class Expression { neutral, joy, sadness, anger, fear, disgust, surprise };
std::string_view to_string(Expression e);

struct ChannelWeight {
  std::string_view channel;
  float weight;
};

std::span<const ChannelWeight> expression_weights(Expression e);

// The affect a sentence shows, from its words and final punctuation: a small word list (happy,
// love, sorry, angry, afraid, disgusting, wow, ...; case-insensitive, whole words) decides; a
// sentence ending in '!' without such a word is surprise; otherwise neutral.
Expression affect_from_text(std::string_view sentence);

}  // namespace gestura::face
