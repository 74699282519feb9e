// W1–W3: the per-frame animation core on the shared 67-joint, 15 s test clip (anim/synthetic_motion.hpp,
// the same subject as W7/W8). Numbers are per character-frame.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "gestura/anim/blend.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/anim/synthetic_motion.hpp"

using namespace gestura;

namespace {

struct Fixture {
  Skeleton skeleton = synthetic_humanoid();
  Clip clip = synthetic_clip(skeleton, 15.0f, 30.0f);
  Pose rest = rest_pose(skeleton);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// W1a: sampling only, forward playback at 30 Hz with per-track cursors.
void W1_SampleForward30Hz(benchmark::State& state) {
  const Fixture& f = fixture();
  Sampler sampler(f.clip);
  Pose pose = f.rest;
  float t = 0.0f;
  for (auto _ : state) {
    sampler.sample(t, WrapMode::Loop, f.rest, pose);
    benchmark::DoNotOptimize(pose.rotations.data());
    t += 1.0f / 30.0f;
    if (t > f.clip.duration) t -= f.clip.duration;
  }
  state.counters["joints"] = static_cast<double>(f.skeleton.size());
}
BENCHMARK(W1_SampleForward30Hz);

// W1b: local-to-model of the sampled pose.
void W1_LocalToModel(benchmark::State& state) {
  const Fixture& f = fixture();
  Pose pose = f.rest;
  sample_clip(f.clip, 3.3f, WrapMode::Clamp, f.rest, pose);
  std::vector<mat4> model(f.skeleton.size());
  for (auto _ : state) {
    local_to_model(f.skeleton.parents, pose.translations, pose.rotations, pose.scales, model);
    benchmark::DoNotOptimize(model.data());
  }
}
BENCHMARK(W1_LocalToModel);

// W1: both, as a player does every frame.
void W1_SampleAndLocalToModel(benchmark::State& state) {
  const Fixture& f = fixture();
  Sampler sampler(f.clip);
  Pose pose = f.rest;
  std::vector<mat4> model(f.skeleton.size());
  float t = 0.0f;
  for (auto _ : state) {
    sampler.sample(t, WrapMode::Loop, f.rest, pose);
    local_to_model(f.skeleton.parents, pose.translations, pose.rotations, pose.scales, model);
    benchmark::DoNotOptimize(model.data());
    t += 1.0f / 30.0f;
    if (t > f.clip.duration) t -= f.clip.duration;
  }
}
BENCHMARK(W1_SampleAndLocalToModel);

// W2: random seek into the 15 s clip (a fresh binary search per track).
void W2_RandomSeek(benchmark::State& state) {
  const Fixture& f = fixture();
  Sampler sampler(f.clip);
  Pose pose = f.rest;
  std::vector<float> times(4096);
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> any(0.0f, f.clip.duration);
  for (float& t : times) t = any(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    sampler.sample(times[i++ & 4095], WrapMode::Clamp, f.rest, pose);
    benchmark::DoNotOptimize(pose.rotations.data());
  }
}
BENCHMARK(W2_RandomSeek);

struct BlendFixture {
  Pose a, b, c, delta, out;
  std::vector<float> upper_body;
  BlendFixture() {
    const Fixture& f = fixture();
    sample_clip(f.clip, 1.0f, WrapMode::Clamp, f.rest, a);
    sample_clip(f.clip, 5.0f, WrapMode::Clamp, f.rest, b);
    sample_clip(f.clip, 9.0f, WrapMode::Clamp, f.rest, c);
    make_additive(f.rest, c, delta);
    upper_body.assign(f.skeleton.size(), 0.0f);
    for (std::size_t j = 0; j < f.skeleton.size(); ++j) {
      const std::string& n = f.skeleton.names[j];
      if (n.find("hip") == std::string::npos && n.find("knee") == std::string::npos &&
          n.find("ankle") == std::string::npos && n.find("toes") == std::string::npos)
        upper_body[j] = 1.0f;
    }
  }
};

// W3a: three full layers, weighted (one priority, no masks: the fast path).
void W3_Blend3Layers(benchmark::State& state, SimdPath path) {
  static BlendFixture bf;
  const Fixture& f = fixture();
  const BlendLayer layers[] = {{&bf.a, 0.5f}, {&bf.b, 0.3f}, {&bf.c, 0.2f}};
  for (auto _ : state) {
    blend_layers(layers, f.rest, bf.out, path);
    benchmark::DoNotOptimize(bf.out.rotations.data());
  }
}
BENCHMARK_CAPTURE(W3_Blend3Layers, avx2, SimdPath::Auto);
BENCHMARK_CAPTURE(W3_Blend3Layers, portable, SimdPath::Portable);

// W3b: two layers, the upper one masked to the upper body at a higher priority, plus one additive
// layer, in one call.
void W3_Blend2MaskedPlusAdditive(benchmark::State& state, SimdPath path) {
  static BlendFixture bf;
  const Fixture& f = fixture();
  const BlendLayer layers[] = {{&bf.a, 1.0f, {}, 0}, {&bf.b, 1.0f, bf.upper_body, 1}, {&bf.delta, 0.7f, {}, 0, true}};
  for (auto _ : state) {
    blend_layers(layers, f.rest, bf.out, path);
    benchmark::DoNotOptimize(bf.out.rotations.data());
  }
}
BENCHMARK_CAPTURE(W3_Blend2MaskedPlusAdditive, avx2, SimdPath::Auto);
BENCHMARK_CAPTURE(W3_Blend2MaskedPlusAdditive, portable, SimdPath::Portable);

}  // namespace
