// gestura view --scene: plays a performed scene in a window (the scene renderer of gestura scene).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <charconv>
#include <cstdio>
#include <sstream>

#include "command.hpp"
#include "gestura/app/scene_command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/render/staged_file.hpp"
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

int run_scene_view(const std::vector<std::string>& args) {
  SceneRequest request;
  request.cameras = {};
  ImageSize size{1280, 720};
  std::string screenshot;
  int frames = 30;
  std::optional<float> start_at;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--scene") request.scene = flag_value(args, i);
    else if (a == "--script") request.script_file = flag_value(args, i);
    else if (a == "--do") request.script_text = flag_value(args, i);
    else if (a == "--camera") {
      std::stringstream in(flag_value(args, i));
      for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) request.cameras.push_back(item);
    } else if (a == "--size") size = parse_image_size(flag_value(args, i));
    else if (a == "--screenshot") screenshot = flag_value(args, i);
    else if (a == "--frames") {
      const std::string n = flag_value(args, i);
      const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), frames);
      if (ec != std::errc() || end != n.data() + n.size() || frames < 1 || frames > 100000)
        throw Error("bad --frames '" + n + "' (a whole number 1..100000)");
    } else if (a == "--at") start_at = parse_seconds(flag_value(args, i), a);
    else throw Error("unknown flag " + a + " for a scene (see gestura view --help)");
  }
  // Every camera the scene has, then the built-in views; the first given (or the first there is) shows first.
  LoadedScene loaded = load_scene_request(request);
  std::vector<std::string> cameras = request.cameras;
  for (const SceneCamera& c : loaded.scene.cameras) cameras.push_back(c.name);
  for (const char* b : {"perspective", "plan", "section", "characters"}) cameras.push_back(b);
  const ScenePerformance performance = perform_loaded_scene(loaded, 30, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  for (const LogEntry& e : performance.log)
    if (e.warning) std::fprintf(stderr, "warning: %s\n", e.text.c_str());
  std::optional<StagedFile> shot;
  if (!screenshot.empty()) shot.emplace(screenshot);

  WindowGlContext window(size.width, size.height, "gestura view — " + request.scene);
  SceneRenderer renderer;
  SceneAnimator animator(loaded.scene, loaded.geometry, performance);
  animator.upload(renderer);
  SceneViewer viewer;
  viewer.cameras = cameras;
  if (start_at) viewer.controls.time = std::min(*start_at, performance.duration), viewer.controls.playing = false;
  glfwSetWindowUserPointer(window.window(), &viewer);
  glfwSetKeyCallback(window.window(), on_key);
  double last = glfwGetTime();
  Image frame;
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
    const std::vector<View> views =
        scene_views({viewer.cameras[viewer.camera]}, loaded.scene, animator.bounds(), animator.views(), width, height);
    renderer.render(views, animator.objects(), animator.frames());
    renderer.present(width, height);
    if (shot && drawn + 1 >= frames) {
      renderer.read_window_pixels(frame, width, height);
      write_png(*shot, frame);
      break;
    }
    window.swap_buffers();
    char title[200];
    std::snprintf(title, sizeof title, "gestura view — %s — %.2f / %.2f s  camera %s (c: next)%s", request.scene.c_str(),
                  viewer.controls.time, performance.duration, viewer.cameras[viewer.camera].c_str(), viewer.controls.playing ? "" : "  paused");
    glfwSetWindowTitle(window.window(), title);
  }
  return 0;
}

}  // namespace gestura::cli
