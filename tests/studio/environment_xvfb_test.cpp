// The studio's environment and colour editors under a virtual X server, driven by --script: a box
// dragged in the plan view moves by what the drag covers on the floor, saved; undo puts it back; a
// colour chosen is saved; a malformed scene is refused with its place and loses nothing. Screenshots
// go to $GESTURA_STUDIO_SCREENSHOTS when set (docs/studio.md uses them). Skipped only where xvfb-run
// is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "gestura/world/scene_json.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/studio_under_xvfb.hpp"
#include "support/png_file.hpp"

namespace gestura {
namespace {

namespace fs = std::filesystem;
using gestura::test::run_command;
using gestura::testing::TempDir;
using gestura::test::have_xvfb;
using gestura::test::read_json_file;
using gestura::test::shot_dir;

gestura::test::CliRun run_studio(const TempDir& dir, const std::string& script) {
  return gestura::test::run_studio(dir, dir.file("user.sqlite"), "env.script", script);
}


std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}



// An 8 m × 6 m floor and a 1 m box in the middle of it.
constexpr const char* kRoom = R"({
  "name": "test room",
  "materials": {"floor": "#9c8466", "wood": "#8a5a36"},
  "objects": [
    {"name": "floor", "shape": "plane", "size": [8, 6], "material": "floor"},
    {"name": "box", "shape": "box", "size": [1, 1, 1], "position": [0, 0.5, 0], "material": "wood"},
    {"name": "ball", "shape": "sphere", "radius": 0.3, "position": [2, 0.3, 1.5]}
  ],
  "places": {"door": {"position": [3.5, 0, -2.5]}},
  "characters": [{"name": "anna", "position": [-2, 0, 1]}]
})";

vec3 position_of(const nlohmann::json& scene, const std::string& name) {
  for (const auto& o : scene["objects"])
    if (o["name"] == name) {
      if (!o.contains("position")) return vec3(0.0f);
      return vec3(o["position"][0].get<float>(), o["position"][1].get<float>(), o["position"][2].get<float>());
    }
  ADD_FAILURE() << "no object " << name << " in " << scene.dump();
  return vec3(0.0f);
}

// One studio run for both tests (each start of the studio under Xvfb costs seconds): the drag, the
// colours and the undo on one scene, then an edit and a malformed scene refused.
struct EnvRun {
  TempDir dir;
  std::string room, bad, j, shots;
  std::string bad_text = "{\n  \"objects\": [\n    {\"name\": \"x\", \"shape\": \"cube\"}\n  ]\n}\n";
  gestura::test::CliRun result;
  EnvRun() {
    room = dir.write("room.json", kRoom), bad = dir.write("bad.json", bad_text), j = dir.file(""), shots = shot_dir(dir);
    result = run_studio(dir,
                        "mode env\n"
                        "env-open " + room + "\n"
                        "wait 1\n"
                        "dump " + j + "opened.json\n"
                        "env-drag-from plan box 100 -50\n"  // 100 pixels right, 50 up: east and north on the plan
                        "dump " + j + "dragged.json\n"
                        "env-save\n"
                        "env-colour 2060c0\n"
                        "env-select ball\n"
                        "env-ramp 0 4\n"  // a click on the palette's red-up ramp
                        "env-select box\n"
                        "wait 1\n"
                        "screenshot " + shots + "/studio-environment.png\n"
                        "env-save " + j + "moved.json\n"
                        "undo\n"  // the ball's colour
                        "undo\n"  // the box's colour
                        "undo\n"  // the drag
                        "dump " + j + "undone.json\n"
                        "env-save " + j + "undone-saved.json\n"
                        "env-open " + room + "\n"  // as saved after the drag
                        "env-select box\n"
                        "env-set position 1.5 0.5 -1\n"
                        "env-open " + bad + "\n"
                        "dump " + j + "refused.json\n"
                        "env-save\n"
                        "quit\n");
  }
};

const EnvRun& env_run() {
  static const EnvRun run;
  return run;
}

