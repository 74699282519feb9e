// R1: headless rendering speed of a ~25k-triangle skinned figure at 1280×720 on llvmpipe — GPU vs
// CPU skinning, where a frame's time goes (draw, readback, encode) and export speed. The fps
// counter is frames per second; `x_realtime_30fps` is that divided by 30.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "gestura/render/cpu_skinning.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/render/test_figure.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct Scene {
  HeadlessGlContext context;
  RenderSubject figure = make_test_figure(2);
  Animator animator{figure};
  Renderer renderer{Look{}, 4};
  Renderer single_sample{Look{}, 1};
  std::vector<View> views;
  Scene() {
    for (Renderer* r : {&renderer, &single_sample}) {
      r->upload(figure.mesh);
      r->resize(kWidth, kHeight);
    }
    for (Renderer* r : {&renderer, &single_sample})  // compile shaders, fill caches
      for (SkinningPath path : {SkinningPath::Gpu, SkinningPath::Cpu}) {
        r->render(views, animator.skinning(), animator.morph_weights(), path);
        r->finish();
      }
    views.push_back({preset_camera(CameraPreset::Front, framing_box(figure.mesh, figure.skeleton),
                                   float(kWidth) / kHeight), {0, 0, kWidth, kHeight}});
  }
  void draw(int frame, SkinningPath path) {
    animator.pose_at(static_cast<float>(frame % 60) / 30.0f);
    renderer.render(views, animator.skinning(), animator.morph_weights(), path);
  }
};

Scene& scene() {
  static Scene s;
  return s;
}

// CPU time of the whole process (llvmpipe's rasteriser threads and the encoder's included): on a
// shared machine the work per frame is steadier than the wall time.
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

struct CpuMeter {
  double start = process_cpu_seconds();
  void report(benchmark::State& state) const {
    state.counters["process_cpu_ms_per_frame"] =
        (process_cpu_seconds() - start) * 1000.0 / static_cast<double>(std::max<benchmark::IterationCount>(1, state.iterations()));
  }
};

void set_counters(benchmark::State& state) {
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["x_realtime_30fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()) / 30.0, benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(scene().figure.mesh.triangle_count());
}

// Draw only (pose, skin, draw, MSAA resolve), waiting for the GL to finish. Args: skinning path
// (0 GPU, 1 CPU), MSAA samples (4 or 1).
void BM_R1_Draw(benchmark::State& state) {
  Scene& s = scene();
  const auto path = static_cast<SkinningPath>(state.range(0));
  Renderer& renderer = state.range(1) == 4 ? s.renderer : s.single_sample;
  int frame = 0;
  const CpuMeter meter;
  for (auto _ : state) {
    s.animator.pose_at(static_cast<float>(frame++ % 60) / 30.0f);
    renderer.render(s.views, s.animator.skinning(), s.animator.morph_weights(), path);
    renderer.finish();
  }
  meter.report(state);
  set_counters(state);
  state.SetLabel(std::string(path == SkinningPath::Gpu ? "gpu skinning" : "cpu skinning + upload") +
                 (state.range(1) == 4 ? ", 4x msaa" : ", no msaa") + "; " + s.context.description());
}
BENCHMARK(BM_R1_Draw)->Args({0, 4})->Args({1, 4})->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// The renderer's CPU linear-blend skinning loop alone (what the CPU path adds before its upload).
void BM_R1_CpuSkinningLoop(benchmark::State& state) {
  Scene& s = scene();
  const Mesh& mesh = s.figure.mesh;
  std::vector<vec3> scratch_p(mesh.vertex_count()), scratch_n(mesh.vertex_count()), out_p(mesh.vertex_count()),
      out_n(mesh.vertex_count());
  s.animator.pose_at(1.0f);
  for (auto _ : state) {
    cpu_skin_for_render(mesh, s.animator.skinning(), s.animator.morph_weights(), scratch_p, scratch_n, out_p, out_n);
    benchmark::DoNotOptimize(out_p.data());
  }
  state.counters["vertices"] = static_cast<double>(mesh.vertex_count());
}
BENCHMARK(BM_R1_CpuSkinningLoop)->Unit(benchmark::kMicrosecond);

// A full headless frame: draw + glReadPixels into an Image.
void BM_R1_DrawAndReadback(benchmark::State& state) {
  Scene& s = scene();
  const auto path = static_cast<SkinningPath>(state.range(0));
  Image image;
  int frame = 0;
  const CpuMeter meter;
  for (auto _ : state) {
    s.draw(frame++, path);
    s.renderer.read_pixels(image);
  }
  meter.report(state);
  set_counters(state);
  state.SetLabel(path == SkinningPath::Gpu ? "gpu skinning" : "cpu skinning + upload");
}
BENCHMARK(BM_R1_DrawAndReadback)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Readback alone (the frame is already drawn).
void BM_R1_Readback(benchmark::State& state) {
  Scene& s = scene();
  s.draw(0, SkinningPath::Gpu);
  s.renderer.finish();
  Image image;
  const CpuMeter meter;
  for (auto _ : state) s.renderer.read_pixels(image);
  meter.report(state);
  set_counters(state);
}
BENCHMARK(BM_R1_Readback)->Unit(benchmark::kMillisecond)->UseRealTime();

const char* kExtensions[] = {"mp4", "webm", "gif"};

// Encoding alone: the same pre-rendered frames fed to the encoder (colour conversion included).
void BM_R1_Encode(benchmark::State& state) {
  Scene& s = scene();
  std::vector<Image> frames(30);
  for (int i = 0; i < 30; ++i) {
    s.draw(i * 2, SkinningPath::Gpu);
    s.renderer.read_pixels(frames[static_cast<std::size_t>(i)]);
  }
  const std::string path = (std::filesystem::temp_directory_path() / "gestura_bench_encode.").string() +
                           kExtensions[state.range(0)];
  {
    VideoWriter writer(path, kWidth, kHeight, 30);
    int i = 0;
    const CpuMeter meter;
    for (auto _ : state) writer.write(frames[static_cast<std::size_t>(i++ % 30)]);
    writer.finish();
    meter.report(state);
  }
  std::remove(path.c_str());
  set_counters(state);
  state.SetLabel(kExtensions[state.range(0)]);
}
BENCHMARK(BM_R1_Encode)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Export end to end: pose, draw, read back, encode — frames per second of video written.
void BM_R1_Export(benchmark::State& state) {
  Scene& s = scene();
  const std::string path = (std::filesystem::temp_directory_path() / "gestura_bench_export.").string() +
                           kExtensions[state.range(0)];
  Image image;
  {
    VideoWriter writer(path, kWidth, kHeight, 30);
    int frame = 0;
    const CpuMeter meter;
    for (auto _ : state) {
      s.draw(frame++, SkinningPath::Gpu);
      s.renderer.read_pixels(image);
      writer.write(image);
    }
    writer.finish();
    meter.report(state);
  }
  std::remove(path.c_str());
  set_counters(state);
  state.SetLabel(kExtensions[state.range(0)]);
}
BENCHMARK(BM_R1_Export)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gestura
