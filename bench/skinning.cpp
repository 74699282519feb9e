// W5: skinning the MakeHuman base mesh (19,158 vertices incl. helpers, real weights truncated to 4
// influences) in a pose with every joint turned a few degrees. Numbers are per frame; "Mvert"
// is vertices per second. Each kernel runs on both paths (portable and AVX2+FMA).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gestura/body/skinning.hpp"
#include "gestura/io/makehuman.hpp"

using namespace gestura;

namespace {

struct SkinningFixture {
  MakeHumanBody body;
  std::vector<mat4> skinning;
  std::vector<DualQuat> dual;
  std::vector<vec3> positions, normals;
};

// Loaded once; null when the shared data is absent. GESTURA_SHARED_DATA in the environment
// overrides the build-time path.
const SkinningFixture* fixture() {
  static const std::unique_ptr<SkinningFixture> f = []() -> std::unique_ptr<SkinningFixture> {
    const char* env = std::getenv("GESTURA_SHARED_DATA");
    const std::string dir = std::string(env && *env ? env : GESTURA_SHARED_DATA) + "/makehuman";
    if (!std::filesystem::exists(dir + "/base.obj")) return nullptr;
    auto out = std::make_unique<SkinningFixture>();
    out->body = load_makehuman(dir);
    const Skeleton& s = out->body.rig.skeleton;
    Pose pose = rest_pose(s);
    for (std::size_t j = 0; j < s.size(); ++j) {  // 2–6° about a joint-dependent axis
      const float k = static_cast<float>(j);
      const vec3 axis = glm::normalize(vec3(std::sin(k), std::cos(1.3f * k), 0.5f));
      pose.rotations[j] = glm::angleAxis(deg(2.0f + 4.0f * std::abs(std::sin(0.7f * k))), axis) * pose.rotations[j];
    }
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    out->skinning.resize(s.size());
    skinning_matrices(model, out->body.rig.inverse_bind, out->skinning);
    out->dual.resize(s.size());
    skinning_dual_quaternions(out->skinning, out->dual);
    const std::size_t n = out->body.mesh.mesh.vertex_count();
    out->positions.resize(n);
    out->normals.resize(n);
    return out;
  }();
  return f.get();
}

// Shared preamble: skip without data or without the requested path; report throughput.
template <class Kernel>
void run(benchmark::State& state, SkinningPath path, Kernel kernel) {
  SkinningFixture* f = const_cast<SkinningFixture*>(fixture());
  if (!f) {
    state.SkipWithError("no MakeHuman data (set GESTURA_SHARED_DATA to the shared data directory)");
    return;
  }
  if (path == SkinningPath::Avx2 && !cpu_has_avx2_fma()) {
    state.SkipWithError("CPU without AVX2+FMA");
    return;
  }
  const Mesh& m = f->body.mesh.mesh;
  for (auto _ : state) {
    kernel(*f, m);
    benchmark::DoNotOptimize(f->positions.data());
    benchmark::DoNotOptimize(f->normals.data());
    benchmark::ClobberMemory();
  }
  const double n = static_cast<double>(m.vertex_count());
  state.counters["vertices"] = n;
  state.counters["Mvert"] = benchmark::Counter(n * 1e-6 * static_cast<double>(state.iterations()),
                                                 benchmark::Counter::kIsRate);
}

void W5_LbsPositions(benchmark::State& state, SkinningPath path) {
  run(state, path, [path](SkinningFixture& f, const Mesh& m) {
    skin_positions(f.skinning, m.joints, m.weights, m.positions, f.positions, path);
  });
}

void W5_LbsPositionsNormals(benchmark::State& state, SkinningPath path) {
  run(state, path, [path](SkinningFixture& f, const Mesh& m) {
    skin_positions_normals(f.skinning, m.joints, m.weights, m.positions, m.normals, f.positions, f.normals, path);
  });
}

void W5_DqsPositions(benchmark::State& state, SkinningPath path) {
  run(state, path, [path](SkinningFixture& f, const Mesh& m) {
    skin_dual_quaternion(f.dual, m.joints, m.weights, m.positions, {}, f.positions, {}, path);
  });
}

void W5_DqsPositionsNormals(benchmark::State& state, SkinningPath path) {
  run(state, path, [path](SkinningFixture& f, const Mesh& m) {
    skin_dual_quaternion(f.dual, m.joints, m.weights, m.positions, m.normals, f.positions, f.normals, path);
  });
}

}  // namespace

BENCHMARK_CAPTURE(W5_LbsPositions, portable, SkinningPath::Portable)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_LbsPositions, avx2, SkinningPath::Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_LbsPositionsNormals, portable, SkinningPath::Portable)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_LbsPositionsNormals, avx2, SkinningPath::Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_DqsPositions, portable, SkinningPath::Portable)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_DqsPositions, avx2, SkinningPath::Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_DqsPositionsNormals, portable, SkinningPath::Portable)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(W5_DqsPositionsNormals, avx2, SkinningPath::Avx2)->Unit(benchmark::kMicrosecond);
