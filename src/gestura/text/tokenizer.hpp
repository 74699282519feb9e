#pragma once
// Splits UTF-8 English text into words, numbers, symbols and punctuation, each with its byte span in
// the input. Typographic variants are folded so later stages see one form: ’ and ‘ inside a word
// become ', em/en dashes and … are pauses, curly and guillemet quotes are dropped; words are in
// Unicode NFC (a letter typed with a combining accent is the precomposed letter).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

enum class TokenKind {
  word,         // letters, with inner ' and - and abbreviation periods ("don't", "well-known", "p.m.")
  number,       // digits with inner , . : / - ("1,000", "3.5", "3:30", "3/14/2024"), optional ordinal suffix
  symbol,       // $ € £ % & + @ #
  sentence_end, // . ! ?
  pause,        // , ; : — – … ( )
};

struct Token {
  TokenKind kind;
  std::string text;  // normalized spelling (apostrophes folded, NFC), original case
  std::size_t begin = 0, end = 0;  // byte span in the input
};

// Throws gestura::Error for invalid UTF-8. Linear in the input size.
std::vector<Token> tokenize(std::string_view text);

}  // namespace gestura
