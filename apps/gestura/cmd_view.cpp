// gestura view: the interactive viewer (GLFW window, same renderer as `gestura render`).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/render/viewer_controls.hpp"
#include "render_subject.hpp"

namespace gestura::cli {
namespace {

constexpr const char* kUsage = R"(usage: gestura view [CLIP.bvh | --rest | --test-motion | SIGN | "TEXT"] [options]
       SIGN: --hamnosys TEXT | --names SYMBOLS | --sigml FILE [--gloss NAME]
       TEXT: English to translate and sign, as gestura say does (anything not naming a file)

Shows the default avatar at rest (the default), doing the test wave, playing CLIP.bvh (a motion
on the avatar's skeleton), or performing a sign written in HamNoSys (Unicode or comma-separated
symbol names, as in gestura sign) or the first (or --gloss NAME) sign of a SiGML file. Opens a window (needs a display; under no display use
xvfb-run -a gestura view ...).

  --camera PRESET        start camera: front, side, three-quarter, top, side-section  [front]
  --size WxH             window size                                        [1280x720]
  --background #rrggbb   background colour
  --screenshot PATH.png  save the window after --frames frames and quit (for scripts, Xvfb)
  --frames N             frames before the screenshot                       [30]
  --at SECONDS           start paused at this time of the motion (for screenshots)
  --avatar SPEC                    default (generated), a built-in look (gestura avatar looks)
                                   or makehuman:DIR (MakeHuman assets)
  --height M, --build X, --sex S   the avatar, as in gestura avatar export

keys:  space play/pause   , . step one frame back/forward   1 2 3 speed 0.25x 0.5x 1x
       l loop on/off   F1..F5 (or f s t p x) front, side, three-quarter, top (plan), side-section
       r restart   q / Esc quit
mouse: left drag orbit   right or middle drag pan   wheel zoom)";

// What the window callbacks reach: the controls and the mouse state.
struct Viewer {
  ViewerControls controls;
  bool dragging_orbit = false, dragging_pan = false;
  double last_x = 0.0, last_y = 0.0;
};

Viewer& viewer_of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

std::optional<ViewerCommand> command_for(int key) {
  switch (key) {
    case GLFW_KEY_SPACE: return ViewerCommand::PlayPause;
    case GLFW_KEY_COMMA: return ViewerCommand::StepBack;
    case GLFW_KEY_PERIOD: return ViewerCommand::StepForward;
    case GLFW_KEY_1: return ViewerCommand::Speed025;
    case GLFW_KEY_2: return ViewerCommand::Speed05;
    case GLFW_KEY_3: return ViewerCommand::Speed1;
    case GLFW_KEY_L: return ViewerCommand::ToggleLoop;
    case GLFW_KEY_R: return ViewerCommand::Restart;
    case GLFW_KEY_F1: case GLFW_KEY_F: return ViewerCommand::Front;
    case GLFW_KEY_F2: case GLFW_KEY_S: return ViewerCommand::Side;
    case GLFW_KEY_F3: case GLFW_KEY_T: return ViewerCommand::ThreeQuarter;
    case GLFW_KEY_F4: case GLFW_KEY_P: return ViewerCommand::Top;
    case GLFW_KEY_F5: case GLFW_KEY_X: return ViewerCommand::SideSection;
    default: return std::nullopt;
  }
}

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  if (key == GLFW_KEY_Q || key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  else if (const auto command = command_for(key)) viewer_of(window).controls.apply(*command);
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
  if (v.dragging_orbit) v.controls.orbit_drag(dx, dy);
  else if (v.dragging_pan) v.controls.pan_drag(dx, dy);
}

void on_scroll(GLFWwindow* window, double, double dy) { viewer_of(window).controls.zoom(static_cast<float>(dy)); }

bool names_motion_file(const std::string& arg) {
  std::string ext = std::filesystem::path(arg).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return arg.find(' ') == std::string::npos && (ext == ".bvh" || ext == ".glb" || ext == ".gltf" || ext == ".bap");
}

int run(const std::vector<std::string>& args) {
  Motion motion = Motion::Rest;
  AvatarParams avatar;
  SignSource sign;
  bool motion_given = false;
  std::string avatar_spec = "default";
  std::string clip_path, screenshot;
  ImageSize size{1280, 720};
  CameraPreset start = CameraPreset::Front;
  Look look;
  int screenshot_frames = 30;
  std::optional<float> start_at;
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
    } else if (a == "--at") start_at = parse_seconds(flag_value(args, i), a);
    else if (a == "--rest") motion = Motion::Rest, motion_given = true;
    else if (a == "--test-motion") motion = Motion::TestMotion, motion_given = true;
    else if (parse_avatar_flag(args, i, avatar, avatar_spec)) continue;
    else if (parse_sign_source_flag(args, i, sign)) continue;
    else if (!a.empty() && a[0] == '-') throw Error("unknown flag " + a + " (see gestura view --help)");
    // FILE or TEXT: an existing file or a motion file name is a clip; anything else is English to sign.
    else if (std::filesystem::exists(a) || names_motion_file(a)) clip_path = a, motion = Motion::ClipFile, motion_given = true;
    else sign.text = a;
  }
  if (sign.given() || !sign.gloss.empty()) {
    if (motion_given) throw Error("show either a sign (--hamnosys, --names, --sigml) or CLIP.bvh / --rest / --test-motion");
    motion = Motion::Sign;
  }
  const RenderSubject subject = load_render_subject(motion, clip_path, avatar, sign, avatar_spec);
  Animator animator(subject);
  std::optional<StagedFile> screenshot_file;
  if (!screenshot.empty()) screenshot_file.emplace(screenshot);

  WindowGlContext window(size.width, size.height, "gestura view");
  Renderer renderer(look);
  renderer.upload(subject.mesh);
  Viewer viewer{ViewerControls(framing_box(subject.mesh, subject.skeleton), start,
                                static_cast<float>(size.width) / static_cast<float>(size.height))};
  if (start_at) viewer.controls.time = std::min(*start_at, animator.duration()), viewer.controls.playing = false;
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
    ViewerControls& c = viewer.controls;
    c.advance(static_cast<float>(now - last), animator.duration());
    last = now;
    animator.pose_at(c.time);

    int width = 0, height = 0;
    window.framebuffer_size(width, height);
    if (width <= 0 || height <= 0) continue;  // minimised
    renderer.resize(width, height);
    c.aspect = static_cast<float>(width) / static_cast<float>(height);
    const View view{c.camera(c.aspect), {0, 0, width, height}};
    renderer.render(std::span(&view, 1), animator.skinning(), animator.morph_weights());
    renderer.present(width, height);
    if (screenshot_file && drawn + 1 >= screenshot_frames) {
      renderer.read_window_pixels(frame, width, height);
      write_png(*screenshot_file, frame);
      break;
    }
    window.swap_buffers();
    char title[160];
    std::snprintf(title, sizeof title, "gestura view — %.2f / %.2f s  %.2gx%s%s", c.time, animator.duration(), c.speed,
                  c.playing ? "" : "  paused", c.loop ? "  loop" : "");
    glfwSetWindowTitle(window.window(), title);
  }
  return 0;
}

const Registration reg{{"view", "interactive viewer (play, step, slow motion, orbit, camera presets)", kUsage, run}};

}  // namespace
}  // namespace gestura::cli
