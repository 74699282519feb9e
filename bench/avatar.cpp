// Default avatar generation: the whole pipeline and its stages (polygonisation dominates).
#include <benchmark/benchmark.h>

#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/avatar_volume.hpp"
#include "gestura/body/polygonize.hpp"
#include "gestura/io/gltf_export.hpp"

static void BM_AvatarBuild(benchmark::State& state) {
  for (auto _ : state) {
    gestura::Avatar a = gestura::build_avatar();
    benchmark::DoNotOptimize(a.mesh.positions.data());
    state.counters["triangles"] = static_cast<double>(a.mesh.triangle_count());
  }
}
BENCHMARK(BM_AvatarBuild)->Unit(benchmark::kMillisecond);

static void BM_AvatarPolygonize(benchmark::State& state) {
  const gestura::AvatarParams params;
  const gestura::Skeleton skeleton = gestura::build_avatar_skeleton(params);
  const gestura::ImplicitBody body = gestura::build_avatar_volume(skeleton, params);
  gestura::PolygonizeOptions options;
  options.cell = 0.016f;
  options.detail = gestura::avatar_detail_boxes(skeleton, params);
  for (auto _ : state) {
    gestura::Polygonization p = gestura::polygonize(body, options);
    benchmark::DoNotOptimize(p.indices.data());
  }
}
BENCHMARK(BM_AvatarPolygonize)->Unit(benchmark::kMillisecond);

static void BM_AvatarSkinWeights(benchmark::State& state) {
  const gestura::Avatar a = gestura::build_avatar();
  const gestura::ImplicitBody body = gestura::build_avatar_volume(a.skeleton, a.params);
  const auto method = static_cast<gestura::SkinWeightMethod>(state.range(0));
  gestura::Mesh mesh = a.mesh;
  for (auto _ : state) {
    gestura::compute_skin_weights(a.skeleton, body, method, mesh);
    benchmark::DoNotOptimize(mesh.weights.data());
  }
  state.SetLabel(std::string(gestura::to_string(method)));
}
BENCHMARK(BM_AvatarSkinWeights)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

static void BM_AvatarEncodeGlb(benchmark::State& state) {
  const gestura::Avatar a = gestura::build_avatar();
  for (auto _ : state) {
    auto bytes = gestura::encode_glb(a.skeleton, a.mesh);
    benchmark::DoNotOptimize(bytes.data());
    state.counters["bytes"] = static_cast<double>(bytes.size());
  }
}
BENCHMARK(BM_AvatarEncodeGlb)->Unit(benchmark::kMillisecond);
