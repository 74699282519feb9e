#pragma once
// scene: perform a scene (docs/scene.md) — its characters walk planned paths, sign what they say,
// open doors, look at whoever signs, follow and avoid each other, as its script tells them (the
// scene's own, a file, or text) — and render it headless to a PNG, contact sheet, GIF, MP4 or WebM.
// SceneViewRequest is the same performance for a window (the window is the adapter's:
// apps/gestura/scene_view.cpp, later the studio).
#include <optional>
#include <string>
#include <vector>

#include "gestura/app/codecs.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/world/performance.hpp"
#include "gestura/world/scene.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/script.hpp"

namespace gestura::app {

// Which scene and which script: shared by the file and the window.
struct SceneSource {
  std::string scene;   // the scene's JSON file
  std::string script;  // a script file (text or JSON); "" = `do` or the scene's own
  std::string do_text; // a script given as text

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.scene, FieldInfo{.name = "scene", .help = "the scene (JSON, docs/scene.md)", .value = "SCENE.json", .positional = true, .required = true});
    visit(self.script, FieldInfo{.name = "script", .help = "the script (text or JSON) instead of the scene's own", .value = "FILE"});
    visit(self.do_text, FieldInfo{.name = "do", .help = "the script as text, e.g. \"anna walks to chair; anna says \\\"Hello\\\"\"", .value = "TEXT"});
  }
};

inline constexpr const char* kSceneCameraHelp =
    "the scene's cameras or plan, section, perspective, perspective2, characters, alias (the four ALIAS views), or a "
    "character's name; a comma list renders a split view";

struct SceneRequest {
  SceneSource source;
  std::string output;  // .png, .gif, .mp4 or .webm; "" = perform and report without rendering
  ImageSize size{1280, 720};
  int fps = 30;
  std::string camera = "perspective";  // comma list of names (scene cameras are the scene's own words)
  std::optional<float> time;           // the moment a single PNG shows (default: the middle)
  bool sheet = false;                  // .png: a 4×4 contact sheet over the performance
  int msaa = 4;
  bool check = false;                  // read and check scene and script; perform nothing

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    SceneSource::fields(self.source, visit);
    visit(self.output, FieldInfo{.name = "output", .help = "the picture or video to write: .png, .gif, .mp4 or .webm", .value = "OUT", .short_flag = 'o', .group = "Output"});
    visit(self.size, FieldInfo{.name = "size", .help = "image size, 16..4096 per side, at most 4096x2304 pixels", .value = "WxH", .group = "Output"});
    visit(self.fps, FieldInfo{.name = "fps", .help = "frames per second (also the key rate of the characters' motion)", .value = "N", .min = 1, .max = kMaxFps, .group = "Output"});
    visit(self.camera, FieldInfo{.name = "camera", .help = kSceneCameraHelp, .value = "LIST", .group = "Output"});
    visit(self.time, FieldInfo{.name = "time", .help = "the moment a single PNG shows (s)", .value = "S", .min = 0, .max = 3600, .group = "Output", .unset = "the middle"});
    visit(self.sheet, FieldInfo{.name = "sheet", .help = ".png: a 4x4 contact sheet of 16 frames over the performance", .group = "Output"});
    visit(self.msaa, FieldInfo{.name = "msaa", .help = "samples per pixel for edge smoothing: 1, 2 or 4", .value = "N", .min = 1, .max = 4, .group = "Output"});
    visit(self.check, FieldInfo{.name = "check", .help = "read and check the scene and script, print a summary, perform nothing"});
  }
};

struct SceneResult {
  std::vector<std::string> summary;  // what the scene and script hold, one line each
  ScenePerformance performance;      // empty with check
  int warnings = 0;                  // actions that could not be done (no path, …), in the log
  std::string written;               // the file, when one was rendered
  RenderReport render;
};

// A scene read with its geometry and its script, checked against each other.
struct LoadedScene {
  Scene scene;
  SceneGeometry geometry;
  Script script;
};

// Field limits and combinations (script and do together, a non-picture output, --sheet or
// --time without a .png, msaa 3); throws AppError (usage) at the field.
void validate(const SceneRequest& request);
// Reads, checks and performs (unless check), then renders when an output is named. The scene and
// script are input errors at their file:line:col; an unknown camera is a usage error at camera.
// Progress lines ("anna walks to chair") go to context.progress; context.stop cancels.
SceneResult run(const SceneRequest& request, const RunContext& context = {});
nlohmann::json to_json(const SceneResult& result);

struct SceneViewRequest {
  SceneSource source;
  std::string camera;  // the first camera shown; the viewer cycles through the scene's and the built-in ones
  ImageSize size{1280, 720};
  std::string screenshot;  // save the window after `frames` frames and quit
  int frames = 30;
  std::optional<float> at;  // start paused at this time

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    SceneSource::fields(self.source, visit);
    visit(self.camera, FieldInfo{.name = "camera", .help = kSceneCameraHelp, .value = "NAME", .group = "Output"});
    visit(self.size, FieldInfo{.name = "size", .help = "window size", .value = "WxH", .group = "Output"});
    visit(self.screenshot, FieldInfo{.name = "screenshot", .help = "save the window after --frames frames and quit", .value = "PATH.png", .group = "Output"});
    visit(self.frames, FieldInfo{.name = "frames", .help = "frames before the screenshot", .value = "N", .min = 1, .max = 100000, .group = "Output"});
    visit(self.at, FieldInfo{.name = "at", .help = "start paused at this time (s)", .value = "SECONDS", .min = 0, .max = 3600, .group = "Output"});
  }
};

// What the window shows: the scene, its performance, and the cameras to cycle through (the one
// asked for first, then the scene's own, then the built-in views).
struct PlayableScene {
  LoadedScene loaded;
  ScenePerformance performance;
  std::vector<std::string> cameras;
};

void validate(const SceneViewRequest& request);
PlayableScene run(const SceneViewRequest& request, const RunContext& context = {});

}  // namespace gestura::app
