#pragma once
// The scene command as a plain request and result, for every adapter (the CLI's `gestura scene`
// and `gestura view --scene`, later the studio and the server): read a scene, its script (the
// scene's own, a file, or text), perform it, and render it to a file when an output is asked for.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gestura/render/render_job.hpp"
#include "gestura/world/performance.hpp"
#include "gestura/world/scene.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/script.hpp"

namespace gestura {

struct SceneRequest {
  std::string scene;                  // the scene's JSON file
  std::string script_file;            // a script file (text or JSON); "" = script_text or the scene's own
  std::string script_text;            // a script given as text
  std::string output;                 // .png, .gif, .mp4 or .webm; "" = perform without rendering
  ImageSize size{1280, 720};
  int fps = 30;
  std::vector<std::string> cameras{"perspective"};
  bool sheet = false;                 // PNG: a 4×4 contact sheet over the performance
  std::optional<float> still_time;    // PNG: the moment shown (default: the middle)
  int msaa_samples = 4;
  bool check_only = false;            // read and check scene and script; perform nothing
};

struct SceneResult {
  std::vector<std::string> summary;   // what the scene holds, one line each
  ScenePerformance performance;       // empty when check_only
  int warnings = 0;                   // actions that could not be done (no path, …)
  bool rendered = false;
  RenderReport render;
};

// A scene read with its geometry and its script, checked against each other.
struct LoadedScene {
  Scene scene;
  SceneGeometry geometry;
  Script script;
};

// Throws gestura::Error (located in the scene or script file) for anything malformed, unknown
// names, unreadable meshes, or bad render options — before performing or rendering anything.
LoadedScene load_scene_request(const SceneRequest& request);

// `progress` hears what happens as it happens (optional).
SceneResult run_scene_request(const SceneRequest& request, const std::function<void(const std::string&)>& progress = {});

// Performs an already loaded scene (what the viewer shows).
ScenePerformance perform_loaded_scene(const LoadedScene& loaded, int fps, const std::function<void(const std::string&)>& progress = {});

}  // namespace gestura
