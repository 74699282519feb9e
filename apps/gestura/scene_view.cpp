// gestura view --scene: plays a performed scene in a window (the scene renderer of gestura scene).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "command.hpp"
#include "gestura/render/camera_glide.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/viewer_controls.hpp"
#include "scene_view.hpp"

namespace gestura::cli {
namespace {

struct SceneViewer {
  ViewerControls controls{FramingBox{}, CameraPreset::Front, 16.0f / 9.0f};
  std::vector<std::string> cameras;
  std::size_t camera = 0;
};

SceneViewer& viewer_of(GLFWwindow* window) { return *static_cast<SceneViewer*>(glfwGetWindowUserPointer(window)); }

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  SceneViewer& v = viewer_of(window);
  switch (key) {
    case GLFW_KEY_Q: case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case GLFW_KEY_SPACE: v.controls.apply(ViewerCommand::PlayPause); break;
    case GLFW_KEY_COMMA: v.controls.apply(ViewerCommand::StepBack); break;
    case GLFW_KEY_PERIOD: v.controls.apply(ViewerCommand::StepForward); break;
    case GLFW_KEY_1: v.controls.apply(ViewerCommand::Speed025); break;
    case GLFW_KEY_2: v.controls.apply(ViewerCommand::Speed05); break;
    case GLFW_KEY_3: v.controls.apply(ViewerCommand::Speed1); break;
    case GLFW_KEY_L: v.controls.apply(ViewerCommand::ToggleLoop); break;
    case GLFW_KEY_R: v.controls.apply(ViewerCommand::Restart); break;
    case GLFW_KEY_C: v.camera = (v.camera + 1) % v.cameras.size(); break;
    default: break;
  }
}

}  // namespace

int show_scene(const app::SceneViewRequest& request, const app::RunContext& context) {
  const app::PlayableScene playable = app::run(request, context);
  const app::LoadedScene& loaded = playable.loaded;
  const ScenePerformance& performance = playable.performance;
  for (const LogEntry& e : performance.log)
    if (e.warning) std::fprintf(stderr, "warning: %s\n", e.text.c_str());
  std::optional<StagedFile> shot;
  if (!request.screenshot.empty()) shot.emplace(request.screenshot);
  const ImageSize size = request.size;
  const std::optional<float> start_at = request.at;
  const int frames = request.frames;

  WindowGlContext window(size.width, size.height, "gestura view — " + request.source.scene);
  SceneRenderer renderer;
  SceneAnimator animator(loaded.scene, loaded.geometry, performance);
  animator.upload(renderer);
  SceneViewer viewer;
  viewer.cameras = playable.cameras;
  if (start_at) viewer.controls.time = std::min(*start_at, performance.duration), viewer.controls.playing = false;
  glfwSetWindowUserPointer(window.window(), &viewer);
  glfwSetKeyCallback(window.window(), on_key);
  double last = glfwGetTime();
  Image frame;
  CameraGlide glide;
  std::size_t shown_camera = ~std::size_t{0};
  float shown_time = 0.0f;
  for (int drawn = 0; !window.should_close(); ++drawn) {
    glfwPollEvents();
    const double now = glfwGetTime();
    viewer.controls.advance(static_cast<float>(now - last), performance.duration);
    last = now;
    int width = 0, height = 0;
    window.framebuffer_size(width, height);
    if (width <= 0 || height <= 0) continue;
    renderer.resize(width, height);
    animator.pose_at(viewer.controls.time);
    std::vector<View> views = scene_views({viewer.cameras[viewer.camera]}, loaded.scene, animator.bounds(), animator.views(), width, height);
    // The characters view glides between its shots; a new camera, or a jump in time, cuts.
    const bool cut = viewer.camera != shown_camera || std::abs(viewer.controls.time - shown_time) > 0.25f;
    glide.keep_inside(animator.bounds().min + vec3(0.35f), animator.bounds().max - vec3(0.35f));
    if (viewer.cameras[viewer.camera] == "characters") views[0].camera = glide.follow(views[0].camera, cut ? 0.0f : static_cast<float>(viewer.controls.time - shown_time));
    shown_camera = viewer.camera, shown_time = viewer.controls.time;
    renderer.render(views, animator.objects(), animator.frames());
    renderer.present(width, height);
    if (shot && drawn + 1 >= frames) {
      renderer.read_window_pixels(frame, width, height);
      write_png(*shot, frame);
      break;
    }
    window.swap_buffers();
    char title[200];
    std::snprintf(title, sizeof title, "gestura view — %s — %.2f / %.2f s  camera %s (c: next)%s", request.source.scene.c_str(),
                  viewer.controls.time, performance.duration, viewer.cameras[viewer.camera].c_str(), viewer.controls.playing ? "" : "  paused");
    glfwSetWindowTitle(window.window(), title);
  }
  return 0;
}

}  // namespace gestura::cli
