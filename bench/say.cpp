// gestura say without rendering (S1): a 15-word English sentence → the whole performance
// (translation, lexicon, sign planning and joining, joint motion, face channels), and its parts.
// Warm: the signer has performed these signs before (their citation motion is cached); cold: a
// fresh signer, so every sign is planned and solved by IK first (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sentence/citation_store.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/sign_performer.hpp"
#include "gestura/text/lexicon_inventory.hpp"
#include "gestura/text/translator.hpp"

namespace {

// 15 words, all with built-in signs except the name (fingerspelled).
constexpr const char* kSentence = "Yesterday my sister and I went to the big store and bought a new book for Anna.";

struct World {
  gestura::Avatar avatar = gestura::build_avatar();
  gestura::Lexicon builtin = gestura::load_builtin_lexicon(gestura::builtin_lexicon_files());
  gestura::LayeredLexicon layers;
  std::optional<gestura::Signer> signer;
  World() {
    layers.push_layer(builtin);
    signer.emplace(avatar, layers);
  }
};

World& world() {
  static World w;
  return w;
}

void BM_SaySentence(benchmark::State& state) {
  gestura::SayOptions options;
  options.mouthing = state.range(0) != 0;
  gestura::SentencePerformance p;
  for (auto _ : state) {
    p = world().signer->say(kSentence, options);
    benchmark::DoNotOptimize(p.clip.rotations.data());
  }
  state.counters["performance_s"] = p.duration;
  state.counters["transitions"] = p.motion.transitions;
  state.counters["bent"] = p.motion.via;
  state.counters["ik_every_frame"] = p.motion.escaped;
}
BENCHMARK(BM_SaySentence)->Arg(1)->Arg(0)->ArgNames({"mouthing"})->Unit(benchmark::kMillisecond);

// S1 warm on a text the signer has not met (its signs it has): the 15-word sentence with a new
// name every iteration ("… for Annaab."), so the text is translated and parsed afresh each time
// rather than found among the texts translated before (sentence/lexicon_memo.hpp).
void BM_SaySentenceUnseenText(benchmark::State& state) {
  gestura::SayOptions options;
  options.mouthing = false;
  const std::string stem(kSentence, std::string_view(kSentence).size() - 1);  // without the full stop
  world().signer->say(kSentence, options);
  gestura::SentencePerformance p;
  std::size_t k = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::string text = stem;
    for (std::size_t n = ++k; n > 0; n /= 26) text.push_back(static_cast<char>('a' + n % 26));
    text.push_back('.');
    state.ResumeTiming();
    p = world().signer->say(text, options);
    benchmark::DoNotOptimize(p.clip.rotations.data());
  }
  state.counters["performance_s"] = p.duration;
}
BENCHMARK(BM_SaySentenceUnseenText)->Unit(benchmark::kMillisecond);

// A sentence two of whose transitions would pass through the head (SLEEP at the face): they are bent
// through via postures and re-solved by IK in their middle, every call.
void BM_SayBentTransitions(benchmark::State& state) {
  gestura::SentencePerformance p;
  for (auto _ : state) {
    p = world().signer->say("The dog and the cat sleep in the house.");
    benchmark::DoNotOptimize(p.clip.rotations.data());
  }
  state.counters["transitions"] = p.motion.transitions;
  state.counters["bent"] = p.motion.via;
  state.counters["ik_every_frame"] = p.motion.escaped;
}
BENCHMARK(BM_SayBentTransitions)->Unit(benchmark::kMillisecond);

// The first call on a new signer (building the signer itself is not timed).
void BM_SaySentenceCold(benchmark::State& state) {
  gestura::SayOptions options;
  options.mouthing = state.range(0) != 0;
  std::optional<gestura::Signer> signer;
  for (auto _ : state) {
    state.PauseTiming();
    signer.reset();
    signer.emplace(world().avatar, world().layers);
    state.ResumeTiming();
    benchmark::DoNotOptimize(signer->say(kSentence, options).clip.rotations.data());
  }
}
BENCHMARK(BM_SaySentenceCold)->Arg(1)->Arg(0)->ArgNames({"mouthing"})->Unit(benchmark::kMillisecond);

// A second `gestura say` process: a new signer whose citation forms an earlier one kept in the
// user lexicon database (sentence/citation_store.hpp). Opening the store is timed, building the
// signer is not.
void BM_SaySentenceColdStored(benchmark::State& state) {
  gestura::SayOptions options;
  options.mouthing = state.range(0) != 0;
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("gestura-bench-citations-" + std::to_string(::getpid()) + ".sqlite")).string();
  {
    gestura::Signer first(world().avatar, world().layers);
    first.keep_citations_in(path);
    first.say(kSentence, options);
  }
  std::optional<gestura::Signer> signer;
  std::size_t loaded = 0;
  for (auto _ : state) {
    state.PauseTiming();
    signer.reset();
    signer.emplace(world().avatar, world().layers);
    state.ResumeTiming();
    signer->keep_citations_in(path);
    benchmark::DoNotOptimize(signer->say(kSentence, options).clip.rotations.data());
    loaded = signer->store()->loaded();
  }
  signer.reset();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  state.counters["signs_loaded"] = static_cast<double>(loaded);
}
BENCHMARK(BM_SaySentenceColdStored)->Arg(1)->Arg(0)->ArgNames({"mouthing"})->Unit(benchmark::kMillisecond);

// The former motion step for comparison: the same utterance plan performed with IK every frame
// (sign_performer's perform_plan), instead of stitching cached motion.
void BM_SayPlanWithIkEveryFrame(benchmark::State& state) {
  const gestura::SentencePerformance p = world().signer->say(kSentence);
  for (auto _ : state)
    benchmark::DoNotOptimize(gestura::perform_plan(p.plan, world().signer->rig(), {}).rotations.data());
}
BENCHMARK(BM_SayPlanWithIkEveryFrame)->Unit(benchmark::kMillisecond);

// The translation step alone, with a fresh (uncached) inventory each time like say() uses.
void BM_SayTranslate(benchmark::State& state) {
  for (auto _ : state) {
    gestura::LexiconInventory inventory(world().layers, "ase");
    benchmark::DoNotOptimize(gestura::translate_to_gloss(kSentence, inventory).glosses.data());
  }
}
BENCHMARK(BM_SayTranslate)->Unit(benchmark::kMicrosecond);

// Looking up a gloss in the built-in lexicon (what say() does once per sign).
void BM_BuiltinLexiconFind(benchmark::State& state) {
  const char* glosses[] = {"MOTHER", "STORE", "BUY", "BOOK", "NEW", "GO", "YESTERDAY", "SISTER"};
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(world().layers.find(glosses[i++ % 8], "ase"));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BuiltinLexiconFind);

}  // namespace
