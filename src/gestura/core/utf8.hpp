#pragma once
// The few Unicode operations English text processing needs: strict UTF-8 decoding (so malformed
// input is reported, not misread), case mapping for ASCII and Latin-1 letters, and a letter test
// that treats every non-ASCII code point outside the punctuation blocks as part of a word.
#include <cstddef>
#include <string>
#include <string_view>

namespace gestura::utf8 {

// Decodes the code point starting at text[pos] and advances pos. Throws gestura::Error
// ("invalid UTF-8 at byte N") for bad lead bytes, truncated or overlong sequences and surrogates.
char32_t next(std::string_view text, std::size_t& pos);
// Throws the same error as next() for the first malformed sequence in `text`.
void validate(std::string_view text);
void append(std::string& out, char32_t cp);

char32_t to_lower(char32_t cp);
char32_t to_upper(char32_t cp);
// The base Latin letter of an accented Latin-1 letter (é → e), else cp itself.
char32_t strip_accent(char32_t cp);
bool is_letter(char32_t cp);
bool is_digit(char32_t cp);
// Spaces, controls and the Unicode space separators.
bool is_space(char32_t cp);

std::string lower(std::string_view text);
std::string upper(std::string_view text);

}  // namespace gestura::utf8
