// Cleaning the avatar's marching-cubes surface: our short-edge collapse (body/mesh_simplify) against
// meshoptimizer's quadric simplifier at the same triangle count. Time per run, and the quality of
// the result as counters: triangles, slivers (smallest angle under 10°), the 1st percentile of the
// smallest angle, and how far triangle centres and edge midpoints lie from the true (implicit)
// surface — mean and max, in millimetres. Built only when meshoptimizer is installed.
#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/body/avatar_volume.hpp"
#include "gestura/body/mesh_simplify.hpp"
#include "gestura/body/polygonize.hpp"

namespace {

using gestura::vec3;

struct Surface {
  gestura::ImplicitBody body;
  gestura::Polygonization raw;
};

// The surface build_avatar polygonises (same cell, detail boxes and bind-pose jaw), before cleaning.
const Surface& avatar_surface() {
  static const Surface surface = [] {
    Surface s;
    const gestura::AvatarParams params;
    const gestura::Skeleton skeleton = gestura::build_avatar_skeleton(params);
    s.body = gestura::build_avatar_volume(skeleton, params, gestura::proportions::kBindJawOpenDegrees);
    gestura::PolygonizeOptions options;
    options.cell = 0.016f;
    options.detail = gestura::avatar_detail_boxes(skeleton, params);
    s.raw = gestura::polygonize(s.body, options);
    return s;
  }();
  return surface;
}

struct Mesh {
  std::vector<vec3> positions;
  std::vector<std::uint32_t> indices;
};

float smallest_angle(const vec3& a, const vec3& b, const vec3& c) {
  const auto angle = [](const vec3& p, const vec3& q, const vec3& r) {
    const vec3 u = glm::normalize(q - p), v = glm::normalize(r - p);
    return std::acos(std::clamp(glm::dot(u, v), -1.0f, 1.0f));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// Quality counters of a cleaned mesh against the implicit surface.
void measure(benchmark::State& state, const Mesh& m, const gestura::ImplicitBody& body) {
  std::vector<float> angles;
  double deviation_sum = 0.0, deviation_max = 0.0;
  std::size_t samples = 0;
  const auto deviation = [&](const vec3& p) {
    const float g = glm::length(body.gradient(p));
    const double d = g > 1e-6f ? std::abs(body.field(p)) / g : 0.0;
    deviation_sum += d, deviation_max = std::max(deviation_max, d), ++samples;
  };
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    angles.push_back(smallest_angle(a, b, c));
    if (t % 9 == 0) {  // every third triangle: its centre and the middle of its first edge
      deviation((a + b + c) / 3.0f);
      deviation(0.5f * (a + b));
    }
  }
  std::sort(angles.begin(), angles.end());
  const auto slivers = std::count_if(angles.begin(), angles.end(), [](float a) { return a < gestura::deg(10.0f); });
  state.counters["triangles"] = static_cast<double>(angles.size());
  state.counters["slivers_under_10deg"] = static_cast<double>(slivers);
  state.counters["p1_min_angle_deg"] = gestura::to_degrees(angles[angles.size() / 100]);
  state.counters["mean_dev_mm"] = 1e3 * deviation_sum / static_cast<double>(samples);
  state.counters["max_dev_mm"] = 1e3 * deviation_max;
}

Mesh ours() {
  const Surface& s = avatar_surface();
  Mesh m{s.raw.positions, s.raw.indices};
  gestura::collapse_short_edges(m.positions, m.indices, 0.5f);
  return m;
}

void BM_CleanSurfaceRaw(benchmark::State& state) {
  const Surface& s = avatar_surface();
  for (auto _ : state) benchmark::DoNotOptimize(s.raw.indices.data());
  measure(state, Mesh{s.raw.positions, s.raw.indices}, s.body);
}
BENCHMARK(BM_CleanSurfaceRaw)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_CleanSurfaceCollapseShortEdges(benchmark::State& state) {
  Mesh m;
  for (auto _ : state) {
    m = ours();
    benchmark::DoNotOptimize(m.indices.data());
  }
  measure(state, m, avatar_surface().body);
}
BENCHMARK(BM_CleanSurfaceCollapseShortEdges)->Unit(benchmark::kMillisecond);

// meshopt_simplify to the triangle count our collapse reaches, error bound 1 % of the mesh extent
// (the count, not the bound, is what stops it).
void BM_CleanSurfaceMeshoptSimplify(benchmark::State& state) {
  const Surface& s = avatar_surface();
  const std::size_t target = ours().indices.size();
  Mesh m;
  float error = 0.0f;
  for (auto _ : state) {
    m.indices.assign(s.raw.indices.size(), 0);
    const std::size_t n = meshopt_simplify(m.indices.data(), s.raw.indices.data(), s.raw.indices.size(),
                                           &s.raw.positions[0].x, s.raw.positions.size(), sizeof(vec3), target, 0.01f,
                                           0, &error);
    m.indices.resize(n);
    benchmark::DoNotOptimize(m.indices.data());
  }
  m.positions = s.raw.positions;
  state.counters["meshopt_error_rel"] = error;
  measure(state, m, s.body);
}
BENCHMARK(BM_CleanSurfaceMeshoptSimplify)->Unit(benchmark::kMillisecond);

}  // namespace
