// A script performed end to end: the issue's example ("anna walks to chair; anna says "Hello, sit
// down please."; ben turns to anna") and "ben walks to the door and opens it" — the walk reaches the
// chair, the sentence is signed with face channels, ben looks at anna while she signs and then turns
// to her, his hand holds the door's handle while the door swings open; an unreachable goal is a
// located "no path" warning; and the performance renders.
#include <gtest/gtest.h>

#include "support/png_file.hpp"

#include <filesystem>

#include "gestura/anim/sampler.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/world/director.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/trajectory.hpp"

namespace {

using namespace gestura;

const char* kScene = R"({
  "objects": [
    {"name": "floor", "shape": "box", "size": [8, 0.1, 7], "position": [3, -0.05, 2.5]},
    {"name": "wall_north", "shape": "box", "size": [8, 2.5, 0.2], "position": [3, 1.25, -1.1]},
    {"name": "wall_east", "parts": [
      {"shape": "box", "size": [0.2, 2.5, 3.0], "position": [7.1, 1.25, 0.5]},
      {"shape": "box", "size": [0.2, 2.5, 2.1], "position": [7.1, 1.25, 4.95]}]},
    {"name": "door", "position": [7.0, 0, 2.0], "rotation": [0, -90, 0], "door": {"handle": [0.77, 1.0, 0.06], "open_angle": -90},
     "parts": [{"shape": "box", "size": [0.86, 2.0, 0.04], "position": [0.45, 1.0, 0]},
               {"shape": "box", "size": [0.13, 0.022, 0.022], "position": [0.73, 1.0, 0.06]}]},
    {"name": "chair", "parts": [
      {"shape": "box", "size": [0.45, 0.05, 0.45], "position": [0, 0.45, 0]},
      {"shape": "box", "size": [0.45, 0.5, 0.05], "position": [0, 0.72, -0.2]}], "position": [2.5, 0, 1.0]},
    {"name": "closet_wall", "parts": [
      {"shape": "box", "size": [0.2, 2.5, 2.0], "position": [-0.5, 1.25, 4.0]},
      {"shape": "box", "size": [1.8, 2.5, 0.2], "position": [-1.5, 1.25, 3.0]}]}
  ],
  "places": {"closet": [-1.6, 4.4]},
  "characters": [
    {"name": "anna", "sex": "female", "height": 1.65, "position": [1.0, 3.0], "facing": 90},
    {"name": "ben", "sex": "male", "height": 1.8, "position": [4.5, 2.6], "facing": 180}
  ],
  "cameras": [{"name": "wide", "position": [3, 2.2, 5.8], "target": [3.5, 0.9, 1.5], "fov": 60}]
})";

struct Performed {
  Scene scene = parse_scene(kScene, "director.json");
  SceneGeometry geometry = build_scene_geometry(scene);
  ScenePerformance performance;
  explicit Performed(const std::string& script) {
    performance = perform_scene(scene, geometry, parse_script(script, "script.txt"));
  }
  const PerformedCharacter& character(const std::string& name) const {
    for (const PerformedCharacter& c : performance.characters)
      if (c.name == name) return c;
    throw Error("no " + name);
  }
  float logged(const std::string& start) const {
    for (const LogEntry& e : performance.log)
      if (e.text.rfind(start, 0) == 0) return e.time;
    return -1.0f;
  }
};

std::vector<mat4> posed(const PerformedCharacter& c, float t) {
  const Skeleton& s = c.avatar->skeleton;
  Pose pose;
  sample_clip(c.clip, t, WrapMode::Clamp, rest_pose(s), pose);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  return model;
}

vec3 joint(const PerformedCharacter& c, const std::vector<mat4>& model, const char* name) {
  return vec3(model[static_cast<std::size_t>(c.avatar->skeleton.find(name))][3]);
}

// One performance for the whole test (performing builds two avatars and their signers).
const Performed& performed() {
  static const Performed p("anna walks to chair; anna says \"Hello, sit down please.\"; ben turns to anna\n"
                           "anna walks to closet; ben walks to the door and opens it");
  return p;
}

