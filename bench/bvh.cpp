// BVH reading and writing speed on MakeHuman's face pose units (163 joints, 492 channels), with its
// 60 frames repeated to a longer take (state.range(0) frames) so the motion section dominates.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gestura/io/bvh.hpp"

namespace {

std::string face_units_text() {
  const char* dir = std::getenv("GESTURA_SHARED_DATA");
  const std::string path = std::string(dir ? dir : GESTURA_SHARED_DATA) + "/makehuman/poseunits/face-poseunits.bvh";
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The file with its motion lines repeated until there are `frames` of them.
std::string long_take(int frames) {
  const std::string text = face_units_text();
  const std::size_t motion = text.find("MOTION");
  std::istringstream in(text.substr(motion));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != 'M' && line[0] != 'F') lines.push_back(line);
  if (lines.empty()) return {};
  std::string out = text.substr(0, motion) + "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: 0.041667\n";
  for (int f = 0; f < frames; ++f) out += lines[static_cast<std::size_t>(f) % lines.size()] + "\n";
  return out;
}

void BM_BvhRead(benchmark::State& state) {
  const std::string text = long_take(static_cast<int>(state.range(0)));
  if (text.empty()) return state.SkipWithError("face-poseunits.bvh not found (set GESTURA_SHARED_DATA)");
  for (auto _ : state) benchmark::DoNotOptimize(gestura::read_bvh(text, "face.bvh"));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations() * state.range(0)),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BvhRead)->Arg(60)->Arg(2400)->Unit(benchmark::kMillisecond);

void BM_BvhWrite(benchmark::State& state) {
  const std::string text = long_take(static_cast<int>(state.range(0)));
  if (text.empty()) return state.SkipWithError("face-poseunits.bvh not found (set GESTURA_SHARED_DATA)");
  const gestura::BvhFile bvh = gestura::read_bvh(text, "face.bvh");
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string out = gestura::write_bvh(bvh);
    bytes += out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations() * state.range(0)),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BvhWrite)->Arg(60)->Arg(2400)->Unit(benchmark::kMillisecond);

}  // namespace
