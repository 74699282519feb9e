// Fingerspelling without rendering: a word planned and performed on the default avatar (hands by
// inverse kinematics every frame, then the eyes and head aimed at the hand every frame), and the
// gaze pass alone on that clip — what fingerspelling adds to `gestura say` besides the hands.
#include <benchmark/benchmark.h>

#include "gestura/face/eye_gaze.hpp"
#include "gestura/sentence/fingerspelling_performance.hpp"

namespace {

struct World {
  gestura::Avatar avatar = gestura::build_avatar();
  gestura::SigningRig rig = gestura::make_signing_rig(avatar);
};

const World& world() {
  static const World w;
  return w;
}

void BM_FingerspellWord(benchmark::State& state) {
  const auto alphabet = state.range(0) == 0 ? gestura::ManualAlphabet::Asl : gestura::ManualAlphabet::Bsl;
  for (auto _ : state) {
    const gestura::FingerspellingPerformance p =
        gestura::perform_fingerspelling(gestura::plan_spelling("HELLO", alphabet), world().rig);
    benchmark::DoNotOptimize(p.clip.rotations.data());
  }
}
BENCHMARK(BM_FingerspellWord)->Arg(0)->Arg(1)->ArgNames({"bsl"})->Unit(benchmark::kMillisecond);

void BM_EyeGaze(benchmark::State& state) {
  const gestura::FingerspellingPerformance p =
      gestura::perform_fingerspelling(gestura::plan_spelling("HELLO", gestura::ManualAlphabet::Asl), world().rig);
  double frames = 0.0;
  for (auto _ : state) {
    gestura::Clip clip = p.clip;
    gestura::face::write_eye_gaze(world().avatar.skeleton, clip, 30.0f);
    frames = static_cast<double>(clip.rotations[static_cast<std::size_t>(world().avatar.skeleton.find("skullbase"))].size());
    benchmark::DoNotOptimize(clip.rotations.data());
  }
  state.counters["frames"] = frames;
}
BENCHMARK(BM_EyeGaze)->Unit(benchmark::kMicrosecond);

}  // namespace
