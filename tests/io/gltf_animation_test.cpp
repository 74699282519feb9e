// glTF animation export: clip → glTF → clip round trips (FK positions compared), the Khronos
// glTF-Validator on what we write (with and without a skinned, morphing mesh), malformed input,
// and the convert rows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gestura/anim/sampler.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"
#include "support/build_paths.hpp"

namespace {

using namespace gestura;

using gestura::test::shared_data;

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("gestura_gltf_" + std::to_string(getpid()) + "_" + name)).string();
}

using test::CliRun;
using test::run_command;

// The Khronos validator via tools/validate-gltf.mjs; skips when node or the npm package is absent.
bool validator_available() {
  return std::filesystem::exists(gestura::test::source_dir() + "/tools/node_modules/gltf-validator") &&
         run_command("node --version").status == 0;
}

CliRun validate_file(const std::string& path) {
  return run_command("node '" + gestura::test::source_dir() + "/tools/validate-gltf.mjs' '" + path + "'");
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The avatar waving: shoulder slerp keys, elbow Catmull-Rom (resampled on export), a stepped wrist,
// root translation.
Clip wave(const Skeleton& s) {
  Clip clip;
  clip.name = "wave";
  clip.resize_joints(s.size());
  clip.duration = 2.0f;
  QuatTrack& sh = clip.rotations[static_cast<std::size_t>(s.find("l_shoulder"))];
  sh.interpolation = Interpolation::Slerp;
  sh.add(0.0f, quat(1, 0, 0, 0));
  sh.add(1.0f, glm::angleAxis(deg(120.0f), vec3(0, 0, 1)));
  sh.add(2.0f, glm::angleAxis(deg(90.0f), vec3(0, 0, 1)));
  QuatTrack& el = clip.rotations[static_cast<std::size_t>(s.find("l_elbow"))];
  el.interpolation = Interpolation::CatmullRom;
  for (int k = 0; k <= 4; ++k) el.add(0.5f * float(k), glm::angleAxis(deg(-40.0f - 30.0f * float(k % 2)), vec3(1, 0, 0)));
  QuatTrack& wr = clip.rotations[static_cast<std::size_t>(s.find("l_wrist"))];
  wr.interpolation = Interpolation::Step;
  wr.add(0.0f, quat(1, 0, 0, 0));
  wr.add(1.3f, glm::angleAxis(deg(30.0f), vec3(0, 0, 1)));
  Vec3Track& root = clip.translations[0];
  root.add(0.0f, s.rest_translations[0]);
  root.add(2.0f, s.rest_translations[0] + vec3(0.2f, 0.0f, 0.1f));
  return clip;
}

std::vector<vec3> fk(const Skeleton& s, const Clip& c, float t) {
  Pose pose;
  sample_clip(c, t, WrapMode::Clamp, rest_pose(s), pose);
  std::vector<mat4> m(s.size());
  local_to_model(s, pose, m);
  std::vector<vec3> p(s.size());
  model_positions(m, p);
  return p;
}

float worst_position_error(const Skeleton& a, const Clip& ca, const Skeleton& b, const Clip& cb, float duration) {
  float worst = 0.0f;
  for (int k = 0; k <= 40; ++k) {
    const float t = std::min(duration, duration * (float(k) + 0.37f) / 40.0f);  // between keys too
    const auto pa = fk(a, ca, t), pb = fk(b, cb, t);
    for (std::size_t j = 0; j < pa.size(); ++j) worst = std::max(worst, glm::length(pa[j] - pb[j]));
  }
  return worst;
}

TEST(GltfAnimation, RoundTripKeepsTheMotion) {
  const Skeleton avatar = build_avatar_skeleton();
  const Clip clip = wave(avatar);
  for (bool binary : {true, false}) {
    const GltfDocument doc = make_gltf(avatar, clip, nullptr, {60.0f});
    const std::string bytes = binary ? pack_glb(doc) : pack_gltf_embedded(doc);
    const GltfAnimation back = read_gltf_animation(bytes, "wave");
    ASSERT_EQ(back.skeleton.names, avatar.names);
    EXPECT_EQ(back.skeleton.parents, avatar.parents);
    EXPECT_EQ(back.clip.name, "wave");
    EXPECT_FLOAT_EQ(back.clip.duration, 2.0f);
    EXPECT_EQ(back.clip.rotations[static_cast<std::size_t>(avatar.find("l_wrist"))].interpolation, Interpolation::Step);
    // Exact keys for slerp / step / linear tracks; the Catmull-Rom elbow is resampled at 60 fps.
    const float worst = worst_position_error(avatar, clip, back.skeleton, back.clip, 2.0f);
    EXPECT_LT(worst, 0.002f) << (binary ? "glb" : "gltf");
    RecordProperty(binary ? "glb_worst_m" : "gltf_worst_m", std::to_string(worst));
  }
}

TEST(GltfAnimation, MakeHumanBvhRoundTrip) {
  const BvhFile bvh = load_bvh(shared_data() + "/makehuman/poses/run01.bvh", {0.1f, true});
  const GltfAnimation back = read_gltf_animation(pack_glb(make_gltf(bvh.skeleton, bvh.clip)), "run01");
  ASSERT_EQ(back.skeleton.size(), bvh.skeleton.size());
  const float worst = worst_position_error(bvh.skeleton, bvh.clip, back.skeleton, back.clip, bvh.clip.duration);
  EXPECT_LT(worst, 1e-5f);
  RecordProperty("run01_worst_m", std::to_string(worst));
}

// A two-joint strip skinned half to each joint, with two named morph targets.
Mesh strip_mesh(const Skeleton& s) {
  Mesh m;
  const int a = s.find("l_shoulder"), b = s.find("l_elbow");
  const auto rest = rest_joint_positions(s);
  for (int k = 0; k < 4; ++k) {
    const vec3 base = rest[static_cast<std::size_t>(k < 2 ? a : b)];
    m.positions.push_back(base + vec3(0.0f, 0.0f, k % 2 ? 0.05f : -0.05f));
    m.normals.push_back(vec3(1, 0, 0));
    m.materials.push_back(0);
    m.joints.push_back(JointIndices(k < 2 ? a : b, 0, 0, 0));
    m.weights.push_back(vec4(1, 0, 0, 0));
  }
  m.indices = {0, 2, 1, 1, 2, 3};
  m.morphs.push_back({"aa", {0, 1}, {vec3(0, 0.01f, 0), vec3(0, 0.02f, 0)}, {}});
  m.morphs.push_back({"blink", {3}, {vec3(0.01f, 0, 0)}, {}});
  return m;
}

TEST(GltfAnimation, SkinnedMorphingMeshReadsBackItsWeights) {
  const Skeleton avatar = build_avatar_skeleton();
  Clip clip = wave(avatar);
  FloatTrack& aa = clip.channel("aa");
  aa.add(0.0f, 0.0f);
  aa.add(0.5f, 1.0f);
  aa.add(1.0f, 0.25f);
  clip.channel("not_a_morph").add(0.0f, 3.0f);
  const Mesh mesh = strip_mesh(avatar);
  const GltfDocument doc = make_gltf(avatar, clip, &mesh);
  const nlohmann::json json = nlohmann::json::parse(doc.json);
  EXPECT_EQ(json["meshes"][0]["extras"]["targetNames"], nlohmann::json({"aa", "blink"}));
  EXPECT_EQ(json["skins"][0]["joints"].size(), avatar.size());
  const GltfAnimation back = read_gltf_animation(pack_glb(doc), "mesh");
  EXPECT_EQ(back.skeleton.size(), avatar.size()) << "the mesh node is not a joint";
  const int c = back.clip.find_channel("aa");
  ASSERT_GE(c, 0);
  EXPECT_NEAR(sample_track(back.clip.channels[static_cast<std::size_t>(c)], 0.75f), 0.625f, 1e-6f);
  const int blink = back.clip.find_channel("blink");
  ASSERT_GE(blink, 0);
  EXPECT_EQ(sample_track(back.clip.channels[static_cast<std::size_t>(blink)], 0.5f), 0.0f);
  EXPECT_LT(back.clip.find_channel("not_a_morph"), 0);
}

TEST(GltfAnimation, KhronosValidatorFindsNoErrors) {
  if (!validator_available()) GTEST_SKIP() << "node or tools/node_modules/gltf-validator missing (cd tools && npm install)";
  const Skeleton avatar = build_avatar_skeleton();
  Clip clip = wave(avatar);
  clip.channel("aa").add(0.0f, 0.0f);
  clip.channel("aa").add(1.0f, 1.0f);
  const Mesh mesh = strip_mesh(avatar);
  const BvhFile bvh = load_bvh(shared_data() + "/makehuman/poses/run01.bvh", {0.1f, true});
  const std::vector<std::pair<std::string, std::string>> files = {
      {"wave.glb", pack_glb(make_gltf(avatar, clip))},
      {"wave.gltf", pack_gltf_embedded(make_gltf(avatar, clip))},
      {"mesh.glb", pack_glb(make_gltf(avatar, clip, &mesh))},
      {"run01.glb", pack_glb(make_gltf(bvh.skeleton, bvh.clip))}};
  for (const auto& [name, bytes] : files) {
    const std::string path = temp_path(name);
    write_file(path, bytes);
    const CliRun r = validate_file(path);
    std::filesystem::remove(path);
    EXPECT_EQ(r.status, 0) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("\"numErrors\": 0"), std::string::npos) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("\"numWarnings\": 0"), std::string::npos) << name << "\n" << r.output;
  }
}