TEST(Director, PerformsTheIssuesScriptOpensTheDoorWarnsOfNoPathAndRenders) {
  const Performed& p = performed();
  for (const LogEntry& e : p.performance.log) std::printf("%6.2f %s%s\n", e.time, e.warning ? "warning: " : "", e.text.c_str());
  for (const LogEntry& e : p.performance.log) EXPECT_TRUE(!e.warning || e.text.find("closet") != std::string::npos) << e.text;
  const float says = p.logged("anna says"), turns = p.logged("ben turns to anna"), opens = p.logged("ben opens door");
  ASSERT_GT(says, 1.0f);
  ASSERT_GT(turns, says);
  ASSERT_GT(opens, turns);

  // Anna stands by the chair when she starts signing.
  const PerformedCharacter& anna = p.character("anna");
  const PerformedCharacter& ben = p.character("ben");
  const vec3 anna_root = joint(anna, posed(anna, says), "humanoid_root");
  EXPECT_LT(glm::length(vec2(anna_root.x - 2.5f, anna_root.z - 1.0f)), 1.1f);
  // Her sentence: the hands move and the face carries mouthing channels.
  EXPECT_FALSE(anna.clip.channel_names.empty());
  const auto mid = posed(anna, says + 1.5f), before = posed(anna, says - 0.5f);
  EXPECT_GT(glm::length(joint(anna, mid, "r_wrist") - joint(anna, before, "r_wrist")), 0.1f);

  // Ben, who sees her signing, looks at her meanwhile: his head turns toward her.
  const auto watching = posed(ben, says + 2.0f);
  const vec3 head = joint(ben, watching, "skullbase");
  const vec3 looks = glm::normalize(vec3(watching[static_cast<std::size_t>(ben.avatar->skeleton.find("skullbase"))][2]));
  const vec3 to_anna = glm::normalize(joint(anna, posed(anna, says + 2.0f), "skullbase") - head);
  EXPECT_GT(glm::dot(vec2(looks.x, looks.z) / glm::length(vec2(looks.x, looks.z)), vec2(to_anna.x, to_anna.z) / glm::length(vec2(to_anna.x, to_anna.z))),
            std::cos(deg(30.0f)));
  // After turning he faces her with his body.
  const auto turned = posed(ben, p.logged("ben walks to door") - 0.05f);
  const vec3 forward = vec3(turned[0][2]);
  const vec3 to_her = joint(anna, posed(anna, turns + 1.0f), "humanoid_root") - vec3(turned[0][3]);
  EXPECT_LT(std::abs(angle_difference(yaw_of(forward), yaw_of(to_her))), deg(12.0f));

  // The door opened, and while it swung his right hand held its handle.
  ASSERT_EQ(p.performance.doors.size(), 1u);
  EXPECT_NEAR(p.performance.doors[0].angle.values.back(), -90.0f, 0.5f);
  const float swing = p.performance.doors[0].angle.times[1];  // the first key after the start
  const std::vector<mat4> transforms = object_transforms_at(p.scene, p.performance, swing + 0.2f);
  const mat4 lever = transforms[static_cast<std::size_t>(p.geometry.find_object("door"))] *
                     glm::translate(mat4(1.0f), vec3(0.73f, 1.0f, 0.06f));
  const auto holding = posed(ben, swing + 0.2f);
  const vec3 fingers = joint(ben, holding, "r_middle2");
  EXPECT_LT(glm::length(fingers - vec3(lever[3])), 0.07f) << "the hand is not on the handle";
  (void)opens;

  // The unreachable closet: a warning at its place in the script, and the script went on.
  bool warned = false;
  for (const LogEntry& e : p.performance.log)
    if (e.warning) {
      warned = true;
      EXPECT_NE(e.text.find("script.txt:2:1: anna walks to closet"), std::string::npos) << e.text;
      EXPECT_NE(e.text.find("no path"), std::string::npos) << e.text;
    }
  EXPECT_TRUE(warned);
  EXPECT_GT(p.logged("ben opens door"), 0.0f);

  // And the performance renders from the scene's camera.
  const auto path = std::filesystem::temp_directory_path() / ("gestura_director_" + std::to_string(::getpid()) + ".png");
  SceneRenderJob job;
  job.output = path.string();
  job.size = {320, 180};
  job.cameras = {"wide"};
  job.still_time = p.logged("anna says") + 1.0f;
  render_scene_to_file(p.scene, p.geometry, p.performance, job);
  const test::PngPixels image = test::read_png(path.string(), 3);
  std::filesystem::remove(path);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(image.width, 320);
  // The floor, the walls and a dark-clothed figure: many distinct shades, some dark pixels.
  int dark = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* px = image.at(x, y);
      if (px[0] < 70 && px[1] < 70 && px[2] < 90) ++dark;
    }
  EXPECT_GT(dark, 80) << "no figure in the frame";
}

}  // namespace

