// W7 — compress a 15 s, 67-joint clip at 30 Hz (the synthetic humanoid and clip of
// anim/synthetic_motion.hpp: every joint turning about three axes as sums of sines, root swaying).
// Counters: bytes, raw bytes, ratio, max and 99th-percentile error (cm) on the ACL virtual points.
// References: ACL 91.6 KB at max 0.0128 cm from a 1.21 MB raw clip; ozz optimizer 78.8 KB at max
// 0.297 cm (different clips: compare orders of magnitude, not digits).
// W7_CompressFacePoseUnits — the same on real motion: MakeHuman's face pose units (60 frames at 24 Hz,
// 163 joints, read in metres, Y-up), at its own frame rate.
// W8 — decompress one full 67-joint pose: playing forward through a PlaybackContext, at random times,
// and with the stateless CompressedClip::sample (bench/anchors compares with ozz and ACL).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/compress/playback_context.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"

namespace {

using namespace gestura;

void compress_and_report(benchmark::State& state, const Clip& clip, const Skeleton& skeleton, float rate) {
  CompressionSettings settings;
  settings.max_error = static_cast<float>(state.range(0)) * 1e-5f;  // range in units of 0.001 cm
  settings.sample_rate = rate;
  CompressionReport report;
  for (auto _ : state) {
    CompressedClip c = compress(clip, skeleton, settings, &report);
    benchmark::DoNotOptimize(c.bytes().data());
  }
  state.counters["bytes"] = static_cast<double>(report.bytes);
  state.counters["raw_bytes"] = static_cast<double>(report.raw_bytes);
  state.counters["ratio"] = static_cast<double>(report.raw_bytes) / static_cast<double>(report.bytes);
  state.counters["max_error_cm"] = report.max_error * 100.0;
  state.counters["p99_error_cm"] = report.p99_error * 100.0;
  state.counters["passes"] = report.passes;
}

void BM_W7_Compress(benchmark::State& state) {
  const Skeleton skeleton = synthetic_humanoid();
  const Clip clip = synthetic_clip(skeleton, 15.0f, 30.0f);
  compress_and_report(state, clip, skeleton, 30.0f);
}
// Bounds 0.01 cm (ACL's regime) and 0.3 cm (ozz's).
BENCHMARK(BM_W7_Compress)->Arg(10)->Arg(300)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_W7_CompressFacePoseUnits(benchmark::State& state) {
  const char* dir = std::getenv("GESTURA_SHARED_DATA");
  const std::string path = std::string(dir ? dir : GESTURA_SHARED_DATA) + "/makehuman/poseunits/face-poseunits.bvh";
  BvhFile bvh;
  try {
    bvh = load_bvh(path, BvhReadOptions{0.1f, true});
  } catch (const Error& e) {
    return state.SkipWithError(e.what());
  }
  compress_and_report(state, bvh.clip, bvh.skeleton, 1.0f / bvh.frame_time);
}
BENCHMARK(BM_W7_CompressFacePoseUnits)->Arg(10)->Arg(300)->Unit(benchmark::kMillisecond)->Iterations(1);

const CompressedClip& w8_clip(int bound_in_0001cm) {
  static std::map<int, CompressedClip> clips;
  auto it = clips.find(bound_in_0001cm);
  if (it == clips.end()) {
    const Skeleton skeleton = synthetic_humanoid();
    const Clip clip = synthetic_clip(skeleton, 15.0f, 30.0f);
    CompressionSettings settings;
    settings.max_error = static_cast<float>(bound_in_0001cm) * 1e-5f;
    it = clips.emplace(bound_in_0001cm, compress(clip, skeleton, settings)).first;
  }
  return it->second;
}

// W8 forward: a 60 fps player on the 30 Hz clip, through a PlaybackContext.
void BM_W8_DecompressForward(benchmark::State& state, SimdPath path) {
  const CompressedClip& c = w8_clip(static_cast<int>(state.range(0)));
  PlaybackContext context;
  Pose pose;
  pose.resize(c.joint_count());
  float t = 0.0f;
  for (auto _ : state) {
    context.sample(c, t, pose, path);
    benchmark::DoNotOptimize(pose.rotations.data());
    t += 1.0f / 60.0f;
    if (t > c.duration()) t = 0.0f;
  }
  state.counters["joints"] = static_cast<double>(c.joint_count());
}
BENCHMARK_CAPTURE(BM_W8_DecompressForward, avx2, SimdPath::Auto)->Arg(10)->Arg(300);
BENCHMARK_CAPTURE(BM_W8_DecompressForward, portable, SimdPath::Portable)->Arg(10)->Arg(300);

// W8 random access: every sample a jump, through the context (no key can be reused).
void BM_W8_DecompressRandom(benchmark::State& state) {
  const CompressedClip& c = w8_clip(static_cast<int>(state.range(0)));
  PlaybackContext context;
  Pose pose;
  pose.resize(c.joint_count());
  std::vector<float> times(4096);
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> any(0.0f, c.duration());
  for (float& t : times) t = any(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    context.sample(c, times[i++ & 4095], pose);
    benchmark::DoNotOptimize(pose.rotations.data());
  }
}
BENCHMARK(BM_W8_DecompressRandom)->Arg(10)->Arg(300);

// The stateless CompressedClip::sample (decodes two keys per track every call), moving through the clip.
void BM_W8_DecompressPoseStateless(benchmark::State& state) {
  const CompressedClip& c = w8_clip(static_cast<int>(state.range(0)));
  Pose pose;
  pose.resize(c.joint_count());
  float t = 0.0f;
  for (auto _ : state) {
    c.sample(t, pose);
    benchmark::DoNotOptimize(pose.rotations.data());
    t += 0.0137f;
    if (t > c.duration()) t -= c.duration();
  }
  state.counters["joints"] = static_cast<double>(c.joint_count());
}
BENCHMARK(BM_W8_DecompressPoseStateless)->Arg(10)->Arg(300);

}  // namespace
