// The track system (a walk on the whole body, signing masked onto the arms and head above it, fading
// in and out) and collision: body capsules against the environment, bodies against each other, soles
// on the ground; glTF meshes in scenes.
#include <gtest/gtest.h>

#include "support/signing_avatar.hpp"

#include <filesystem>
#include <fstream>

#include "gestura/core/error.hpp"
#include "gestura/world/body_collision.hpp"
#include "gestura/world/locomotion.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/tracks.hpp"
#include "gestura/world/walk.hpp"

namespace {

using namespace gestura;

const Avatar& avatar() { return test::signing_avatar().avatar; }

// A clip holding the right arm raised for `seconds` (what a sign does to the arm), nothing else.
std::shared_ptr<Clip> raised_arm(float seconds) {
  const Skeleton& s = avatar().skeleton;
  auto clip = std::make_shared<Clip>();
  clip->resize_joints(s.size());
  clip->duration = seconds;
  const int shoulder = s.find("r_shoulder");
  const quat up = joint_rotation(s, shoulder, vec3(deg(-80.0f), 0.0f, 0.0f));
  clip->rotations[static_cast<std::size_t>(shoulder)].add(0.0f, up);
  clip->rotations[static_cast<std::size_t>(shoulder)].add(seconds, up);
  clip->channel("jaw_open").add(0.0f, 0.6f);
  clip->channel("jaw_open").add(seconds, 0.6f);
  return clip;
}

TEST(Tracks, WalkOnTheBodySigningOnTheArmAboveIt) {
  const Skeleton& s = avatar().skeleton;
  const WalkRig rig = make_walk_rig(avatar());
  const RootTrajectory body = follow_path(std::vector<vec3>{vec3(0, 0, 0), vec3(0, 0, 5)}, 0.0f, std::nullopt);
  const WalkMotion walk = synthesize_walk(rig, body, nullptr);
  TrackStack stack(s);
  TrackLayer w;
  w.name = "walk";
  w.clip = std::make_shared<Clip>(walk.clip);
  w.fade_in = w.fade_out = 0.0f;
  stack.add(w);
  TrackLayer sign;
  sign.name = "sign";
  sign.clip = raised_arm(2.0f);
  sign.start = 1.5f;
  sign.fade_in = sign.fade_out = 0.3f;
  sign.mask = mask_of_clip(*sign.clip, s.size());
  sign.priority = 1;
  stack.add(sign);
  Pose pose, walking;
  std::vector<float> channels;
  const int shoulder = s.find("r_shoulder"), l_shoulder = s.find("l_shoulder"), knee = s.find("l_knee");
  // Mid-sign: the right arm is the sign's, the legs and the other arm the walk's.
  stack.evaluate(2.5f, pose, &channels);
  sample_clip(walk.clip, 2.5f, WrapMode::Clamp, rest_pose(s), walking);
  EXPECT_NEAR(std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(shoulder)], sign.clip->rotations[static_cast<std::size_t>(shoulder)].values[0])), 1.0f, 1e-4f);
  EXPECT_NEAR(std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(knee)], walking.rotations[static_cast<std::size_t>(knee)])), 1.0f, 1e-5f);
  EXPECT_NEAR(std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(l_shoulder)], walking.rotations[static_cast<std::size_t>(l_shoulder)])), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(pose.translations[0] - walking.translations[0]), 0.0f, 1e-5f);
  ASSERT_EQ(stack.channel_names().size(), 1u);
  EXPECT_NEAR(channels[0], 0.6f, 1e-4f);
  // Fading in: halfway between the walk's arm and the sign's.
  stack.evaluate(1.65f, pose, &channels);
  sample_clip(walk.clip, 1.65f, WrapMode::Clamp, rest_pose(s), walking);
  const float to_sign = std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(shoulder)], sign.clip->rotations[static_cast<std::size_t>(shoulder)].values[0]));
  const float to_walk = std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(shoulder)], walking.rotations[static_cast<std::size_t>(shoulder)]));
  EXPECT_LT(to_sign, 0.9999f);
  EXPECT_LT(to_walk, 0.9999f);
  EXPECT_NEAR(channels[0], 0.3f, 0.05f);
  // After the sign: the walk alone again.
  stack.evaluate(4.2f, pose, &channels);
  sample_clip(walk.clip, 4.2f, WrapMode::Clamp, rest_pose(s), walking);
  EXPECT_NEAR(std::abs(glm::dot(pose.rotations[static_cast<std::size_t>(shoulder)], walking.rotations[static_cast<std::size_t>(shoulder)])), 1.0f, 1e-5f);
  EXPECT_NEAR(channels[0], 0.0f, 1e-6f);
  // Baked: one clip, keys on every driven joint.
  Clip baked = bake(stack, walk.clip.duration, 30.0f);
  EXPECT_FALSE(baked.rotations[static_cast<std::size_t>(shoulder)].empty());
  EXPECT_FALSE(baked.translations[0].empty());
}

