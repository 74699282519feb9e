// VRM 1.0 import: a small VRM built here (our glTF writer + a hand-written VRMC_vrm extension with
// VRoid-style node names), read back into H-Anim joints, a skinned mesh, morphs and face channels;
// malformed VRMs give errors naming the place.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/vrm.hpp"
#include "support/cli.hpp"
#include "support/build_paths.hpp"

namespace {

using namespace gestura;
using nlohmann::json;

struct Built {
  Skeleton skeleton;
  Mesh mesh;
  json doc;
  std::vector<std::uint8_t> buffer;
  std::string bytes() const { return pack_glb({doc.dump(), buffer}); }
};

// The avatar skeleton with a 4-vertex strip on the left upper arm / forearm and two morphs.
Built build_vrm() {
  Built b;
  b.skeleton = build_avatar_skeleton();
  const Skeleton& s = b.skeleton;
  const int a = s.find("l_shoulder"), e = s.find("l_elbow");
  const auto rest = rest_joint_positions(s);
  for (int k = 0; k < 4; ++k) {
    b.mesh.positions.push_back(rest[static_cast<std::size_t>(k < 2 ? a : e)] + vec3(0.0f, 0.0f, k % 2 ? 0.05f : -0.05f));
    b.mesh.normals.push_back(vec3(1, 0, 0));
    b.mesh.materials.push_back(0);
    b.mesh.joints.push_back(JointIndices(k < 2 ? a : e, 0, 0, 0));
    b.mesh.weights.push_back(vec4(1, 0, 0, 0));
  }
  b.mesh.indices = {0, 2, 1, 1, 2, 3};
  b.mesh.morphs.push_back({"Fcl_MTH_A", {0, 1}, {vec3(0, 0.01f, 0), vec3(0, 0.02f, 0)}, {}});
  b.mesh.morphs.push_back({"Fcl_EYE_Close_L", {3}, {vec3(0.01f, 0, 0)}, {}});
  Clip still;
  still.resize_joints(s.size());
  const GltfDocument g = make_gltf(s, still, &b.mesh);
  b.doc = json::parse(g.json);
  b.buffer = g.buffer;
  // VRoid-style node names, so the mapping must come from humanBones, not from the names.
  const std::pair<const char*, const char*> renamed[] = {
      {"humanoid_root", "J_Bip_C_Hips"}, {"vl5", "J_Bip_C_Spine"}, {"skullbase", "J_Bip_C_Head"},
      {"l_shoulder", "J_Bip_L_UpperArm"}, {"l_elbow", "J_Bip_L_LowerArm"}, {"r_shoulder", "J_Bip_R_UpperArm"}};
  json bones = json::object();
  const std::pair<const char*, const char*> vrm_bone[] = {{"J_Bip_C_Hips", "hips"},         {"J_Bip_C_Spine", "spine"},
                                                          {"J_Bip_C_Head", "head"},         {"J_Bip_L_UpperArm", "leftUpperArm"},
                                                          {"J_Bip_L_LowerArm", "leftLowerArm"}, {"J_Bip_R_UpperArm", "rightUpperArm"}};
  for (std::size_t i = 0; i < std::size(renamed); ++i) {
    const int j = s.find(renamed[i].first);
    b.doc["nodes"][static_cast<std::size_t>(j)]["name"] = renamed[i].second;
    bones[vrm_bone[i].second] = {{"node", j}};
  }
  const std::size_t mesh_node = s.size();
  b.doc["extensionsUsed"] = {"VRMC_vrm"};
  b.doc["extensions"]["VRMC_vrm"] = {
      {"specVersion", "1.0"},
      {"meta", {{"name", "test"}, {"authors", {"gestura"}}, {"licenseUrl", "https://vrm.dev/licenses/1.0/"}}},
      {"humanoid", {{"humanBones", bones}}},
      {"expressions",
       {{"preset",
         {{"aa", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 0}, {"weight", 1.0}}}}}},
          {"ee", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 0}, {"weight", 0.4}}}}}},
          {"blinkLeft", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 1}, {"weight", 1.0}}}}}},
          {"happy", {{"morphTargetBinds", json::array()}}}}},
        {"custom", {{"tongueOut", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 1}, {"weight", 0.5}}}}}}}}}}};
  return b;
}

