// Our glTF exports in a real consumer: three.js's GLTFLoader and AnimationMixer, run in Node by
// tools/load-in-three.mjs. Skipped only when node or the three npm package is not installed
// (scripts/setup-deps.sh installs both).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "gestura/body/avatar.hpp"
#include "gestura/core/math.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "support/cli.hpp"
#include "support/build_paths.hpp"

using namespace gestura;
namespace fs = std::filesystem;

namespace {

using test::CliRun;
using test::run_command;

const std::string kTools = gestura::test::source_dir() + "/tools";

bool three_available() {
  return run_command("node --version").status == 0 && fs::exists(kTools + "/node_modules/three/package.json");
}

// Runs the loader on `file`; fails the test (and returns null) when it does not load.
nlohmann::json load_in_three(const fs::path& file) {
  const CliRun r = run_command("node " + kTools + "/load-in-three.mjs " + file.string());
  EXPECT_EQ(r.status, 0) << r.output;
  if (r.status != 0) return nullptr;
  return nlohmann::json::parse(r.output);
}

bool has(const nlohmann::json& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST(ThreeLoad, ExportedAvatarLoadsAsSkinnedMeshWithMorphs) {
  if (!three_available()) GTEST_SKIP() << "node or tools/node_modules/three missing (scripts/setup-deps.sh)";
  const fs::path file = fs::temp_directory_path() / "gestura_three_avatar.glb";
  const CliRun exported = test::run_cli("avatar export -o " + file.string());
  ASSERT_EQ(exported.status, 0) << exported.output;
  const nlohmann::json r = load_in_three(file);
  fs::remove(file);
  ASSERT_FALSE(r.is_null());
  EXPECT_GE(r["skinnedMeshes"].get<int>(), 1) << r.dump();
  EXPECT_GE(r["bones"].get<int>(), 60) << r.dump();
  EXPECT_TRUE(has(r["morphTargets"], "aa")) << r.dump();
  EXPECT_TRUE(has(r["morphTargets"], "eyeBlink_L")) << r.dump();
  EXPECT_TRUE(has(r["morphTargets"], "browInnerUp_L")) << r.dump();
  EXPECT_TRUE(r["animations"].empty());
}

TEST(ThreeLoad, ExportedAnimationPlaysInAnimationMixer) {
  if (!three_available()) GTEST_SKIP() << "node or tools/node_modules/three missing (scripts/setup-deps.sh)";
  const Avatar avatar = build_avatar();
  const Skeleton& s = avatar.skeleton;
  // Raise the left arm 90° about +Z over 2 s (slerp), and open the mouth ("aa") as a morph channel.
  Clip clip;
  clip.name = "raise_arm";
  clip.duration = 2.0f;
  clip.resize_joints(s.size());
  const auto shoulder = static_cast<std::size_t>(s.find("l_shoulder"));
  const quat rest = s.rest_rotations[shoulder];
  QuatTrack& arm = clip.rotations[shoulder];
  arm.interpolation = Interpolation::Slerp;
  arm.add(0.0f, rest);
  arm.add(2.0f, rest * glm::angleAxis(glm::radians(90.0f), vec3(0, 0, 1)));
  FloatTrack& mouth = clip.channel("aa");
  mouth.add(0.0f, 0.0f);
  mouth.add(2.0f, 1.0f);

  const fs::path file = fs::temp_directory_path() / "gestura_three_raise_arm.glb";
  save_gltf(file.string(), s, clip, &avatar.mesh);
  const nlohmann::json r = load_in_three(file);
  fs::remove(file);
  ASSERT_FALSE(r.is_null());
  EXPECT_GE(r["skinnedMeshes"].get<int>(), 1) << r.dump();
  ASSERT_EQ(r["animations"].size(), 1u) << r.dump();
  EXPECT_EQ(r["animations"][0]["name"], "raise_arm");
  EXPECT_NEAR(r["animations"][0]["duration"].get<double>(), 2.0, 1e-4);
  EXPECT_GE(r["animations"][0]["tracks"].get<int>(), 2) << r.dump();  // the arm rotation and the "aa" weight
  // Half-way through, the shoulder has turned 45° from its bind orientation (slerp is uniform in angle).
  const nlohmann::json& p = r["playback"];
  EXPECT_GE(p["bonesMoved"].get<int>(), 1) << r.dump();
  EXPECT_NEAR(p["maxAngle"].get<double>(), glm::radians(45.0), glm::radians(0.5)) << r.dump();
}
