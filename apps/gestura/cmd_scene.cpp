// gestura scene: perform a scene's script and render it (app/scene.hpp does the work).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/scene.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  struct State {
    app::SceneRequest request;
    bool json = false;
  };
  auto state = std::make_shared<State>();
  const app::SceneRequest* request = &state->request;
  Invocation invocation;
  invocation.fields = bind_fields(state->request);
  invocation.fields.push_back(flag({.name = "json", .help = "print the result as JSON (summary, log, duration, file written)"}, state->json));
  invocation.run = [state, request](const app::RunContext& context) {
    const app::SceneResult result = app::run(*request, context);
    if (state->json) {
      std::printf("%s\n", app::to_json(result).dump(2).c_str());
      return 0;
    }
    for (const std::string& line : result.summary) std::printf("%s\n", line.c_str());
    for (const LogEntry& e : result.performance.log) {
      if (e.warning) std::fprintf(stderr, "warning: %s\n", e.text.c_str());
      else std::printf("%7.2f s  %s\n", static_cast<double>(e.time), e.text.c_str());
    }
    if (!request->check) {
      std::printf("performed %.2f s", static_cast<double>(result.performance.duration));
      if (result.warnings) std::printf(", %d warning(s)", result.warnings);
      std::printf("\n");
    }
    if (!result.written.empty()) std::printf("wrote %s (%d frames)\n", result.written.c_str(), result.render.frames);
    return 0;
  };
  return invocation;
}

const Registration reg{{"scene", "perform a scene's script (walking, signing, doors, autonomous actors) and render it",
                        "Performs a scene (docs/scene.md): its characters walk the paths the planner finds, sign what\n"
                        "they say with the sentence pipeline, open doors, look at whoever signs, follow and avoid each\n"
                        "other — as the scene's own script, a script file or --do text tells them (docs/scene.md,\n"
                        "\"Scripts\"). Prints what happened; with -o renders it headless like gestura render (a .png\n"
                        "is one moment, or with --sheet 16 frames in a 4x4 grid; .gif/.mp4/.webm every frame at\n"
                        "--fps). A goal that cannot be reached is reported (\"warning: script:2:1: ... no path: ...\")\n"
                        "and skipped. gestura view --scene SCENE.json plays a scene in a window.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