TEST(GltfAnimation, ValidatorScriptFailsOnABrokenFile) {
  if (!validator_available()) GTEST_SKIP() << "node or tools/node_modules/gltf-validator missing";
  const std::string path = temp_path("broken.gltf");
  write_file(path, R"({"asset":{"version":"2.0"},"nodes":[{"children":[0]}]})");
  const CliRun r = validate_file(path);
  std::filesystem::remove(path);
  EXPECT_EQ(r.status, 1) << r.output;
}

void expect_error(const std::string& bytes, const std::string& needle) {
  try {
    read_gltf_animation(bytes, "bad.glb");
    ADD_FAILURE() << "accepted: " << needle;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.glb"), std::string::npos) << e.what();
  }
}

TEST(GltfAnimation, MalformedInputIsAnErrorNamingThePlace) {
  const Skeleton avatar = build_avatar_skeleton();
  const std::string glb = pack_glb(make_gltf(avatar, wave(avatar)));
  expect_error(glb.substr(0, glb.size() / 2), "truncated");
  expect_error(glb.substr(0, 14), "shorter");
  expect_error("{\"asset\": {\"version\": \"2.0\"", "bad JSON");
  expect_error("{\"asset\": {\"version\": \"1.0\"}}", "asset");
  expect_error(std::string("\x00\x01\xff\xfe junk \x7f", 11), "bad JSON");
  expect_error(R"({"asset":{"version":"2.0"},"nodes":[{"children":[1]},{"children":[0]}]})", "cycle");
  expect_error(R"({"asset":{"version":"2.0"},"nodes":[{"children":[2]},{"children":[2]},{}]})", "two parents");
  expect_error(R"({"asset":{"version":"2.0"},"nodes":[{"children":[5]}]})", "nodes[0]");
  expect_error(R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":8}]})", "buffers[0]");
  expect_error(R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":8,"uri":"skin.bin"}]})", "external");
  // An accessor reading past its buffer view, and a channel to a missing sampler.
  nlohmann::json doc = nlohmann::json::parse(make_gltf(avatar, wave(avatar)).json);
  const GltfDocument good = make_gltf(avatar, wave(avatar));
  doc["accessors"][0]["count"] = 1000000;
  expect_error(pack_glb({doc.dump(), good.buffer}), "accessors[0]");
  doc = nlohmann::json::parse(good.json);
  doc["animations"][0]["channels"][0]["sampler"] = 99;
  expect_error(pack_glb({doc.dump(), good.buffer}), "channels[0]");
  doc = nlohmann::json::parse(good.json);
  doc["bufferViews"][0]["byteLength"] = 1u << 30;
  expect_error(pack_glb({doc.dump(), good.buffer}), "bufferViews[0]");
  // Byte flips anywhere in the file never crash: either an Error or a readable result.
  for (std::size_t at = 0; at < glb.size(); at += 13) {
    std::string mutated = glb;
    mutated[at] = static_cast<char>(mutated[at] ^ 0x5A);
    try {
      read_gltf_animation(mutated, "mutated");
    } catch (const Error&) {
    }
  }
}

TEST(GltfAnimation, ConvertBvhToGlbAndBack) {
  const std::string in = shared_data() + "/makehuman/poses/standing02.bvh";
  const std::string glb = temp_path("s.glb"), bvh = temp_path("s.bvh");
  const CliRun to = test::run_cli("convert '" + in + "' '" + glb + "' --scale 0.1 --z-up");
  ASSERT_EQ(to.status, 0) << to.output;
  const CliRun back = test::run_cli("convert '" + glb + "' '" + bvh + "'");
  ASSERT_EQ(back.status, 0) << back.output;
  const BvhFile original = load_bvh(in, {0.1f, true}), again = load_bvh(bvh);
  std::filesystem::remove(glb);
  std::filesystem::remove(bvh);
  ASSERT_EQ(again.skeleton.names, original.skeleton.names);
  EXPECT_LT(worst_position_error(original.skeleton, original.clip, again.skeleton, again.clip, 0.0f), 1e-4f);
}

}  // namespace
