// gestura scene: perform a scene's script and render it (src/gestura/app/scene_command.hpp does the work).
#include <charconv>
#include <cstdio>
#include <sstream>

#include "command.hpp"
#include "gestura/app/scene_command.hpp"
#include "gestura/core/error.hpp"

namespace gestura::cli {
namespace {

constexpr const char* kUsage = R"(usage: gestura scene SCENE.json [-o OUT.png|.gif|.mp4|.webm] [--script FILE | --do TEXT] [options]

Performs a scene (docs/scene.md): its characters walk the paths the planner finds, sign what they
say with the sentence pipeline, open doors, look at whoever signs, follow and avoid each other — as
the scene's own script, a script file or --do text tells them (docs/scene.md, "Scripts"). Prints what
happened; with -o renders it headless like gestura render. A goal that cannot be reached is reported
("warning: script:2:1: ... no path: ...") and skipped.

  -o, --output PATH     .png (one moment, or --sheet), .gif, .mp4 or .webm
  --script FILE         the script (text or JSON) instead of the scene's own
  --do TEXT             the script as text, e.g. "anna walks to chair; anna says \"Hello\""
  --camera LIST         the scene's cameras or plan, section, perspective, perspective2,
                        characters, alias (the four ALIAS views), or a character's name;
                        a comma list renders a split view                         [perspective]
  --size WxH            image size                                               [1280x720]
  --fps N               frames per second, 1..120                                [30]
  --time S              the moment a single PNG shows                [the middle]
  --sheet               PNG: a 4x4 contact sheet over the performance
  --msaa N              samples per pixel: 1, 2 or 4                             [4]
  --check               read and check the scene and script, print a summary, perform nothing)";

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

int run(const std::vector<std::string>& args) {
  SceneRequest request;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") request.output = flag_value(args, i);
    else if (a == "--script") request.script_file = flag_value(args, i);
    else if (a == "--do") request.script_text = flag_value(args, i);
    else if (a == "--camera") request.cameras = split_list(flag_value(args, i));
    else if (a == "--size") request.size = parse_image_size(flag_value(args, i));
    else if (a == "--fps") request.fps = parse_fps(flag_value(args, i));
    else if (a == "--time") request.still_time = parse_seconds(flag_value(args, i), "--time");
    else if (a == "--sheet") request.sheet = true;
    else if (a == "--msaa") request.msaa_samples = parse_msaa(flag_value(args, i));
    else if (a == "--check") request.check_only = true;
    else if (!a.empty() && a[0] == '-') throw Error("unknown flag " + a + " (see gestura scene --help)");
    else if (request.scene.empty()) request.scene = a;
    else throw Error("one scene file, got a second: '" + a + "'");
  }
  if (!request.script_file.empty() && !request.script_text.empty()) throw Error("give --script FILE or --do TEXT, not both");
  const SceneResult result = run_scene_request(request, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  for (const std::string& line : result.summary) std::printf("%s\n", line.c_str());
  for (const LogEntry& e : result.performance.log) {
    if (e.warning) std::fprintf(stderr, "warning: %s\n", e.text.c_str());
    else std::printf("%7.2f s  %s\n", e.time, e.text.c_str());
  }
  if (!request.check_only) std::printf("performed %.2f s%s\n", result.performance.duration,
                                       result.warnings ? (", " + std::to_string(result.warnings) + " warning(s)").c_str() : "");
  if (result.rendered) std::printf("wrote %s (%d frames)\n", request.output.c_str(), result.render.frames);
  return 0;
}

const Registration reg{{"scene", "perform a scene's script (walking, signing, doors, autonomous actors) and render it", kUsage, run}};

}  // namespace
}  // namespace gestura::cli