TEST(Vrm, ImportsHumanoidMeshMorphsAndExpressions) {
  const Built b = build_vrm();
  const VrmAvatar v = read_vrm(b.bytes(), "test.vrm");
  // Mapped bones carry H-Anim names; the rest keep their node names (here already H-Anim).
  EXPECT_EQ(v.humanoid.at("hips"), "humanoid_root");
  EXPECT_EQ(v.humanoid.at("leftLowerArm"), "l_elbow");
  EXPECT_GE(v.skeleton.find("l_shoulder"), 0);
  EXPECT_LT(v.skeleton.find("J_Bip_L_UpperArm"), 0);
  EXPECT_EQ(v.skeleton.size(), b.skeleton.size());
  EXPECT_EQ(v.skeleton.parents, b.skeleton.parents);
  // Mesh: positions back in rest model space, skinned to the same joints.
  ASSERT_EQ(v.mesh.vertex_count(), 4u);
  EXPECT_EQ(v.mesh.indices, b.mesh.indices);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LT(glm::length(v.mesh.positions[i] - b.mesh.positions[i]), 1e-5f) << i;
    EXPECT_EQ(v.skeleton.names[v.mesh.joints[i][0]], b.skeleton.names[b.mesh.joints[i][0]]);
    EXPECT_FLOAT_EQ(v.mesh.weights[i][0], 1.0f);
  }
  ASSERT_EQ(v.mesh.morphs.size(), 2u);
  EXPECT_EQ(v.mesh.morphs[0].name, "Fcl_MTH_A");
  EXPECT_EQ(v.mesh.morphs[0].vertices, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_LT(glm::length(v.mesh.morphs[0].position_deltas[1] - vec3(0, 0.02f, 0)), 1e-6f);
  // Inverse binds: the file's, equal to the inverse rest pose for our writer.
  const auto rest = rest_joint_positions(v.skeleton);
  const int elbow = v.skeleton.find("l_elbow");
  EXPECT_LT(glm::length(vec3(v.inverse_binds[static_cast<std::size_t>(elbow)] * vec4(rest[static_cast<std::size_t>(elbow)], 1.0f))), 1e-5f);
  // Expressions → our face channels.
  ASSERT_EQ(v.face_channels.at("aa").size(), 1u);
  EXPECT_EQ(v.face_channels.at("aa")[0].morph, 0);
  EXPECT_FLOAT_EQ(v.face_channels.at("E")[0].weight, 0.4f);
  EXPECT_EQ(v.face_channels.at("eyeBlink_L")[0].morph, 1);
  EXPECT_TRUE(v.face_channels.at("joy").empty());
  EXPECT_FLOAT_EQ(v.face_channels.at("tongueOut")[0].weight, 0.5f);
}

TEST(Vrm, PresetNamesMapToOurFaceChannels) {
  EXPECT_EQ(face_channel_for_vrm_preset("ee"), "E");
  EXPECT_EQ(face_channel_for_vrm_preset("surprised"), "surprise");
  EXPECT_EQ(face_channel_for_vrm_preset("blinkRight"), "eyeBlink_R");
  EXPECT_EQ(face_channel_for_vrm_preset("Fcl_ALL_Joy"), "");
}

void expect_vrm_error(const std::string& bytes, const std::string& needle) {
  try {
    read_vrm(bytes, "bad.vrm");
    ADD_FAILURE() << "accepted: " << needle;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(Vrm, MalformedVrmIsAnErrorNamingThePlace) {
  const Built good = build_vrm();
  const std::string bytes = good.bytes();
  expect_vrm_error(bytes.substr(0, bytes.size() - 100), "truncated");
  expect_vrm_error("not a vrm at all", "bad JSON");
  Built b = good;
  b.doc.erase("extensions");
  expect_vrm_error(b.bytes(), "VRMC_vrm");
  b = good;
  b.doc["extensions"] = {{"VRM", json::object()}};  // VRM 0.x is read, but needs its humanoid
  expect_vrm_error(b.bytes(), "humanoid.humanBones (a list)");
  b = good;
  b.doc["extensions"]["VRMC_vrm"]["humanoid"]["humanBones"]["hips"]["node"] = 100000;
  expect_vrm_error(b.bytes(), "humanBones.hips");
  b = good;
  b.doc["extensions"]["VRMC_vrm"]["humanoid"]["humanBones"].erase("hips");
  expect_vrm_error(b.bytes(), "no hips");
  b = good;
  b.doc["extensions"]["VRMC_vrm"]["expressions"]["preset"]["aa"]["morphTargetBinds"][0]["index"] = 7;
  expect_vrm_error(b.bytes(), "expressions.preset.aa");
  b = good;
  b.doc["extensions"]["VRMC_vrm"]["expressions"]["preset"]["aa"]["morphTargetBinds"][0]["node"] = 0;
  expect_vrm_error(b.bytes(), "has no mesh");
  b = good;
  b.doc["skins"][0]["joints"] = {0};  // JOINTS_0 now point past the skin's joint list
  b.doc["skins"][0].erase("inverseBindMatrices");
  expect_vrm_error(b.bytes(), "skin joint");
  b = good;
  b.doc["meshes"][0]["primitives"][0]["indices"] = 999;
  expect_vrm_error(b.bytes(), "accessors");
  b = good;
  b.buffer.resize(16);
  expect_vrm_error(b.bytes(), "buffers[0]");
  // Junk flips across the file: an Error or a result, never a crash.
  for (std::size_t at = 0; at < bytes.size(); at += 11) {
    std::string m = bytes;
    m[at] = static_cast<char>(m[at] ^ 0x33);
    try {
      read_vrm(m, "mutated");
    } catch (const Error&) {
    }
  }
}

TEST(Vrm, TestFileIsValidGltf) {
  // The VRM written for these tests is itself checked by the Khronos validator (VRMC_vrm is an
  // extension it does not know: reported as info/warning, not as an error).
  if (!std::filesystem::exists(gestura::test::source_dir() + "/tools/node_modules/gltf-validator"))
    GTEST_SKIP() << "tools/node_modules/gltf-validator missing (cd tools && npm install)";
  const std::string path =
      (std::filesystem::temp_directory_path() / ("gestura_vrm_" + std::to_string(getpid()) + ".vrm")).string();
  {
    const std::string bytes = build_vrm().bytes();
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const gestura::test::CliRun r =
      gestura::test::run_command("node '" + gestura::test::source_dir() + "/tools/validate-gltf.mjs' '" + path + "'");
  std::filesystem::remove(path);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("\"numErrors\": 0"), std::string::npos) << r.output;
}

}  // namespace