namespace {

// A cup in the middle of a table's near half: out of the arm's reach from where she can stand, so
// she bends over the table, and her hand closes on the cup without a "stops short" warning.
TEST(Director, TakesACupFromATableByBendingOverIt) {
  Scene scene = parse_scene(R"({
    "objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0]},
      {"name": "table", "parts": [
        {"shape": "box", "size": [1.3, 0.05, 0.8], "position": [0, 0.735, 0]},
        {"shape": "box", "size": [0.06, 0.71, 0.06], "position": [0.58, 0.355, 0.33]},
        {"shape": "box", "size": [0.06, 0.71, 0.06], "position": [-0.58, 0.355, 0.33]},
        {"shape": "box", "size": [0.06, 0.71, 0.06], "position": [0.58, 0.355, -0.33]},
        {"shape": "box", "size": [0.06, 0.71, 0.06], "position": [-0.58, 0.355, -0.33]}], "position": [0, 0, 0]},
      {"name": "cup", "shape": "cylinder", "radius": 0.035, "height": 0.1, "position": [0.1, 0.81, 0.2]}
    ],
    "characters": [{"name": "anna", "sex": "female", "height": 1.65, "position": [0.2, 2.0], "facing": 180}]
  })", "table.json");
  const SceneGeometry geometry = build_scene_geometry(scene);
  const ScenePerformance performance = perform_scene(scene, geometry, parse_script("anna takes the cup", "script.txt"));
  float reach = -1.0f;
  const char* hand = "r_middle2";
  for (const LogEntry& e : performance.log) {
    if (e.text.find("cup with the left") != std::string::npos) hand = "l_middle2";
    std::printf("%6.2f %s%s\n", e.time, e.warning ? "warning: " : "", e.text.c_str());
    EXPECT_FALSE(e.warning) << e.text;
    if (e.text.find("cup with the") != std::string::npos) reach = e.time;
  }
  ASSERT_GT(reach, 0.0f);
  const PerformedCharacter& anna = performance.characters.at(0);
  const auto before = posed(anna, reach), holding = posed(anna, reach + PerformOptions{}.reach_seconds + 0.05f);
  EXPECT_LT(glm::length(joint(anna, holding, hand) - vec3(0.1f, 0.81f, 0.2f)), 0.08f) << "the hand is not at the cup";
  // She bent over: her head came down and forward, toward the table.
  const vec3 head_up = joint(anna, before, "skullbase"), head_down = joint(anna, holding, "skullbase");
  EXPECT_LT(head_down.y, head_up.y - 0.05f);
  // Her feet stayed on the floor.
  EXPECT_LT(std::abs(joint(anna, holding, "l_ankle").y - joint(anna, before, "l_ankle").y), 0.01f);

  // Bending over it, no skin goes more than 1 cm into the table (the fingers meet the cup).
  const Avatar& a = *anna.avatar;
  std::vector<mat4> inverse_bind(a.skeleton.size()), skinning(a.skeleton.size());
  {
    std::vector<mat4> bind(a.skeleton.size());
    local_to_model(a.skeleton, rest_pose(a.skeleton), bind);
    for (std::size_t j = 0; j < bind.size(); ++j) inverse_bind[j] = glm::inverse(bind[j]);
  }
  Environment table = build_environment(geometry);
  std::erase_if(table.primitives, [&](const WorldPrimitive& w) { return w.object != geometry.find_object("table"); });
  std::vector<vec3> skin(a.mesh.vertex_count());
  float deepest = 0.0f, when = 0.0f;
  vec3 where(0.0f);
  std::string bone;
  for (float t = reach; t <= reach + 2.5f; t += 0.1f) {
    skinning_matrices(posed(anna, t), inverse_bind, skinning);
    skin_positions(skinning, a.mesh.joints, a.mesh.weights, a.mesh.positions, skin);
    for (std::size_t k = 0; k < skin.size(); ++k) {
      const float d = -primitive_signed_distance(table, skin[k]);
      if (d > deepest) deepest = d, where = skin[k], when = t, bone = a.skeleton.names[a.mesh.joints[k][0]];
    }
  }
  std::printf("taking the cup: deepest skin point %.1f mm into the table at (%.2f %.2f %.2f), t=%.2f, %s\n", deepest * 1000.0f,
              where.x, where.y, where.z, when, bone.c_str());
  EXPECT_LT(deepest, 0.01f);
}

