#pragma once
// UTF-8 text, one way for the whole library: strict decoding (malformed input is reported with its
// byte, never misread), and Unicode normalisation, case and character classes from ICU. The text
// tokenizer, the HamNoSys parser, subtitles, fingerspelling and the phonemizer all read text
// through here.
#include <cstddef>
#include <string>
#include <string_view>

namespace gestura::utf8 {

// Decodes the code point starting at text[pos] into `cp` and advances pos; returns false (pos
// unchanged) for bad lead bytes, truncated or overlong sequences, surrogates and code points past
// U+10FFFF.
bool decode(std::string_view text, std::size_t& pos, char32_t& cp);
// The same, throwing gestura::Error ("invalid UTF-8 at byte N") instead of returning false.
char32_t next(std::string_view text, std::size_t& pos);
// Throws the same error as next() for the first malformed sequence in `text`.
void validate(std::string_view text);
void append(std::string& out, char32_t cp);

// Simple (one code point to one) case mapping of every script that has case.
char32_t to_lower(char32_t cp);
char32_t to_upper(char32_t cp);
// The base letter of a letter with diacritics (é → e, ŝ → s, ḗ → e): the first code point of its
// canonical decomposition when the rest are combining marks; else cp itself (ß, æ, ø, ł have none).
char32_t base_letter(char32_t cp);
// Letters of any script, and the combining marks that belong to them (so a decomposed "é" stays
// one word).
bool is_letter(char32_t cp);
bool is_mark(char32_t cp);  // combining marks (general category M)
bool is_digit(char32_t cp);  // ASCII 0-9
// White space, controls, and the zero-width space and byte order mark that separate like spaces.
bool is_space(char32_t cp);

// Full case mapping of a whole text (ß → SS in upper case), root locale. Throws for invalid UTF-8.
std::string lower(std::string_view text);
std::string upper(std::string_view text);
// Canonical composition (NFC): a letter followed by combining accents becomes the precomposed letter
// where one exists, so "José" reads the same however it was typed. Throws for invalid UTF-8.
std::string nfc(std::string_view text);

}  // namespace gestura::utf8
