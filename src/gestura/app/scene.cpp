#include "gestura/app/scene.hpp"

#include <filesystem>
#include <sstream>

#include "gestura/app/input_file.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/render/scene_cameras.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/world/director.hpp"
#include "gestura/world/scene_json.hpp"

namespace gestura::app {
namespace {

std::vector<std::string> camera_names(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

void validate(const SceneSource& source) {
  if (!source.script.empty() && !source.do_text.empty()) usage_error("do", "give --script FILE or --do TEXT, not both");
  require_file("scene", source.scene);
  if (!source.script.empty()) require_file("script", source.script);
}

SceneRenderJob render_job(const SceneRequest& request, float still_time) {
  SceneRenderJob job;
  job.output = request.output;
  job.size = request.size;
  job.fps = request.fps;
  job.cameras = camera_names(request.camera);
  job.sheet = request.sheet;
  job.still_time = still_time;
  job.msaa_samples = request.msaa;
  return job;
}

// The scene and its script, read and checked against each other; malformed files are input errors
// at their file:line:col (gestura::Error carries the place).
LoadedScene load(const SceneSource& source) {
  LoadedScene out;
  out.scene = read_scene(source.scene);
  if (!source.do_text.empty()) out.script = parse_script(source.do_text, "--do");
  else if (!source.script.empty())  // text only: a binary or non-UTF-8 file is refused naming the byte
    out.script = parse_script(read_text_input("script", source.script, kMaxScriptBytes), source.script);
  else if (!out.scene.script.empty()) out.script = parse_script(out.scene.script, source.scene + " (its script)");
  check_script(out.script, out.scene);
  return out;
}

ScenePerformance perform(const LoadedScene& loaded, int fps, const RunContext& context) {
  RunWorkspace workspace(context);
  PerformOptions options;
  options.fps = static_cast<float>(fps);
  int step = 0;
  options.progress = [&](const std::string& line) {
    context.check_stop();
    context.report(line, ++step, 0);
  };
  return perform_scene(loaded.scene, loaded.geometry, loaded.script, &workspace->lexicon(), options);
}

}  // namespace

void validate(const SceneRequest& request) {
  check_fields(request);
  if (request.msaa == 3) usage_error("msaa", "3 is not 1, 2 or 4");
  if (camera_names(request.camera).empty()) usage_error("camera", "no camera named");
  if (request.output.empty()) {
    if (request.sheet) usage_error("sheet", "--sheet needs an output (-o OUT.png)");
    if (request.time) usage_error("time", "--time needs an output (-o OUT.png)");
  } else {
    as_field_error(ErrorCategory::usage, "output", [&] {
      SceneRenderJob job = render_job(request, 0.0f);
      RenderJob plain;
      plain.output = job.output;
      plain.size = job.size;
      plain.fps = job.fps;
      plain.sheet = job.sheet;
      plain.msaa_samples = job.msaa_samples;
      gestura::validate(plain);
    });
  }
  validate(request.source);
}

SceneResult run(const SceneRequest& request, const RunContext& context) {
  validate(request);
  // Before the performance (seconds of work): the file's folder must be there to write into.
  if (const std::filesystem::path folder = std::filesystem::path(request.output).parent_path();
      !request.output.empty() && !request.check && !folder.empty() && !std::filesystem::is_directory(folder))
    throw AppError(ErrorCategory::output, Place{"output", {}}, "cannot write " + request.output + ": no folder " + folder.string());
  LoadedScene loaded = load(request.source);
  const std::vector<std::string> cameras = camera_names(request.camera);
  as_field_error(ErrorCategory::usage, "camera", [&] { expand_scene_cameras(cameras, loaded.scene); });
  loaded.geometry = build_scene_geometry(loaded.scene);

  SceneResult result;
  const Scene& s = loaded.scene;
  std::size_t actions = 0;
  for (const ScriptStatement& st : loaded.script.statements)
    for (const ScriptChain& c : st.chains) actions += c.actions.size();
  result.summary.push_back("scene " + (s.name.empty() ? request.source.scene : s.name) + ": " + std::to_string(s.objects.size()) +
                           " objects, " + std::to_string(loaded.geometry.triangle_count()) + " triangles, " +
                           std::to_string(s.places.size()) + " places, " + std::to_string(s.characters.size()) + " characters, " +
                           std::to_string(s.cameras.size()) + " cameras");
  result.summary.push_back("script: " + std::to_string(loaded.script.statements.size()) + " statements, " + std::to_string(actions) +
                           " actions");
  if (request.check) return result;

  result.performance = perform(loaded, request.fps, context);
  for (const LogEntry& e : result.performance.log) result.warnings += e.warning ? 1 : 0;
  if (!request.output.empty()) {
    context.check_stop();
    const SceneRenderJob job = render_job(request, request.time.value_or(result.performance.duration * 0.5f));
    result.render = as_field_error(ErrorCategory::output, "output",
                                   [&] { return render_scene_to_file(loaded.scene, loaded.geometry, result.performance, job); });
    result.written = job.output;
  }
  return result;
}

nlohmann::json to_json(const SceneResult& result) {
  nlohmann::json log = nlohmann::json::array();
  for (const LogEntry& e : result.performance.log) log.push_back({{"time", e.time}, {"text", e.text}, {"warning", e.warning}});
  nlohmann::json out = {{"summary", result.summary}, {"duration", result.performance.duration}, {"log", log}, {"warnings", result.warnings}};
  if (!result.written.empty()) out["written"] = result.written, out["frames"] = result.render.frames;
  return out;
}

void validate(const SceneViewRequest& request) {
  check_fields(request);
  if (camera_names(request.camera).size() > 1) usage_error("camera", "the viewer starts with one camera");
  validate(request.source);
}

PlayableScene run(const SceneViewRequest& request, const RunContext& context) {
  validate(request);
  PlayableScene out;
  out.loaded = load(request.source);
  out.cameras = camera_names(request.camera);
  as_field_error(ErrorCategory::usage, "camera", [&] { expand_scene_cameras(out.cameras, out.loaded.scene); });
  for (const SceneCamera& c : out.loaded.scene.cameras) out.cameras.push_back(c.name);
  for (const char* b : {"perspective", "plan", "section", "characters"}) out.cameras.push_back(b);
  out.loaded.geometry = build_scene_geometry(out.loaded.scene);
  out.performance = perform(out.loaded, 30, context);
  return out;
}

}  // namespace gestura::app
