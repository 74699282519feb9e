#pragma once
// English inflection undone by rule tables: irregular forms (went → go, children → child) and the
// regular suffixes -s/-es/-ies, -ed/-ied and -ing. Without a dictionary a suffix rule can guess wrong
// ("hoped" could be hope or hop), so the lemmatizer offers candidates best-first and the caller keeps
// the first one the sign inventory knows.
#include <string>
#include <string_view>
#include <vector>

namespace gestura {

struct LemmaCandidate {
  std::string lemma;
  std::string_view rule;  // "irregular past", "plural -s", "-ing", …; empty for the word itself
};

// Candidates for a lowercase word, most plausible first; the word itself is always the last one.
std::vector<LemmaCandidate> lemma_candidates(std::string_view word);

}  // namespace gestura
