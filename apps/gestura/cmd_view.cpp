// gestura view: the interactive viewer (GLFW window, same renderer as `gestura render`).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/renderer.hpp"
#include "render_subject.hpp"

namespace gestura::cli {
namespace {

constexpr const char* kUsage = R"(usage: gestura view [CLIP.bvh | --rest | --test-motion] [options]

Opens a window (needs a display; under no display use xvfb-run -a gestura view ...).

  --camera PRESET        start camera: front, side, three-quarter, top, side-section  [front]
  --size WxH             window size                                        [1280x720]
  --background #rrggbb   background colour
  --screenshot PATH.png  save the window after --frames frames and quit (for scripts, Xvfb)
  --frames N             frames before the screenshot                       [30]

keys:  space play/pause   , . step one frame back/forward   1 2 3 speed 0.25x 0.5x 1x
       l loop on/off   F1..F5 (or f s t p x) front, side, three-quarter, top (plan), side-section
       r restart   q / Esc quit
mouse: left drag orbit   right or middle drag pan   wheel zoom)";

struct Viewer {
  const RenderSubject* subject = nullptr;
  FramingBox box;
  Orbit orbit;
  std::optional<CameraPreset> fixed;  // an orthographic preset shown as is until the mouse moves it
  float time = 0.0f, speed = 1.0f, step = 1.0f / 30.0f;
  bool playing = true, loop = true;
  bool dragging_orbit = false, dragging_pan = false;
  double last_x = 0.0, last_y = 0.0;
  float aspect = 16.0f / 9.0f;

  void select(CameraPreset preset) {
    orbit = preset_orbit(preset, box, aspect);
    fixed.reset();
    if (preset == CameraPreset::Top || preset == CameraPreset::SideSection) fixed = preset;
  }
  Camera camera(float view_aspect) const {
    return fixed ? preset_camera(*fixed, box, view_aspect) : orbit_camera(orbit, view_aspect);
  }
};

Viewer& viewer_of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  Viewer& v = viewer_of(window);
  switch (key) {
    case GLFW_KEY_SPACE: v.playing = !v.playing; break;
    case GLFW_KEY_COMMA: v.playing = false, v.time = std::max(0.0f, v.time - v.step); break;
    case GLFW_KEY_PERIOD: v.playing = false, v.time += v.step; break;
    case GLFW_KEY_1: v.speed = 0.25f; break;
    case GLFW_KEY_2: v.speed = 0.5f; break;
    case GLFW_KEY_3: v.speed = 1.0f; break;
    case GLFW_KEY_L: v.loop = !v.loop; break;
    case GLFW_KEY_R: v.time = 0.0f, v.playing = true; break;
    case GLFW_KEY_F1: case GLFW_KEY_F: v.select(CameraPreset::Front); break;
    case GLFW_KEY_F2: case GLFW_KEY_S: v.select(CameraPreset::Side); break;
    case GLFW_KEY_F3: case GLFW_KEY_T: v.select(CameraPreset::ThreeQuarter); break;
    case GLFW_KEY_F4: case GLFW_KEY_P: v.select(CameraPreset::Top); break;
    case GLFW_KEY_F5: case GLFW_KEY_X: v.select(CameraPreset::SideSection); break;
    case GLFW_KEY_Q: case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    default: break;
  }
}

void on_button(GLFWwindow* window, int button, int action, int) {
  Viewer& v = viewer_of(window);
  const bool down = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) v.dragging_orbit = down;
  else v.dragging_pan = down;
  glfwGetCursorPos(window, &v.last_x, &v.last_y);
}

void on_move(GLFWwindow* window, double x, double y) {
  Viewer& v = viewer_of(window);
  const float dx = static_cast<float>(x - v.last_x), dy = static_cast<float>(y - v.last_y);
  v.last_x = x, v.last_y = y;
  if (!v.dragging_orbit && !v.dragging_pan) return;
  v.fixed.reset();
  if (v.dragging_orbit) {
    v.orbit.yaw -= dx * 0.008f;
    v.orbit.pitch = std::clamp(v.orbit.pitch + dy * 0.008f, deg(-89.0f), deg(89.0f));
  } else {
    const Camera c = orbit_camera(v.orbit, v.aspect);
    const vec3 right{c.view[0][0], c.view[1][0], c.view[2][0]}, up{c.view[0][1], c.view[1][1], c.view[2][1]};
    const float scale = v.orbit.distance * 0.0015f;
    v.orbit.target += (-dx * right + dy * up) * scale;
  }
}

