// Interchange speed: retargeting a MakeHuman pose (blended in from rest over `range` frames at
// 30 fps) onto the default avatar, with and without the end-effector fix-up, and glTF export.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "gestura/anim/retarget.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"

namespace {

struct Source {
  gestura::BvhFile bvh;
  gestura::Clip clip;
};

// sit01 reached from rest over `frames` frames (two keys per rotated joint).
Source sit_blend(int frames) {
  const char* dir = std::getenv("GESTURA_SHARED_DATA");
  Source s{gestura::load_bvh(std::string(dir ? dir : GESTURA_SHARED_DATA) + "/makehuman/poses/sit01.bvh", {0.1f, true}), {}};
  s.clip = s.bvh.clip;
  const float end = float(frames - 1) / 30.0f;
  const gestura::Pose rest = gestura::rest_pose(s.bvh.skeleton);
  for (std::size_t j = 0; j < s.clip.joint_count(); ++j) {
    gestura::QuatTrack& r = s.clip.rotations[j];
    if (r.empty()) continue;
    const gestura::quat pose = r.values[0];
    r.times = {0.0f, end};
    r.values = {rest.rotations[j], pose};
  }
  s.clip.duration = end;
  return s;
}

void BM_RetargetToAvatar(benchmark::State& state) {
  const Source s = sit_blend(static_cast<int>(state.range(0)));
  const gestura::Skeleton avatar = gestura::build_avatar_skeleton();
  gestura::RetargetOptions options;
  options.preserve_end_effectors = state.range(1) != 0;
  for (auto _ : state) benchmark::DoNotOptimize(gestura::retarget(s.bvh.skeleton, s.clip, avatar, options));
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations() * state.range(0)),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RetargetToAvatar)->Args({300, 0})->Args({300, 1})->Unit(benchmark::kMillisecond);

void BM_GltfExportGlb(benchmark::State& state) {
  const Source s = sit_blend(static_cast<int>(state.range(0)));
  const gestura::Skeleton avatar = gestura::build_avatar_skeleton();
  const gestura::Clip clip = gestura::retarget(s.bvh.skeleton, s.clip, avatar);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string glb = gestura::pack_glb(gestura::make_gltf(avatar, clip));
    bytes += glb.size();
    benchmark::DoNotOptimize(glb.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_GltfExportGlb)->Arg(300)->Unit(benchmark::kMillisecond);

}  // namespace