TEST(Collision, BodyCapsulesTouchWallsAndEachOtherAndStandOnTheGround) {
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0]},
      {"name": "wall", "shape": "box", "size": [0.2, 2.5, 4], "position": [0.35, 1.25, 0]}]})", "c.json");
  const Environment env = build_environment(build_scene_geometry(scene));
  const BodyVolumes volumes = make_body_volumes(avatar());
  EXPECT_GT(volumes.capsules.size(), 30u);
  std::vector<mat4> model(avatar().skeleton.size());
  local_to_model(avatar().skeleton, rest_pose(avatar().skeleton), model);
  std::vector<WorldCapsule> body;
  place_capsules(volumes, model, body);
  // At the origin the left hand (x ≈ 0.27) is 3 cm from the wall's face at x = 0.25: it is inside.
  const std::vector<Contact> contacts = body_contacts(env, body, 0.0f);
  ASSERT_FALSE(contacts.empty());
  bool hand = false;
  for (const Contact& c : contacts) {
    EXPECT_EQ(c.object, 1);
    hand = hand || volumes.capsules[static_cast<std::size_t>(c.capsule)].name.rfind("l_", 0) == 0;
  }
  EXPECT_TRUE(hand);
  // Standing on the floor: the soles at the ground, not in it.
  EXPECT_GT(volumes.soles.size(), 3u);
  EXPECT_LT(std::abs(sole_penetration(env, volumes, model)), 0.002f);
  std::vector<mat4> lifted = model;
  for (mat4& m : lifted) m = glm::translate(mat4(1.0f), vec3(0, 0.1f, 0)) * m;
  EXPECT_NEAR(sole_penetration(env, volumes, lifted), -0.1f, 0.002f);
  // Two bodies: overlapping at the same spot, apart a metre away.
  std::vector<mat4> moved = model;
  for (mat4& m : moved) m = glm::translate(mat4(1.0f), vec3(0, 0, 1.0f)) * m;
  std::vector<WorldCapsule> other;
  place_capsules(volumes, moved, other);
  EXPECT_LT(body_overlap(body, other), -0.3f);
  place_capsules(volumes, model, other);
  EXPECT_GT(body_overlap(body, other), 0.05f);
}

TEST(Collision, GltfMeshesEnterScenesAndBadOnesAreNamed) {
  const auto dir = std::filesystem::temp_directory_path() / ("gestura_gltf_scene_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  // One triangle 1 m across, red, in a node lifted by 0.5 m; the buffer as a data URI.
  const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  std::string bytes(reinterpret_cast<const char*>(tri), sizeof tri);
  static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0) |
                       (i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0);
    encoded += b64[(v >> 18) & 63];
    encoded += b64[(v >> 12) & 63];
    encoded += i + 1 < bytes.size() ? b64[(v >> 6) & 63] : '=';
    encoded += i + 2 < bytes.size() ? b64[v & 63] : '=';
  }
  auto write = [&](const char* name, const std::string& indices_accessor) {
    std::ofstream out(dir / name);
    out << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0, "translation": [0, 0.5, 0]}],
      "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "material": 0)" << indices_accessor << R"(}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}}],
      "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" << encoded << R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, -1], "max": [1, 0, 0]}]})";
  };
  write("tri.gltf", "");
  write("bad.gltf", R"(, "indices": 7)");
  const SceneGeometry g = build_scene_geometry(parse_scene(R"({"objects": [{"name": "t", "shape": "mesh", "file": "tri.gltf"}]})", "s.json", dir.string()));
  ASSERT_EQ(g.triangle_count(), 1u);
  EXPECT_NEAR(g.colors[0].x, 1.0f, 1e-5f);
  EXPECT_NEAR(g.colors[0].y, 0.0f, 1e-5f);
  const auto hit = ground_below(build_environment(g), vec3(0.2f, 2.0f, -0.2f));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->height, 0.5f, 1e-5f);
  try {
    build_scene_geometry(parse_scene(R"({"objects": [{"shape": "mesh", "file": "bad.gltf"}]})", "s.json", dir.string()));
    FAIL() << "an index past the accessors was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/objects/0/file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("meshes[0].primitives[0]"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
