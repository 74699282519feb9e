// `gestura scene` and `gestura view --scene` end to end: checking, performing and rendering a scene,
// and bad scenes, scripts and flags refused with located messages and no file written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/png_file.hpp"

namespace {

namespace fs = std::filesystem;
using gestura::test::run_cli;
using gestura::test::run_command;

std::string example() { return gestura::test::source_dir() + "/data/scenes/living_room.json"; }

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("gestura_scene_cli_" + std::to_string(::getpid()) + "_" + name); }

TEST(SceneCli, ChecksTheExampleScene) {
  const auto r = run_cli("scene " + example() + " --check");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 characters"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("script: 4 statements, 5 actions"), std::string::npos) << r.output;
}

TEST(SceneCli, RefusesBadScenesScriptsAndFlagsWithTheirPlace) {
  const fs::path bad = temp("bad.json");
  {
    std::ofstream out(bad);
    out << "{\n  \"objects\": [\n    {\"shape\": \"cube\"}\n  ]\n}\n";
  }
  const fs::path png = temp("never.png");
  auto r = run_cli("scene " + bad.string() + " -o " + png.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find(bad.string() + ":3:15"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("unknown shape 'cube'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(png));
  fs::remove(bad);

  r = run_cli("scene " + example() + " --check --do 'anna jumps to the chair'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--do:1:6: unknown verb 'jumps'"), std::string::npos) << r.output;
  r = run_cli("scene " + example() + " --check --do 'anna walks to the attic'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("'attic' is no place"), std::string::npos) << r.output;
  r = run_cli("scene " + example() + " --check --camera ceiling");
  EXPECT_EQ(r.status, 2) << "a camera the scene lacks is a bad command line";
  EXPECT_NE(r.output.find("unknown camera 'ceiling'"), std::string::npos) << r.output;
  r = run_cli("scene " + example() + " --wings");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--wings"), std::string::npos) << r.output;
  r = run_cli("scene /no/such/scene.json --check");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("no such file"), std::string::npos) << r.output;
}

TEST(SceneCli, ViewRefusesSceneFlagsThatDoNotGoTogetherBeforeOpeningAWindow) {
  auto r = run_cli("view --do 'anna walks to chair'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("need --scene"), std::string::npos) << r.output;
  r = run_cli("view --scene " + example() + " --rest");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--scene plays a scene"), std::string::npos) << r.output;
  r = run_cli("view --scene " + example() + " --camera ceiling");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("unknown camera 'ceiling'"), std::string::npos) << r.output;
  r = run_cli("view --scene /no/such/room.json");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--scene"), std::string::npos) << r.output;
}

TEST(SceneCli, JsonResultCarriesTheLog) {
  const auto r = run_cli("scene " + example() + " --do 'anna walks to the middle; ben walks to the attic' --json");
  EXPECT_EQ(r.status, 1) << "the attic is no place: a located error";
  const auto ok = run_cli("scene " + example() + " --do 'anna walks to the middle' --json");
  ASSERT_EQ(ok.status, 0) << ok.output;
  const std::size_t brace = ok.output.find('{');
  ASSERT_NE(brace, std::string::npos) << ok.output;
  const nlohmann::json j = nlohmann::json::parse(ok.output.substr(brace, ok.output.rfind('}') - brace + 1));
  EXPECT_EQ(j["warnings"], 0);
  ASSERT_FALSE(j["log"].empty());
  EXPECT_EQ(j["log"][0]["text"].get<std::string>().rfind("anna walks to middle", 0), 0u) << j.dump(2);
  EXPECT_GT(j["duration"].get<double>(), 1.0);
}

TEST(SceneCli, PerformsAScriptAndRendersAStill) {
  const fs::path png = temp("still.png");
  const auto r = run_cli("scene " + example() + " --do 'anna walks to the window; anna walks to the middle' --camera plan --size 320x240 -o " +
                         png.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("anna walks to window"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("wrote"), std::string::npos) << r.output;
  const gestura::test::PngPixels image = gestura::test::read_png(png.string(), 3);
  fs::remove(png);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 240);
}

TEST(SceneCli, ViewPlaysASceneUnderXvfb) {
  if (run_command("command -v xvfb-run").status != 0) GTEST_SKIP() << "xvfb-run not installed";
  const fs::path shot = temp("view.png");
  const auto r = run_command("timeout 120 xvfb-run -a " + gestura::test::cli_path() + " view --scene " + example() +
                             " --do 'anna walks to the middle' --camera plan --size 320x240 --frames 3 --screenshot " + shot.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const gestura::test::PngPixels image = gestura::test::read_png(shot.string(), 3);
  fs::remove(shot);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(image.width, 320);
  // The plan view: the floor's brown covers much of it.
  int floor = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) floor += image.at(x, y)[0] > image.at(x, y)[2] + 20;
  EXPECT_GT(floor, image.width * image.height / 4) << "no floor seen from above";
}

}  // namespace
