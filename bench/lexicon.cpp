// Lexicon lookups on a 5,000-sign SQLite file, and English → gloss translation of a 15-word sentence.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "gestura/lexicon/layered_lexicon.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace {

constexpr int kSigns = 5000;

std::string gloss_of(int i) { return "SIGN" + std::to_string(i); }
std::string keyword_of(int i) { return "word" + std::to_string(i); }

// One generated lexicon file per process: 5,000 signs with two keywords each, plus the words of the
// benchmark sentence.
gestura::Lexicon& lexicon() {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("gestura-bench-lexicon-" + std::to_string(::getpid()) + ".sqlite"))
          .string();
  static gestura::Lexicon lex = [] {
    std::filesystem::remove(path);
    gestura::Lexicon l = gestura::Lexicon::open(path);
    l.atomically([&] {
      for (int i = 0; i < kSigns; ++i) {
        gestura::SignEntry e;
        e.gloss = gloss_of(i);
        e.language = "ase";
        e.notation = "\xee\x80\x80\xee\x80\x81\xee\x80\x82\xee\x80\x83";
        e.keywords = {gestura::Keyword{keyword_of(i)}, gestura::Keyword{"alt" + std::to_string(i)}};
        l.add(std::move(e));
      }
      for (const char* w : {"sister", "and", "go", "big", "store", "buy", "new", "book"}) {
        gestura::SignEntry e;
        e.gloss = w;
        for (char& c : e.gloss) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        e.language = "ase";
        e.notation = "x";
        e.keywords = {gestura::Keyword{w}};
        l.add(std::move(e));
      }
    });
    std::atexit([] {
      std::filesystem::remove(path);
      std::filesystem::remove(path + "-wal");
      std::filesystem::remove(path + "-shm");
    });
    return l;
  }();
  return lex;
}

void BM_LexiconFindByGloss(benchmark::State& state) {
  auto& lex = lexicon();
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> pick(0, kSigns - 1);
  for (auto _ : state) {
    auto found = lex.find(gloss_of(pick(rng)), "ase");
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LexiconFindByGloss);

void BM_LexiconByKeyword(benchmark::State& state) {
  auto& lex = lexicon();
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> pick(0, kSigns - 1);
  for (auto _ : state) {
    auto found = lex.by_keyword(keyword_of(pick(rng)), "ase");
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LexiconByKeyword);

void BM_LexiconSearchPrefix(benchmark::State& state) {
  auto& lex = lexicon();
  for (auto _ : state) {
    auto found = lex.search("word12", gestura::SearchMode::prefix, "ase", 20);
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LexiconSearchPrefix);

// 15 words: contraction, article, prepositions, irregular verb, plural, pronouns, time expression.
constexpr const char* kSentence = "Yesterday my sister and I didn't go to the big store to buy new books.";

void BM_GlossSentenceWordList(benchmark::State& state) {
  gestura::WordListInventory words{{"sister", "SISTER"}, {"and", "AND"}, {"go", "GO"}, {"big", "BIG"},
                                   {"store", "STORE"},   {"buy", "BUY"}, {"new", "NEW"}, {"book", "BOOK"}};
  for (auto _ : state) {
    auto t = gestura::translate_to_gloss(kSentence, words);
    benchmark::DoNotOptimize(t);
  }
  state.SetLabel(gestura::translate_to_gloss(kSentence, words).text());
}
BENCHMARK(BM_GlossSentenceWordList)->Unit(benchmark::kMicrosecond);

// Against the 5,000-sign SQLite lexicon with a fresh (cold) inventory cache each time.
void BM_GlossSentenceLexicon(benchmark::State& state) {
  gestura::LayeredLexicon layers;
  layers.push_layer(lexicon());
  for (auto _ : state) {
    gestura::LexiconInventory inventory(layers, "ase");
    auto t = gestura::translate_to_gloss(kSentence, inventory);
    benchmark::DoNotOptimize(t);
  }
  gestura::LexiconInventory inventory(layers, "ase");
  state.SetLabel(gestura::translate_to_gloss(kSentence, inventory).text());
}
BENCHMARK(BM_GlossSentenceLexicon)->Unit(benchmark::kMicrosecond);

}  // namespace
