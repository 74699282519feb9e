// How many content words of everyday English the built-in ASL lexicon signs rather than fingerspells:
// the measure of tools/coverage.py (make coverage) on data/eval/everyday-sentences.txt, run through
// the library, held to the figure the vocabulary reached (a ratchet: it may rise, never fall).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"
#include "support/build_paths.hpp"

using namespace gestura;

namespace {

const std::string kEval = gestura::test::source_dir() + "/data/eval/";

struct EvalSentence {
  std::string domain, text;
};

std::vector<EvalSentence> read_sentences() {
  std::ifstream in(kEval + "everyday-sentences.txt");
  EXPECT_TRUE(in);
  std::vector<EvalSentence> out;
  std::string domain = "all";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("##", 0) == 0) domain = line.substr(line.find_first_not_of("# "));
    else if (!line.empty() && line[0] != '#') out.push_back({domain, line});
  }
  return out;
}

std::set<std::string> read_function_words() {
  std::ifstream in(kEval + "function-words.txt");
  EXPECT_TRUE(in);
  std::set<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    for (std::string w; words >> w;) out.insert(w);
  }
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool covers(const GlossToken& g, const WordNote& n) { return g.begin <= n.begin && n.end <= g.end; }

struct Coverage {
  int content = 0, signed_words = 0;
  std::map<std::string, int> missed;
  std::set<std::string> domains;
};

Coverage measure() {
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  layers.push_layer(builtin);
  LexiconInventory inventory(layers, "ase");
  const std::set<std::string> function_words = read_function_words();
  Coverage c;
  for (const EvalSentence& s : read_sentences()) {
    c.domains.insert(s.domain);
    const Translation t = translate_to_gloss(s.text, inventory);
    for (const WordNote& n : t.notes) {
      const std::string word = lower(n.word);
      if (std::none_of(word.begin(), word.end(), [](unsigned char ch) { return std::isalpha(ch); })) continue;
      // An auxiliary the parse dropped ("have" of "have been waiting") is a function word here.
      if (function_words.count(word) || n.reason.find(" dropped: auxiliary") != std::string::npos) continue;
      const auto spelled = std::find_if(t.glosses.begin(), t.glosses.end(), [&](const GlossToken& g) {
        return g.kind == GlossKind::fingerspell && covers(g, n);
      });
      // Names and months are fingerspelled in ASL whatever the lexicon holds; they are not counted.
      if (spelled != t.glosses.end() && (spelled->reason.find("name (capitalized)") != std::string::npos ||
                                         spelled->reason.find("month") != std::string::npos))
        continue;
      ++c.content;
      const bool is_signed = spelled == t.glosses.end() &&
                             std::any_of(t.glosses.begin(), t.glosses.end(), [&](const GlossToken& g) {
                               return (g.kind == GlossKind::sign || g.kind == GlossKind::number) && covers(g, n);
                             });
      if (is_signed) ++c.signed_words;
      else ++c.missed[word];
    }
  }
  return c;
}

}  // namespace

TEST(EverydayCoverage, AtLeastThreeHundredSentencesOverEveryDomain) {
  const std::vector<EvalSentence> sentences = read_sentences();
  EXPECT_GE(sentences.size(), 300u);
  std::set<std::string> domains;
  for (const EvalSentence& s : sentences) domains.insert(s.domain);
  for (const char* d : {"home", "work", "travel", "health", "school", "shopping", "time", "weather"})
    EXPECT_TRUE(domains.count(d)) << d;
}

TEST(EverydayCoverage, ContentWordsAreSignedNotFingerspelled) {
  const Coverage c = measure();
  ASSERT_GT(c.content, 1000);
  const double share = static_cast<double>(c.signed_words) / c.content;
  std::string missed;
  for (const auto& [word, count] : c.missed) missed += " " + word;
  std::printf("everyday coverage: %d of %d content words signed (%.1f%%); not signed:%s\n", c.signed_words,
              c.content, 100.0 * share, missed.c_str());
  // Ratchet: 68.9% before the vocabulary of issue 15, 99.7% after (tools/coverage.py prints the same
  // figure); the held-out sentences (data/eval/heldout-sentences.txt, not used to choose signs) reach
  // 97.5% with the rule tables and 99.0% with link-grammar and WordNet.
  EXPECT_GE(share, 0.995);
}
