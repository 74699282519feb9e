#include "gestura/lexicon/sign_language_codes.hpp"

#include <algorithm>
#include <array>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

constexpr std::array kCodes{
    SignLanguageCode{"ase", "American Sign Language"},
    SignLanguageCode{"asf", "Auslan (Australian Sign Language)"},
    SignLanguageCode{"bfi", "British Sign Language"},
    SignLanguageCode{"bzs", "Brazilian Sign Language (Libras)"},
    SignLanguageCode{"csl", "Chinese Sign Language"},
    SignLanguageCode{"cse", "Czech Sign Language"},
    SignLanguageCode{"dse", "Sign Language of the Netherlands (NGT)"},
    SignLanguageCode{"dsl", "Danish Sign Language"},
    SignLanguageCode{"fse", "Finnish Sign Language"},
    SignLanguageCode{"fsl", "French Sign Language (LSF)"},
    SignLanguageCode{"gsg", "German Sign Language (DGS)"},
    SignLanguageCode{"gss", "Greek Sign Language"},
    SignLanguageCode{"icl", "Icelandic Sign Language"},
    SignLanguageCode{"ins", "Indian Sign Language"},
    SignLanguageCode{"ise", "Italian Sign Language (LIS)"},
    SignLanguageCode{"isg", "Irish Sign Language"},
    SignLanguageCode{"jsl", "Japanese Sign Language"},
    SignLanguageCode{"kvk", "Korean Sign Language"},
    SignLanguageCode{"mfs", "Mexican Sign Language"},
    SignLanguageCode{"nsl", "Norwegian Sign Language"},
    SignLanguageCode{"nzs", "New Zealand Sign Language"},
    SignLanguageCode{"pso", "Polish Sign Language (PJM)"},
    SignLanguageCode{"psr", "Portuguese Sign Language"},
    SignLanguageCode{"rsl", "Russian Sign Language"},
    SignLanguageCode{"sfs", "South African Sign Language"},
    SignLanguageCode{"sgg", "Swiss-German Sign Language"},
    SignLanguageCode{"ssp", "Spanish Sign Language"},
    SignLanguageCode{"swl", "Swedish Sign Language"},
    SignLanguageCode{"tsm", "Turkish Sign Language"},
    SignLanguageCode{"vgt", "Flemish Sign Language"},
};

// Names people type instead of the ISO code.
struct Alias {
  std::string_view typed;
  std::string_view code;
};
constexpr std::array kAliases{Alias{"asl", "ase"}, Alias{"bsl", "bfi"}, Alias{"dgs", "gsg"}, Alias{"pjm", "pso"},
                              Alias{"isl", "ins"}, Alias{"lsf", "fsl"}, Alias{"ngt", "dse"}, Alias{"lis", "ise"},
                              Alias{"auslan", "asf"}, Alias{"libras", "bzs"}};

}  // namespace

std::span<const SignLanguageCode> known_sign_languages() { return kCodes; }

bool is_known_sign_language(std::string_view code) {
  return std::any_of(kCodes.begin(), kCodes.end(), [&](const SignLanguageCode& c) { return c.code == code; });
}

void require_known_sign_language(std::string_view code) {
  if (is_known_sign_language(code)) return;
  std::string lowered(code);
  std::transform(lowered.begin(), lowered.end(), lowered.begin(),
                 [](unsigned char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c); });
  std::string hint;
  for (const Alias& a : kAliases)
    if (a.typed == lowered) hint = " (did you mean '" + std::string(a.code) + "'?)";
  if (hint.empty() && is_known_sign_language(lowered)) hint = " (codes are lowercase: '" + lowered + "')";
  throw Error("unknown sign-language code '" + std::string(code) + "'" + hint +
              "; use an ISO 639-3 code such as ase (ASL), bfi (BSL), gsg (DGS), pso (PJM), ins (ISL)");
}

bool is_spoken_language_code(std::string_view code) {
  if (code.size() < 2 || code.size() > 3) return false;
  return std::all_of(code.begin(), code.end(), [](char c) { return c >= 'a' && c <= 'z'; });
}

}  // namespace gestura
