#pragma once
// English text → phonemes with the eSpeak NG library (voice "en-us").
//
// eSpeak is asked for its ASCII phoneme mnemonics (not IPA), one phoneme per '|'-separated name,
// words separated by spaces, stress written as a prefix on the vowel ('\'' primary, ',' secondary).
// ASCII names are stable across eSpeak versions and easy to table (phoneme.hpp); IPA would need
// UTF-8 parsing for the same information.
//
// The engine is global in eSpeak: it is initialised once, on first use, from its default data path
// (or $GESTURA_ESPEAK_DATA: espeak-ng-data or the directory that contains it), and every call is
// serialised by a mutex, so phonemize() is safe to call from any thread.
#include <string_view>
#include <vector>

#include "gestura/face/phoneme.hpp"

namespace gestura::face {

inline constexpr std::size_t kMaxPhonemizeBytes = 1024;

// Phonemes of `text` in order; a clause break (comma, full stop) becomes a pause phoneme "_".
// Empty or letterless text gives an empty list. Throws gestura::Error when the text is not valid
// UTF-8, is longer than kMaxPhonemizeBytes, or eSpeak NG (or its data) cannot be loaded.
std::vector<Phoneme> phonemize(std::string_view text);

// Parses eSpeak's '|'-separated mnemonic string (one clause, as above). Symbols eSpeak adds that are
// not phonemes (';' palatalisation, '-' syllable break, '_' pauses inside) are dropped or become pauses.
std::vector<Phoneme> parse_espeak_phonemes(std::string_view mnemonics);

}  // namespace gestura::face
