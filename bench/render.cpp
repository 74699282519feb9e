// R1: headless rendering speed of the default avatar (build_avatar(): ~38k triangles, 36 morphs)
// doing the test wave at 1280×720 on llvmpipe — GPU vs CPU skinning, MSAA samples, where a frame's
// time goes (draw, readback, encode) and export speed, serial and with the encoder thread. The fps
// counter is frames per second; `x_realtime_30fps` is that divided by 30 (export: multiple of real
// time for a 30 fps video).
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "gestura/body/avatar.hpp"
#include "gestura/render/edge_filter.hpp"
#include "gestura/render/encoder_thread.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/render/test_motion.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

RenderSubject avatar_subject() {
  Avatar avatar = build_avatar();
  RenderSubject subject{std::move(avatar.skeleton), std::move(avatar.mesh), std::nullopt};
  subject.clip = make_wave_clip(subject.skeleton);
  return subject;
}

struct Scene {
  HeadlessGlContext context;
  RenderSubject figure = avatar_subject();
  Animator animator{figure};
  Renderer renderer{Look{}, Antialiasing::Msaa4};  // RenderJob's default
  Renderer two_samples{Look{}, Antialiasing::Msaa2};
  Renderer edge_filter{Look{}, Antialiasing::EdgeFilter};
  Renderer single_sample{Look{}, Antialiasing::None};
  Renderer no_occluders{Look{}, Antialiasing::Msaa4};  // the depth cues' capsules left out: what they cost
  std::vector<View> views;
  Scene() {
    views.push_back({preset_camera(CameraPreset::Front, framing_box(figure.mesh, figure.skeleton),
                                   float(kWidth) / kHeight), {0, 0, kWidth, kHeight}});
    for (Renderer* r : {&renderer, &two_samples, &edge_filter, &single_sample, &no_occluders}) {
      r->upload(figure.mesh);
      if (r != &no_occluders) r->set_occluders(find_occluders(figure.skeleton, figure.mesh));
      r->resize(kWidth, kHeight);
      for (SkinningDevice device : {SkinningDevice::Gpu, SkinningDevice::Cpu}) {  // compile shaders, fill caches
        r->render(views, animator.skinning(), animator.morph_weights(), device);
        r->finish();
      }
    }
  }
  // By bench argument: 0 4× MSAA, 1 2× MSAA, 2 edge filter, 3 one sample, 4 4× MSAA without occluders.
  Renderer& by_arg(std::int64_t arg) {
    Renderer* all[] = {&renderer, &two_samples, &edge_filter, &single_sample, &no_occluders};
    return *all[std::clamp<std::int64_t>(arg, 0, 4)];
  }
  static const char* name(std::int64_t arg) {
    const char* names[] = {"4x MSAA", "2x MSAA (4 on llvmpipe)", "1 sample + edge filter", "1 sample",
                           "4x MSAA, no occluders"};
    return names[std::clamp<std::int64_t>(arg, 0, 4)];
  }
  void draw(int frame, SkinningDevice device, Renderer* with = nullptr) {
    animator.pose_at(static_cast<float>(frame % 60) / 30.0f);
    (with ? *with : renderer).render(views, animator.skinning(), animator.morph_weights(), device);
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

// Draw only (pose, skin, draw, MSAA resolve or edge filter), waiting for the GL to finish. Args:
// skinning device (0 GPU, 1 CPU), antialiasing (Scene::by_arg: 0 4× MSAA, 1 2× MSAA, 2 one sample +
// edge filter, 3 one sample, 4 = 4× MSAA without the occluder capsules' shadows and ambient
// occlusion, for their cost).
void BM_R1_Draw(benchmark::State& state) {
  Scene& s = scene();
  const auto device = static_cast<SkinningDevice>(state.range(0));
  Renderer& renderer = s.by_arg(state.range(1));
  int frame = 0;
  const CpuMeter meter;
  for (auto _ : state) {
    s.animator.pose_at(static_cast<float>(frame++ % 60) / 30.0f);
    renderer.render(s.views, s.animator.skinning(), s.animator.morph_weights(), device);
    renderer.finish();
  }
  meter.report(state);
  set_counters(state);
  state.SetLabel(std::string(device == SkinningDevice::Gpu ? "gpu skinning" : "cpu skinning + upload") + ", " +
                 Scene::name(state.range(1)) + "; " + s.context.description());
}
// Draw at a quarter of the pixels (640×360, 4× MSAA): how much of a frame scales with pixels and
// how much with vertices and triangles.
void BM_R1_DrawQuarterPixels(benchmark::State& state) {
  Scene& s = scene();
  static Renderer small{Look{}, Antialiasing::Msaa4};
  static const bool ready = [&] {
    small.upload(s.figure.mesh);
    small.set_occluders(find_occluders(s.figure.skeleton, s.figure.mesh));
    small.resize(kWidth / 2, kHeight / 2);
    return true;
  }();
  benchmark::DoNotOptimize(ready);
  const std::vector<View> views{{preset_camera(CameraPreset::Front, framing_box(s.figure.mesh, s.figure.skeleton),
                                               float(kWidth) / kHeight), {0, 0, kWidth / 2, kHeight / 2}}};
  int frame = 0;
  const CpuMeter meter;
  for (auto _ : state) {
    s.animator.pose_at(static_cast<float>(frame++ % 60) / 30.0f);
    small.render(views, s.animator.skinning(), s.animator.morph_weights());
    small.finish();
  }
  meter.report(state);
  set_counters(state);
}
BENCHMARK(BM_R1_DrawQuarterPixels)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK(BM_R1_Draw)->Args({0, 0})->Args({0, 2})->Args({0, 3})->Args({0, 4})->Args({0, 1})->Args({1, 0})->Args({1, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

// A full headless frame: draw + glReadPixels into an Image (+ the edge filter). Args: skinning
// device (0 GPU, 1 CPU), antialiasing (Scene::by_arg).
void BM_R1_DrawAndReadback(benchmark::State& state) {
  Scene& s = scene();
  const auto device = static_cast<SkinningDevice>(state.range(0));
  Renderer& renderer = s.by_arg(state.range(1));
  Image image;
  int frame = 0;
  const CpuMeter meter;
  for (auto _ : state) {
    s.draw(frame++, device, &renderer);
    renderer.read_pixels(image);
  }
  meter.report(state);
  set_counters(state);
  state.SetLabel(std::string(device == SkinningDevice::Gpu ? "gpu skinning, " : "cpu skinning + upload, ") +
                 Scene::name(state.range(1)));
}
BENCHMARK(BM_R1_DrawAndReadback)->Args({0, 0})->Args({0, 2})->Args({1, 0})->Unit(benchmark::kMillisecond)->UseRealTime();

// The edge filter alone (render/edge_filter.hpp) over a drawn one-sample frame, the figure's rectangle.
void BM_R1_EdgeFilter(benchmark::State& state) {
  Scene& s = scene();
  s.draw(10, SkinningDevice::Gpu, &s.single_sample);
  Image drawn;
  s.single_sample.read_pixels(drawn);
  Image image = drawn;
  EdgeFilterScratch scratch;
  const CpuMeter meter;
  for (auto _ : state) {
    std::copy(drawn.rgba.begin(), drawn.rgba.end(), image.rgba.begin());
    smooth_edges(image, {0, 0, kWidth, kHeight}, scratch);
  }
  meter.report(state);
  set_counters(state);
  state.SetLabel("whole 1280x720 image (copy included)");
}
BENCHMARK(BM_R1_EdgeFilter)->Unit(benchmark::kMillisecond)->UseRealTime();

// Readback alone (the frame is already drawn).
void BM_R1_Readback(benchmark::State& state) {
  Scene& s = scene();
  s.draw(0, SkinningDevice::Gpu);
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
    s.draw(i * 2, SkinningDevice::Gpu);
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

// Export end to end (as `gestura render`): pose, draw, read back, encode — frames per second of
// video written. Args: format (0 mp4, 1 webm, 2 gif), encoder on its own thread (1, as
// render_to_file does) or inline (0), antialiasing (Scene::by_arg: 0 4× MSAA, 2 edge filter).
void BM_R1_Export(benchmark::State& state) {
  Scene& s = scene();
  const std::string path = (std::filesystem::temp_directory_path() / "gestura_bench_export.").string() +
                           kExtensions[state.range(0)];
  const bool threaded = state.range(1) == 1;
  Renderer& renderer = s.by_arg(state.range(2));
  Image image;
  {
    VideoWriter writer(path, kWidth, kHeight, 30);
    std::optional<EncoderThread> encoder;
    if (threaded) encoder.emplace(writer);
    int frame = 0;
    const CpuMeter meter;
    for (auto _ : state) {
      s.draw(frame++, SkinningDevice::Gpu, &renderer);
      renderer.read_pixels(image);
      if (encoder) encoder->submit(image);
      else writer.write(image);
    }
    if (encoder) encoder->finish();
    else writer.finish();
    meter.report(state);
  }
  std::remove(path.c_str());
  set_counters(state);
  state.SetLabel(std::string(kExtensions[state.range(0)]) + (threaded ? ", encoder thread, " : ", inline encode, ") +
                 Scene::name(state.range(2)));
}
BENCHMARK(BM_R1_Export)
    ->Args({0, 0, 0})
    ->Args({0, 1, 0})
    ->Args({0, 1, 2})
    ->Args({1, 1, 0})
    ->Args({1, 1, 2})
    ->Args({2, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace gestura
