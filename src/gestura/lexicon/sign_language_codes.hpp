#pragma once
// ISO 639-3 codes of the sign languages gestura knows. A lexicon entry must name one of them, so a
// typo ("asl" for "ase") is caught when the entry is stored rather than when nothing matches later.
#include <span>
#include <string>
#include <string_view>

namespace gestura {

struct SignLanguageCode {
  std::string_view code;  // ISO 639-3, lowercase
  std::string_view name;  // English name
};

std::span<const SignLanguageCode> known_sign_languages();
bool is_known_sign_language(std::string_view code);
// Throws gestura::Error listing a few known codes (and the likely intended one for common mix-ups
// like "asl", "bsl", "dgs", "isl") when `code` is not known.
void require_known_sign_language(std::string_view code);

// Spoken-language codes for keywords: two or three lowercase ASCII letters (ISO 639-1 or 639-3).
bool is_spoken_language_code(std::string_view code);

}  // namespace gestura