TEST(EnvironmentEditorUnderXvfb, ABoxDraggedInThePlanViewMovesByTheDragUndoPutsItBackAndAColourIsSaved) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  const EnvRun& run = env_run();
  const auto& r = run.result;
  const std::string& j = run.j;
  const std::string& shots = run.shots;
  ASSERT_EQ(0, r.status) << r.output;
  const auto opened = read_json_file(j + "opened.json")["environment"], dragged = read_json_file(j + "dragged.json")["environment"],
             undone = read_json_file(j + "undone.json")["environment"];
  ASSERT_TRUE(opened.is_object() && dragged.is_object() && undone.is_object()) << r.output;

  // The plan view frames the scene's box (the floor: 8 m east-west, 6 m north-south) with 5 % to spare
  // and shows north up: a pixel covers the same metres both ways.
  const auto& plan = opened["views"][2];
  ASSERT_EQ("plan", plan["name"]);
  const float w = plan["width"], h = plan["height"];
  const float half = std::max(3.0f, 4.0f / (w / h)) * 1.05f, metres_per_pixel = 2.0f * half / h;
  const vec3 moved = position_of(dragged["scene"], "box");
  EXPECT_NEAR(100.0f * metres_per_pixel, moved.x, 1.5f * metres_per_pixel) << dragged["scene"].dump();
  EXPECT_NEAR(-50.0f * metres_per_pixel, moved.z, 1.5f * metres_per_pixel);
  EXPECT_NEAR(0.5f, moved.y, 1e-4f);  // a drag in the plan stays on its floor
  EXPECT_EQ("box", dragged["selection"]);
  EXPECT_EQ("move box", dragged["undo"]);

  // Saved: the file as saved then (read back by the scene reader).
  const Scene coloured = read_scene(j + "moved.json");
  EXPECT_NEAR(moved.x, coloured.find_object("box")->transform.position.x, 1e-4f);
  EXPECT_NEAR(moved.z, coloured.find_object("box")->transform.position.z, 1e-4f);
  // The colours: the box's typed, the ball's a palette click (a red-up ramp: redder than grey).
  const vec3 box_colour = coloured.materials.at(coloured.find_object("box")->material).color;
  EXPECT_NEAR(0x20 / 255.0f, box_colour.x, 1e-3f);
  EXPECT_NEAR(0x60 / 255.0f, box_colour.y, 1e-3f);
  EXPECT_NEAR(0xc0 / 255.0f, box_colour.z, 1e-3f);
  const vec3 ball_colour = coloured.materials.at(coloured.find_object("ball")->material).color;
  EXPECT_GT(ball_colour.x, ball_colour.y + 0.2f);
  EXPECT_NEAR(ball_colour.y, ball_colour.z, 1e-3f);

  // Undo: the box where it was, its material its own again; saved so.
  EXPECT_NEAR(0.0f, position_of(undone["scene"], "box").x, 1e-5f);
  EXPECT_NEAR(0.0f, position_of(undone["scene"], "box").z, 1e-5f);
  const Scene undone_saved = read_scene(j + "undone-saved.json");
  EXPECT_EQ("wood", undone_saved.find_object("box")->material);
  EXPECT_NEAR(0.0f, undone_saved.find_object("box")->transform.position.x, 1e-5f);

  const auto image = gestura::test::read_png(shots + "/studio-environment.png", 3);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(1280, image.width);
}

TEST(EnvironmentEditorUnderXvfb, AMalformedSceneIsRefusedWithItsPlaceAndNothingIsLost) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  const EnvRun& run = env_run();
  ASSERT_EQ(0, run.result.status) << run.result.output;
  const auto refused = read_json_file(run.j + "refused.json")["environment"];
  ASSERT_TRUE(refused.is_object()) << run.result.output;
  const std::string status = refused["status"];
  EXPECT_NE(std::string::npos, status.find("bad.json:3:")) << status;  // the line of the unknown shape
  EXPECT_NE(std::string::npos, status.find("cube")) << status;
  EXPECT_EQ(run.room, refused["file"]);
  EXPECT_TRUE(refused["dirty"].get<bool>());
  EXPECT_NEAR(1.5f, position_of(refused["scene"], "box").x, 1e-5f);  // the edit is still there...
  EXPECT_EQ(run.bad_text, read_text(run.bad));                       // ...and the bad file untouched
  EXPECT_NEAR(1.5f, read_scene(run.room).find_object("box")->transform.position.x, 1e-5f);  // saved where it came from
}

}  // namespace
}  // namespace gestura