TEST(Director, CrouchesForACupNearTheFloorWithItsFeetPlanted) {
  // A cup on a narrow plinth (too small to step onto): its middle 20 cm above the floor, far below what bending over reaches.
  Scene scene = parse_scene(R"({
    "objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0]},
      {"name": "stool", "shape": "box", "size": [0.14, 0.15, 0.14], "position": [0, 0.075, 0]},
      {"name": "cup", "shape": "cylinder", "radius": 0.035, "height": 0.1, "position": [0, 0.2, 0]}
    ],
    "characters": [{"name": "anna", "sex": "female", "height": 1.65, "position": [0.1, 0.6], "facing": 180}]
  })", "stool.json");
  const SceneGeometry geometry = build_scene_geometry(scene);
  const ScenePerformance performance = perform_scene(scene, geometry, parse_script("anna takes the cup", "script.txt"));
  float reach = -1.0f;
  for (const LogEntry& e : performance.log) {
    std::printf("%6.2f %s%s\n", e.time, e.warning ? "warning: " : "", e.text.c_str());
    EXPECT_FALSE(e.warning) << e.text;  // "the hand stops N cm short" would be one: the grasp's palm is within 1 cm
    if (e.text.find("cup with the") != std::string::npos) reach = e.time;
  }
  ASSERT_GT(reach, 0.0f);
  const PerformedCharacter& anna = performance.characters.at(0);
  const float holding_time = reach + PerformOptions{}.reach_seconds + 0.05f;
  const auto before = posed(anna, reach), holding = posed(anna, holding_time);

  // She went down on her legs: the hips lower by a good part of the leg, the knees bent.
  const float hips_down = joint(anna, before, "humanoid_root").y - joint(anna, holding, "humanoid_root").y;
  std::printf("crouching: the hips go down %.2f m\n", hips_down);
  EXPECT_GT(hips_down, 0.15f);
  for (const char* side : {"l", "r"}) {
    const std::string hip = std::string(side) + "_hip", knee = std::string(side) + "_knee", ankle = std::string(side) + "_ankle";
    const auto bend = [&](const std::vector<mat4>& m) {
      const vec3 thigh = glm::normalize(joint(anna, m, knee.c_str()) - joint(anna, m, hip.c_str()));
      const vec3 shin = glm::normalize(joint(anna, m, ankle.c_str()) - joint(anna, m, knee.c_str()));
      return to_degrees(std::acos(std::clamp(glm::dot(thigh, shin), -1.0f, 1.0f)));
    };
    EXPECT_GT(bend(holding), bend(before) + 30.0f) << side << " knee";
    // The feet stay planted: over the whole reach (down, holding, up again) the ankles move less
    // than 1 cm.
    const float standing = joint(anna, before, "humanoid_root").y;
    float moved = 0.0f, crouched_for = 0.0f;
    for (float t = reach; t <= reach + 3.0f; t += 0.02f) {
      const auto m = posed(anna, t);
      if (joint(anna, m, "humanoid_root").y < standing - 0.1f) crouched_for += 0.02f;
      moved = std::max(moved, glm::length(joint(anna, m, ankle.c_str()) - joint(anna, before, ankle.c_str())));
    }
    EXPECT_GT(crouched_for, 1.0f);
    EXPECT_LT(moved, 0.01f) << side << " foot slid";
  }

  // The hand at the cup: some skin of the reaching hand within 1 cm of its surface, none more than
  // 1 cm inside; and no skin more than 1 cm into the floor (or the stool) over the whole reach.
  const Avatar& a = *anna.avatar;
  std::vector<mat4> inverse_bind(a.skeleton.size()), skinning(a.skeleton.size());
  {
    std::vector<mat4> bind(a.skeleton.size());
    local_to_model(a.skeleton, rest_pose(a.skeleton), bind);
    for (std::size_t j = 0; j < bind.size(); ++j) inverse_bind[j] = glm::inverse(bind[j]);
  }
  const Environment env = build_environment(geometry);
  Environment cup = env, ground = env;
  std::erase_if(cup.primitives, [&](const WorldPrimitive& w) { return w.object != geometry.find_object("cup"); });
  std::erase_if(ground.primitives, [&](const WorldPrimitive& w) { return w.object == geometry.find_object("cup"); });
  std::vector<vec3> skin(a.mesh.vertex_count());
  skinning_matrices(holding, inverse_bind, skinning);
  skin_positions(skinning, a.mesh.joints, a.mesh.weights, a.mesh.positions, skin);
  float nearest = 1e9f, deepest_in_cup = 0.0f;
  for (const vec3& v : skin) {
    const float d = primitive_signed_distance(cup, v);
    nearest = std::min(nearest, d), deepest_in_cup = std::max(deepest_in_cup, -d);
  }
  std::printf("crouching: the hand %.1f mm from the cup, %.1f mm at most into it\n", nearest * 1000.0f, deepest_in_cup * 1000.0f);
  EXPECT_LT(nearest, 0.01f);
  EXPECT_LT(deepest_in_cup, 0.01f);
  float deepest = 0.0f;
  std::string bone;
  for (float t = reach; t <= reach + 2.5f; t += 0.1f) {
    skinning_matrices(posed(anna, t), inverse_bind, skinning);
    skin_positions(skinning, a.mesh.joints, a.mesh.weights, a.mesh.positions, skin);
    for (std::size_t k = 0; k < skin.size(); ++k) {
      const float d = -primitive_signed_distance(ground, skin[k]);
      if (d > deepest) deepest = d, bone = a.skeleton.names[a.mesh.joints[k][0]];
    }
  }
  std::printf("crouching: deepest skin point %.1f mm into the floor or stool (%s)\n", deepest * 1000.0f, bone.c_str());
  EXPECT_LT(deepest, 0.01f);
}

}  // namespace
