// Scenes: the JSON form reads what docs/scene.md describes, and every malformed scene gives an error
// that names its place (file:line:column and the JSON pointer) instead of a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gestura/core/error.hpp"
#include "gestura/world/environment.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/scene_json.hpp"

namespace {

using namespace gestura;

const char* kRoom = R"({
  "name": "room",
  "materials": {"floor": "#806040", "wood": {"color": "#a07850", "specular": 0.2}},
  "prototypes": {
    "chair": {"parts": [
      {"shape": "box", "size": [0.45, 0.05, 0.45], "position": [0, 0.45, 0]},
      {"shape": "box", "size": [0.45, 0.5, 0.05], "position": [0, 0.7, -0.2]},
      {"shape": "cylinder", "radius": 0.02, "height": 0.45, "position": [0.2, 0.225, 0.2]}
    ]}
  },
  "objects": [
    {"name": "floor", "shape": "plane", "size": [6, 6], "material": "floor"},
    {"name": "chair", "instance": "chair", "position": [1, 0, 0], "rotation": 90, "material": "wood"},
    {"name": "ball", "shape": "sphere", "radius": 0.2, "position": [-1, 0.2, 0]},
    {"name": "sofa", "position": [0, 0, -2], "material": "wood", "parts": [
      {"shape": "box", "size": [2, 0.45, 0.9], "position": [0, 0.225, 0]},
      {"shape": "box", "size": [2, 0.5, 0.2], "position": [0, 0.7, -0.35]}
    ]}
  ],
  "places": {"window": {"position": [2, -1], "facing": 90}},
  "characters": [{"name": "anna", "position": [0, 1], "facing": 180, "colors": {"cloth": "#203040"}}],
  "cameras": [{"name": "wide", "position": [3, 2, 4], "target": [0, 1, 0]}]
})";

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "bad.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, ReadsObjectsPrototypesPlacesCharactersAndCameras) {
  const Scene s = parse_scene(kRoom, "room.json");
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[1].instance, "chair");
  EXPECT_FLOAT_EQ(s.objects[1].transform.rotation.y, 90.0f);
  ASSERT_EQ(s.characters.size(), 1u);
  EXPECT_EQ(s.characters[0].name, "anna");
  EXPECT_NEAR(s.characters[0].colors.at("cloth").x, 0x20 / 255.0f, 1e-6f);
  EXPECT_FLOAT_EQ(*s.places.at("window").facing, 90.0f);
  EXPECT_NE(s.find_camera("wide"), nullptr);
}

TEST(Scene, FlattensPrototypesAndGroupsIntoPlacedTriangles) {
  const Scene s = parse_scene(kRoom, "room.json");
  const SceneGeometry g = build_scene_geometry(s);
  ASSERT_EQ(g.object_names.size(), 4u);
  // The chair instance: 2 boxes (12 triangles each) and a 32-sided cylinder (32·2 side + 2·32 caps).
  EXPECT_EQ(g.object_count[1] / 3, 12u + 12u + 128u);
  const Environment env = build_environment(g);
  // The chair's seat top is at 0.475 m, whatever the rotation; the sofa seat at 0.45 m.
  const auto seat = ground_below(env, vec3(1.0f, 2.0f, 0.0f));
  ASSERT_TRUE(seat);
  EXPECT_NEAR(seat->height, 0.475f, 1e-4f);
  EXPECT_EQ(seat->object, 1);
  const auto sofa = ground_below(env, vec3(0.5f, 2.0f, -1.9f));
  ASSERT_TRUE(sofa);
  EXPECT_NEAR(sofa->height, 0.45f, 1e-4f);
  const auto floor = ground_below(env, vec3(2.5f, 2.0f, 2.5f));
  ASSERT_TRUE(floor);
  EXPECT_NEAR(floor->height, 0.0f, 1e-5f);
  // The chair's back, (0, 0.7, -0.2) in the chair, turned by +90° about +Y lies at (-0.2, 0.7, 0).
  EXPECT_LT(primitive_signed_distance(env, vec3(1.0f - 0.2f, 0.8f, 0.0f)), 0.0f);
  EXPECT_GT(primitive_signed_distance(env, vec3(1.0f, 0.8f, -0.2f)), 0.0f);
}

TEST(Scene, WritesJsonThatReadsBackToTheSameScene) {
  const Scene s = parse_scene(kRoom, "room.json");
  const Scene t = parse_scene(scene_to_json(s).dump(2), "again.json");
  ASSERT_EQ(t.objects.size(), s.objects.size());
  const SceneGeometry a = build_scene_geometry(s), b = build_scene_geometry(t);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_NEAR(glm::length(a.positions[i] - b.positions[i]), 0.0f, 1e-5f);
  EXPECT_EQ(t.characters[0].name, "anna");
}

