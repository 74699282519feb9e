// The face layer's cost for one sentence: eSpeak NG phonemization and the viseme/jaw/rounding
// actions and keys of its mouthing, and the non-manual markers of a planned sentence.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/face/mouthing.hpp"
#include "gestura/face/nonmanual.hpp"
#include "gestura/face/phonemizer.hpp"
#include "gestura/face/viseme_track.hpp"

using namespace gestura;
using namespace gestura::face;

namespace {

const std::vector<std::string> kSentence{"yesterday", "my",  "brother", "and",    "I",
                                         "went",      "to",  "the",     "market", "to",
                                         "buy",       "fresh", "bread", "and",    "cheese"};  // 15 words

// Phonemize each word and key its mouthing over a 0.5 s sign: what sign synthesis pays per sentence.
void Face_MouthingSentence15Words(benchmark::State& state) {
  std::vector<FaceAction> actions;
  for (auto _ : state) {
    actions.clear();
    float t = 0.0f;
    for (const std::string& w : kSentence) {
      append_mouthing(w, t, t + 0.5f, {}, actions);
      t += 0.5f;
    }
    Clip clip;
    write_face_channels(actions, clip);
    benchmark::DoNotOptimize(clip.channels.data());
  }
  state.counters["actions"] = static_cast<double>(actions.size());
}
BENCHMARK(Face_MouthingSentence15Words)->Unit(benchmark::kMicrosecond);

// The same without eSpeak: phonemes computed once, only the viseme actions and keys.
void Face_VisemeTrackOnly15Words(benchmark::State& state) {
  std::vector<std::vector<Phoneme>> phonemes;
  for (const std::string& w : kSentence) phonemes.push_back(phonemize(w));
  std::vector<FaceAction> actions;
  for (auto _ : state) {
    actions.clear();
    float t = 0.0f;
    for (const auto& p : phonemes) {
      append_viseme_actions(p, t, t + 0.5f, 1.0f, actions);
      t += 0.5f;
    }
    Clip clip;
    write_face_channels(actions, clip);
    benchmark::DoNotOptimize(clip.channels.data());
  }
}
BENCHMARK(Face_VisemeTrackOnly15Words)->Unit(benchmark::kMicrosecond);

// Non-manual markers of a 15-sign plan: a topic, a negated span, a yes/no question, blinks, head keys.
void Face_NonManual15Signs(benchmark::State& state) {
  const Skeleton skeleton = build_avatar_skeleton();
  NonManualPlan plan;
  for (int i = 0; i < 15; ++i) plan.glosses.push_back({0.5f * static_cast<float>(i), 0.5f * static_cast<float>(i + 1)});
  plan.spans = {{NonManualKind::topic, 0, 3}, {NonManualKind::negation, 5, 9}, {NonManualKind::yes_no_question, 10, 15}};
  plan.boundaries = {1.5f, 4.5f};
  for (auto _ : state) {
    Clip clip;
    add_nonmanual_markers(plan, skeleton, clip);
    benchmark::DoNotOptimize(clip.channels.data());
  }
}
BENCHMARK(Face_NonManual15Signs)->Unit(benchmark::kMicrosecond);

}  // namespace
