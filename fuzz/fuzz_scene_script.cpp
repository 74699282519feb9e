// Fuzz target: the world's scripts ("anna walks to the chair; ben opens the door"), text and JSON,
// as `gestura scene --script` reads them: parse_script, then check_script against a small scene
// with two characters, a door, a chair, a cup and a place, so that names resolve and fail both ways.
#include "fuzz_target.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/script.hpp"

namespace {

const gestura::Scene& room() {
  static const gestura::Scene scene = gestura::parse_scene(R"({
    "version": 1, "name": "room",
    "objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0]},
      {"name": "door", "position": [3, 0, 1], "door": {"handle": [0.77, 1.02, 0.06]},
       "parts": [{"shape": "box", "size": [0.86, 2.08, 0.04], "position": [0.45, 1.045, 0]}]},
      {"name": "chair", "shape": "box", "size": [0.45, 0.45, 0.45], "position": [1, 0.225, 1]},
      {"name": "cup", "shape": "cylinder", "radius": 0.035, "height": 0.1, "position": [1, 0.5, 1]}
    ],
    "places": {"window": {"position": [-2, 0], "facing": 90}},
    "characters": [{"name": "anna", "position": [0, 0]}, {"name": "ben", "position": [1, -1], "facing": 180}]
  })", "room.json");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = gestura::fuzz::text_of(data, size);
  gestura::fuzz::expect_result_or_error([&] {
    const gestura::Script script = gestura::parse_script(text, "fuzz.script");
    for (const auto& statement : script.statements)
      for (const auto& chain : statement.chains)
        for (const auto& action : chain.actions) (void)action.describe();
    gestura::check_script(script, room());
  });
  return 0;
}
