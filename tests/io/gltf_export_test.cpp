#include "gestura/io/gltf_export.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gestura/body/avatar.hpp"
#include "gestura/core/error.hpp"
#include "support/cli.hpp"
#include "support/build_paths.hpp"

using namespace gestura;
namespace fs = std::filesystem;

namespace {

const Avatar& avatar() {
  static const Avatar a = build_avatar();
  return a;
}

std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

nlohmann::json json_chunk(const std::vector<std::uint8_t>& glb) {
  const std::uint32_t length = u32(glb, 12);
  return nlohmann::json::parse(std::string(reinterpret_cast<const char*>(glb.data()) + 20, length));
}

fs::path temp_file(const char* name) { return fs::temp_directory_path() / (std::string("gestura_") + name); }

}  // namespace

TEST(GltfExport, WritesAGlbWithSkinJointsMorphNamesAndMaterials) {
  const Avatar& a = avatar();
  const std::vector<std::uint8_t> glb = encode_glb(a.skeleton, a.mesh, "test");
  ASSERT_GT(glb.size(), 28u);
  EXPECT_EQ(u32(glb, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(u32(glb, 4), 2u);
  EXPECT_EQ(u32(glb, 8), glb.size());
  const nlohmann::json j = json_chunk(glb);
  EXPECT_EQ(j["asset"]["version"], "2.0");
  ASSERT_EQ(j["skins"].size(), 1u);
  EXPECT_EQ(j["skins"][0]["joints"].size(), a.skeleton.size());
  const int ibm = j["skins"][0]["inverseBindMatrices"];
  EXPECT_EQ(j["accessors"][ibm]["count"], a.skeleton.size());
  EXPECT_EQ(j["nodes"].size(), a.skeleton.size() + 1);
  EXPECT_EQ(j["nodes"][a.skeleton.find("l_wrist")]["name"], "l_wrist");
  const auto& names = j["meshes"][0]["extras"]["targetNames"];
  ASSERT_EQ(names.size(), a.mesh.morphs.size());
  EXPECT_NE(std::find(names.begin(), names.end(), "aa"), names.end());
  std::set<std::string> materials;
  for (const auto& m : j["materials"]) materials.insert(m["name"]);
  EXPECT_TRUE(materials.count("skin") && materials.count("cloth") && materials.count("hair"));
  std::size_t indices = 0;
  for (const auto& p : j["meshes"][0]["primitives"]) {
    EXPECT_EQ(p["targets"].size(), a.mesh.morphs.size());
    indices += j["accessors"][p["indices"].get<int>()]["count"].get<std::size_t>();
  }
  EXPECT_EQ(indices, a.mesh.indices.size());
}

TEST(GltfExport, RejectsInconsistentMeshesWithClearErrors) {
  const Avatar& a = avatar();
  Mesh m = a.mesh;
  m.indices.push_back(static_cast<std::uint32_t>(m.vertex_count()));
  m.indices.push_back(0);
  m.indices.push_back(1);
  EXPECT_THROW(encode_glb(a.skeleton, m), Error);
  m = a.mesh;
  m.joints[7][0] = static_cast<std::uint16_t>(a.skeleton.size());
  try {
    encode_glb(a.skeleton, m);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos) << e.what();
  }
  m = a.mesh;
  m.normals.pop_back();
  EXPECT_THROW(encode_glb(a.skeleton, m), Error);
  m = a.mesh;
  m.morphs[0].vertices.push_back(0);  // not increasing, and one more index than deltas
  EXPECT_THROW(encode_glb(a.skeleton, m), Error);
  EXPECT_THROW(write_glb("/nonexistent-dir/x.glb", a.skeleton, a.mesh), Error);
}

TEST(GltfExport, KhronosValidatorReportsNoErrors) {
  if (test::run_command("node --version").status != 0) GTEST_SKIP() << "node is not installed";
  const fs::path file = temp_file("avatar_validate.glb");
  write_glb(file.string(), avatar().skeleton, avatar().mesh);
  const std::string script = gestura::test::source_dir() + "/tools/validate-gltf.mjs";
  const test::CliRun r = test::run_command("node " + script + " " + file.string());
  fs::remove(file);
  EXPECT_EQ(r.status, 0) << r.output << "\n(run `cd tools && npm install` if gltf-validator is missing)";
  EXPECT_NE(r.output.find(": 0 errors"), std::string::npos) << r.output;
}

TEST(AvatarCli, InfoExportAndBadFlags) {
  using test::run_cli;
  test::CliRun r = run_cli("avatar info");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("joints 80"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("l_thumb_tip"), std::string::npos);
  EXPECT_NE(r.output.find(" eyeBlink_L"), std::string::npos);

  const fs::path file = temp_file("avatar_cli.glb");
  r = run_cli("avatar export -o " + file.string() + " --height 1.80 --sex male");
  EXPECT_EQ(r.status, 0) << r.output;
  std::ifstream in(file, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");
  fs::remove(file);

  r = run_cli("avatar export -o " + file.string() + " --height -3");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("height"), std::string::npos) << r.output;
  r = run_cli("avatar info --build fat");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("'fat' is not a number"), std::string::npos) << r.output;
  r = run_cli("avatar export");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("-o"), std::string::npos) << r.output;
  EXPECT_NE(run_cli("avatar info --height").status, 0);
  EXPECT_NE(run_cli("avatar dance").status, 0);
  EXPECT_FALSE(fs::exists(file));
}