void on_scroll(GLFWwindow* window, double, double dy) {
  Viewer& v = viewer_of(window);
  v.fixed.reset();
  v.orbit.distance = std::clamp(v.orbit.distance * std::pow(0.9f, static_cast<float>(dy)), 0.1f, 100.0f);
}

int run(const std::vector<std::string>& args) {
  Motion motion = Motion::TestMotion;
  std::string clip_path, screenshot;
  ImageSize size{1280, 720};
  CameraPreset start = CameraPreset::Front;
  Look look;
  int screenshot_frames = 30;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--camera") start = parse_camera_preset(flag_value(args, i));
    else if (a == "--size") size = parse_image_size(flag_value(args, i));
    else if (a == "--background") look.background = parse_hex_color(flag_value(args, i));
    else if (a == "--screenshot") screenshot = flag_value(args, i);
    else if (a == "--frames") {
      const std::string n = flag_value(args, i);
      const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), screenshot_frames);
      if (ec != std::errc() || end != n.data() + n.size() || screenshot_frames < 1 || screenshot_frames > 100000)
        throw Error("bad --frames '" + n + "' (a whole number 1..100000)");
    } else if (a == "--rest") motion = Motion::Rest;
    else if (a == "--test-motion") motion = Motion::TestMotion;
    else if (!a.empty() && a[0] == '-') throw Error("unknown flag " + a + " (see gestura view --help)");
    else clip_path = a, motion = Motion::ClipFile;
  }
  const RenderSubject subject = load_render_subject(motion, clip_path);
  Animator animator(subject);
  std::optional<StagedFile> screenshot_file;
  if (!screenshot.empty()) screenshot_file.emplace(screenshot);

  WindowGlContext window(size.width, size.height, "gestura view");
  Renderer renderer(look);
  renderer.upload(subject.mesh);
  Viewer viewer;
  viewer.subject = &subject;
  viewer.box = framing_box(subject.mesh, subject.skeleton);
  viewer.aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  viewer.select(start);
  glfwSetWindowUserPointer(window.window(), &viewer);
  glfwSetKeyCallback(window.window(), on_key);
  glfwSetMouseButtonCallback(window.window(), on_button);
  glfwSetCursorPosCallback(window.window(), on_move);
  glfwSetScrollCallback(window.window(), on_scroll);

  double last = glfwGetTime();
  Image frame;
  for (int drawn = 0; !window.should_close(); ++drawn) {
    glfwPollEvents();
    const double now = glfwGetTime();
    if (viewer.playing) viewer.time += static_cast<float>(now - last) * viewer.speed;
    last = now;
    const float duration = animator.duration();
    if (duration > 0.0f && viewer.time > duration) viewer.time = viewer.loop ? std::fmod(viewer.time, duration) : duration;
    animator.pose_at(viewer.time);

    int width = 0, height = 0;
    window.framebuffer_size(width, height);
    if (width <= 0 || height <= 0) continue;  // minimised
    renderer.resize(width, height);
    viewer.aspect = static_cast<float>(width) / static_cast<float>(height);
    const View view{viewer.camera(viewer.aspect), {0, 0, width, height}};
    renderer.render(std::span(&view, 1), animator.skinning(), animator.morph_weights());
    renderer.present(width, height);
    if (screenshot_file && drawn + 1 >= screenshot_frames) {
      renderer.read_window_pixels(frame, width, height);
      write_png(*screenshot_file, frame);
      break;
    }
    window.swap_buffers();
    char title[160];
    std::snprintf(title, sizeof title, "gestura view — %.2f / %.2f s  %.2gx%s%s", viewer.time, duration, viewer.speed,
                  viewer.playing ? "" : "  paused", viewer.loop ? "  loop" : "");
    glfwSetWindowTitle(window.window(), title);
  }
  return 0;
}

const Registration reg{{"view", "interactive viewer (play, step, slow motion, orbit, camera presets)", kUsage, run}};

}  // namespace
}  // namespace gestura::cli
