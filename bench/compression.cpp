// W7 — compress a 15 s, 67-joint clip at 30 Hz (the synthetic humanoid and clip of
// anim/synthetic_motion.hpp: every joint turning about three axes as sums of sines, root swaying).
// Counters: bytes, raw bytes, ratio, max and 99th-percentile error (cm) on the ACL virtual points.
// References: ACL 91.6 KB at max 0.0128 cm from a 1.21 MB raw clip; ozz optimizer 78.8 KB at max
// 0.297 cm (different clips: compare orders of magnitude, not digits).
// W7_CompressFacePoseUnits — the same on real motion: MakeHuman's face pose units (60 frames at 24 Hz,
// 163 joints, read in metres, Y-up), at its own frame rate.
// W8 — decompress one full 67-joint pose at a time moving through the clip (reference: ACL ≈ 1.04 µs).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
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

void BM_W8_DecompressPose(benchmark::State& state) {
  const Skeleton skeleton = synthetic_humanoid();
  const Clip clip = synthetic_clip(skeleton, 15.0f, 30.0f);
  CompressionSettings settings;
  settings.max_error = static_cast<float>(state.range(0)) * 1e-5f;
  const CompressedClip c = compress(clip, skeleton, settings);
  Pose pose = rest_pose(skeleton);
  float t = 0.0f;
  for (auto _ : state) {
    c.sample(t, pose);
    benchmark::DoNotOptimize(pose.rotations.data());
    t += 0.0137f;
    if (t > c.duration()) t -= c.duration();
  }
  state.counters["joints"] = static_cast<double>(c.joint_count());
}
BENCHMARK(BM_W8_DecompressPose)->Arg(10)->Arg(300);

}  // namespace
