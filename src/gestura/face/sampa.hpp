#pragma once
// SAMPA (the ASCII phonetic alphabet SiGML mouth pictures are written in, e.g. "O:streIlj@") →
// the phonemes the viseme track knows (phoneme.hpp: eSpeak NG mnemonics).
//
// Symbols are read longest first ("tS" before "t", "aI" before "a", "i:" before "i"). SAMPA covers
// several languages; sounds English lacks are mapped to the English sound with the same lip shape:
// front rounded vowels y Y 2 9 → u U o O (rounded lips), German schwa 6 → a#, ç C → j, uvular R → r.
// Affricates pf and ts become two phonemes. '"' and '%' mark primary and secondary stress of the
// next vowel; '.', '-', '_', '=', '~', '\'', ',' and spaces only separate (a separator also stops
// two symbols from being read as one); a ':' after a symbol without a long form lengthens it.
#include <string>
#include <string_view>
#include <vector>

#include "gestura/face/phoneme.hpp"

namespace gestura::face {

struct SampaReading {
  std::vector<Phoneme> phonemes;
  std::string unknown;  // characters that are no SAMPA symbol, in order (they are skipped)
};

// Never throws; any byte that is not SAMPA lands in `unknown`.
SampaReading phonemes_from_sampa(std::string_view sampa);

}  // namespace gestura::face
