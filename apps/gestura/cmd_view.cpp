// gestura view: the interactive viewer (GLFW window, same renderer as `gestura render`).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "command.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/app/render.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/viewer_controls.hpp"
#include "scene_view.hpp"

namespace gestura::cli {
namespace {

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

// The window: what the controls and the renderer need, until it is closed (or the screenshot taken).
int show(const app::ViewRequest& request, const app::RunContext& context) {
  const app::LoadedSubject loaded = app::run(request, context);
  for (const app::Notice& n : loaded.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
  const RenderSubject& subject = loaded.subject;
  Animator animator(subject);
  std::optional<StagedFile> screenshot_file;
  if (!request.screenshot.empty()) screenshot_file.emplace(request.screenshot);
  Look look;
  if (request.background) look.background = request.background->rgb;
  const ImageSize size = request.size;

  WindowGlContext window(size.width, size.height, "gestura view");
  Renderer renderer(look);
  renderer.upload(subject.mesh);
  renderer.set_occluders(find_occluders(subject.skeleton, subject.mesh));
  Viewer viewer{ViewerControls(framing_box(subject.mesh, subject.skeleton, subject.clip ? &*subject.clip : nullptr), request.camera.front(),
                                static_cast<float>(size.width) / static_cast<float>(size.height))};
  if (request.at) viewer.controls.time = std::min(*request.at, animator.duration()), viewer.controls.playing = false;
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
    if (screenshot_file && drawn + 1 >= request.frames) {
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

Invocation prepare() {
  struct State {
    app::ViewRequest request;
    app::SceneViewRequest scene;  // --scene FILE: a performed scene instead of one avatar
    std::string camera;           // a scene's camera names are its own, so parsed once the subject is known
  };
  auto state = std::make_shared<State>();
  app::ViewRequest* request = &state->request;
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  // The bare argument is a motion file when it names one (or an existing file), else English to sign.
  FieldBinding& subject = binding(invocation.fields, "clip");
  subject.info.value = "CLIP|TEXT";
  subject.info.help = "a motion on the avatar's skeleton (.bvh, .glb, .gltf, .bap), or English text to sign";
  subject.set = [request](std::string_view arg) {
    const std::string text(arg);
    const bool file = std::filesystem::exists(text) || (text.find(' ') == std::string::npos && app::is_motion_file(text));
    (file ? request->subject.clip : request->extras.text) = text;
  };
  FieldBinding& camera = binding(invocation.fields, "camera");
  camera.info.help = "start camera: front, side, three-quarter, top, side-section, follow; with --scene a camera of the scene";
  camera.set = [state](std::string_view text) { state->camera = std::string(text); };
  invocation.fields.push_back(option({.name = "scene", .help = "play a scene (docs/scene.md) performed as gestura scene does; c cycles its cameras", .value = "SCENE.json", .group = "Scene"}, state->scene.source.scene));
  invocation.fields.push_back(option({.name = "script", .help = "with --scene: the script (text or JSON) instead of the scene's own", .value = "FILE", .group = "Scene"}, state->scene.source.script));
  invocation.fields.push_back(option({.name = "do", .help = "with --scene: the script as text", .value = "TEXT", .group = "Scene"}, state->scene.source.do_text));
  invocation.run = [state](const app::RunContext& context) {
    app::ViewRequest& view = state->request;
    app::SceneViewRequest& scene = state->scene;
    if (scene.source.scene.empty()) {
      if (!scene.source.script.empty() || !scene.source.do_text.empty()) app::usage_error("scene", "--script and --do need --scene SCENE.json");
      if (!state->camera.empty()) {
        view.camera.clear();
        app::set_from_text(view.camera, state->camera, app::FieldInfo{.name = "camera"});
      }
      return show(view, context);
    }
    if (!view.subject.clip.empty() || view.subject.rest || view.subject.test_motion || view.extras.sign.given() || !view.extras.text.empty())
      app::usage_error("scene", "--scene plays a scene: give no clip, sign, text, --rest or --test-motion with it");
    scene.camera = state->camera;
    scene.size = view.size;
    scene.screenshot = view.screenshot;
    scene.frames = view.frames;
    scene.at = view.at;
    return show_scene(scene, context);
  };
  return invocation;
}

const Registration reg{{"view", "interactive viewer (play, step, slow motion, orbit, camera presets)",
                        "Shows the avatar at rest (the default), doing the test wave, playing CLIP (a motion on the\n"
                        "avatar's skeleton), performing one sign written in HamNoSys (--hamnosys, --names) or SiGML\n"
                        "(--sigml FILE [--gloss NAME]), or signing English TEXT as gestura say does (a bare argument\n"
                        "that names no file). Opens a window (needs a display; without one use xvfb-run -a gestura\n"
                        "view ...). With --scene SCENE.json it plays a scene performed as gestura scene does (c\n"
                        "cycles its cameras).\n\n"
                        "keys:  space play/pause   , . step one frame back/forward   1 2 3 speed 0.25x 0.5x 1x\n"
                        "       l loop on/off   F1..F5 (or f s t p x) front, side, three-quarter, top (plan), side-section\n"
                        "       r restart   q / Esc quit\n"
                        "mouse: left drag orbit   right or middle drag pan   wheel zoom",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
