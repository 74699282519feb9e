#include "gestura/app/scene_command.hpp"

#include <cstdio>

#include "gestura/core/error.hpp"
#include "gestura/render/scene_cameras.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/world/director.hpp"
#include "gestura/world/scene_json.hpp"

namespace gestura {

LoadedScene load_scene_request(const SceneRequest& request) {
  if (request.scene.empty()) throw Error("no scene file (gestura scene SCENE.json ...)");
  LoadedScene out;
  out.scene = read_scene(request.scene);
  if (!request.script_text.empty()) out.script = parse_script(request.script_text, "--do");
  else if (!request.script_file.empty()) out.script = read_script(request.script_file);
  else if (!out.scene.script.empty()) out.script = parse_script(out.scene.script, request.scene + " (its script)");
  check_script(out.script, out.scene);
  if (!request.output.empty()) {
    SceneRenderJob job;
    job.output = request.output;
    job.size = request.size;
    job.fps = request.fps;
    job.cameras = request.cameras;
    job.sheet = request.sheet;
    job.msaa_samples = request.msaa_samples;
    validate(job, out.scene);
  } else {
    expand_scene_cameras(request.cameras, out.scene);
  }
  out.geometry = build_scene_geometry(out.scene);
  return out;
}

ScenePerformance perform_loaded_scene(const LoadedScene& loaded, int fps, const std::function<void(const std::string&)>& progress) {
  PerformOptions options;
  options.fps = static_cast<float>(fps);
  options.progress = progress;
  return perform_scene(loaded.scene, loaded.geometry, loaded.script, nullptr, options);
}

SceneResult run_scene_request(const SceneRequest& request, const std::function<void(const std::string&)>& progress) {
  const LoadedScene loaded = load_scene_request(request);
  SceneResult result;
  const Scene& s = loaded.scene;
  std::size_t actions = 0;
  for (const ScriptStatement& st : loaded.script.statements)
    for (const ScriptChain& c : st.chains) actions += c.actions.size();
  result.summary.push_back("scene " + (s.name.empty() ? request.scene : s.name) + ": " + std::to_string(s.objects.size()) +
                           " objects, " + std::to_string(loaded.geometry.triangle_count()) + " triangles, " +
                           std::to_string(s.places.size()) + " places, " + std::to_string(s.characters.size()) + " characters, " +
                           std::to_string(s.cameras.size()) + " cameras");
  result.summary.push_back("script: " + std::to_string(loaded.script.statements.size()) + " statements, " + std::to_string(actions) +
                           " actions");
  if (request.check_only) return result;
  result.performance = perform_loaded_scene(loaded, request.fps, progress);
  for (const LogEntry& e : result.performance.log) result.warnings += e.warning ? 1 : 0;
  if (!request.output.empty()) {
    SceneRenderJob job;
    job.output = request.output;
    job.size = request.size;
    job.fps = request.fps;
    job.cameras = request.cameras;
    job.sheet = request.sheet;
    job.msaa_samples = request.msaa_samples;
    job.still_time = request.still_time.value_or(result.performance.duration * 0.5f);
    result.render = render_scene_to_file(loaded.scene, loaded.geometry, result.performance, job);
    result.rendered = true;
  }
  return result;
}

}  // namespace gestura