TEST(Scene, UnknownPrimitiveIsLocatedByLineColumnAndPointer) {
  const std::string e = error_of("{\n  \"objects\": [\n    {\"shape\": \"cube\", \"size\": 1}\n  ]\n}");
  EXPECT_NE(e.find("bad.json:3:15"), std::string::npos) << e;
  EXPECT_NE(e.find("/objects/0/shape"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown shape 'cube'"), std::string::npos) << e;
}

TEST(Scene, NegativeSizeIsLocated) {
  const std::string e = error_of(R"({"objects": [{"shape": "box", "size": [1, -2, 1]}]})");
  EXPECT_NE(e.find("/objects/0/size"), std::string::npos) << e;
  EXPECT_NE(e.find("positive"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.json:1:"), std::string::npos) << e;
}

TEST(Scene, CycleOfPrototypesIsNamed) {
  const std::string e = error_of(R"({"prototypes": {
      "a": {"parts": [{"instance": "b"}]},
      "b": {"parts": [{"shape": "box"}, {"instance": "a"}]}},
    "objects": [{"name": "x", "instance": "a"}]})");
  EXPECT_NE(e.find("cycle"), std::string::npos) << e;
  EXPECT_NE(e.find("a → b → a"), std::string::npos) << e;
}

TEST(Scene, NonFiniteNumbersAreRefused) {
  // JSON has no NaN literal; an overflowing number is what a file can carry.
  std::string e = error_of(R"({"objects": [{"shape": "sphere", "radius": 1e999}]})");
  EXPECT_NE(e.find("bad.json:1:44"), std::string::npos) << e;  // at the literal
  EXPECT_NE(e.find("overflow"), std::string::npos) << e;
  e = error_of(R"({"objects": [{"shape": "sphere", "radius": 1e30}]})");
  EXPECT_NE(e.find("/objects/0/radius"), std::string::npos) << e;
  e = error_of(R"({"objects": [{"shape": "sphere", "radius": "NaN"}]})");
  EXPECT_NE(e.find("expected a number"), std::string::npos) << e;
  Scene s;  // and a scene built in code with a NaN
  SceneObject o;
  o.shape.kind = ShapeKind::Box;
  o.transform.position.x = std::nanf("");
  s.objects.push_back(o);
  try {
    validate(s);
    FAIL() << "a NaN position passed";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("/objects/0/position"), std::string::npos) << err.what();
  }
}

TEST(Scene, OtherMistakesAreNamed) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"objects": [{"shape": "box", "colour": "#ffffff"}]})", "unknown member 'colour'"},
      {R"({"objects": [{"shape": "box", "material": "steel"}]})", "unknown material 'steel'"},
      {R"({"objects": [{"instance": "table"}]})", "unknown prototype 'table'"},
      {R"({"objects": [{"name": "a", "shape": "box"}, {"name": "a", "shape": "box"}]})", "a second object named 'a'"},
      {R"({"objects": [{"shape": "box", "parts": [{"shape": "box"}]}]})", "one of"},
      {R"({"objects": [{"shape": "cylinder", "radius": 0.1, "segments": 2}]})", "segments must be 3..256"},
      {R"({"characters": [{"name": "x", "place": "nowhere"}]})", "unknown place 'nowhere'"},
      {R"({"objects": [{"shape": "mesh", "file": "missing.obj"}]})", ""},  // validated; fails when read
      {R"({"objects": [{"shape": "box", "size": [1, 2]}]})", "expected [x, y, z]"},
      {R"({"objects": {"shape": "box"}})", "expected an array"},
      {"{\"objects\": [\n  {\"shape\": \"box\",}\n]}", "bad.json:2:"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    if (*expected == '\0') {
      EXPECT_EQ(e, "") << text;
      continue;
    }
    EXPECT_NE(e.find(expected), std::string::npos) << text << "\n→ " << e;
  }
}

TEST(Scene, UnreadableMeshFileIsNamedWithItsObject) {
  const Scene s = parse_scene(R"({"objects": [{"name": "lamp", "shape": "mesh", "file": "no-such-lamp.obj"}]})", "m.json", "/tmp");
  try {
    build_scene_geometry(s);
    FAIL() << "a missing mesh file was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/objects/0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no-such-lamp.obj"), std::string::npos) << e.what();
  }
}

TEST(Scene, ReadsObjMeshesRelativeToTheSceneFile) {
  const auto dir = std::filesystem::temp_directory_path() / "gestura_scene_obj_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream obj(dir / "tri.obj");
    obj << "v 0 0 0\nv 100 0 0\nv 0 0 -100\nf 1 2 3\n";  // centimetres
    std::ofstream bad(dir / "bad.obj");
    bad << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
    std::ofstream scene(dir / "scene.json");
    scene << R"({"objects": [{"name": "t", "shape": "mesh", "file": "tri.obj", "unit": 0.01, "position": [0, 0.5, 0]}]})";
  }
  const SceneGeometry g = build_scene_geometry(read_scene((dir / "scene.json").string()));
  ASSERT_EQ(g.triangle_count(), 1u);
  const Environment env = build_environment(g);
  const auto hit = ground_below(env, vec3(0.2f, 2.0f, -0.2f));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->height, 0.5f, 1e-5f);
  // A malformed OBJ: its own file:line:column comes through.
  const Scene bad = parse_scene(R"({"objects": [{"shape": "mesh", "file": "bad.obj"}]})", "s.json", dir.string());
  try {
    build_scene_geometry(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.obj:3:"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Scene, ExpansionBombsStopWithAnError) {
  // Ten prototypes each holding ten of the previous: 10^10 boxes.
  std::string text = R"({"prototypes": {"p0": {"shape": "box"})";
  for (int i = 1; i <= 10; ++i) {
    text += ", \"p" + std::to_string(i) + "\": {\"parts\": [";
    for (int k = 0; k < 10; ++k) text += std::string(k ? "," : "") + "{\"instance\": \"p" + std::to_string(i - 1) + "\"}";
    text += "]}";
  }
  text += R"(}, "objects": [{"name": "bomb", "instance": "p10"}]})";
  const Scene s = parse_scene(text, "bomb.json");
  try {
    build_scene_geometry(s);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("more than"), std::string::npos) << e.what();
  }
}

}  // namespace
