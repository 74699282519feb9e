#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"
#include "support/shared_data.hpp"

using gestura::test::run_cli;

TEST(AvatarSitesCli, WritesTheSignLocationsOfTheAvatarAsJson) {
  const std::string path = (std::filesystem::temp_directory_path() / "gestura_sites_test.json").string();
  const gestura::test::CliRun run = run_cli("avatar sites -o " + path);
  ASSERT_EQ(run.status, 0) << run.output;
  std::ifstream file(path);
  const nlohmann::json j = nlohmann::json::parse(file);
  std::filesystem::remove(path);
  const auto& sites = j.at("sites");
  EXPECT_GE(sites.size(), 30u);
  auto y = [&](const char* name) { return sites.at(name).at("position").at(1).get<float>(); };
  auto x = [&](const char* name) { return sites.at(name).at("position").at(0).get<float>(); };
  EXPECT_GT(y("head_top"), y("forehead"));
  EXPECT_GT(y("forehead"), y("nose"));
  EXPECT_GT(y("nose"), y("chin"));
  EXPECT_GT(y("chin"), y("chest"));
  EXPECT_GT(y("chest"), y("belly"));
  EXPECT_GT(x("l_cheek"), 0.02f);  // the avatar's left is +X
  EXPECT_LT(x("r_cheek"), -0.02f);
  EXPECT_GT(y("forehead"), 1.5f);  // metres, feet on the floor, 1.70 m tall
  EXPECT_LT(y("forehead"), 1.75f);
  EXPECT_EQ(sites.at("nose").at("joint"), "skullbase");
  EXPECT_NE(run_cli("avatar sites -o /nonexistent-dir/x.json").status, 0);
}

TEST(AvatarSitesCli, ListsTheSitesOfTheAvatarItIsGiven) {
  // `--avatar makehuman:DIR` lists the MakeHuman body's sites (it once listed the default avatar's).
  const std::string dir = gestura::test::shared_data() + "/makehuman";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no MakeHuman assets at " << dir;
  const std::string ours = (std::filesystem::temp_directory_path() / "gestura_sites_default.json").string();
  const std::string theirs = (std::filesystem::temp_directory_path() / "gestura_sites_makehuman.json").string();
  ASSERT_EQ(run_cli("avatar sites -o " + ours).status, 0);
  const gestura::test::CliRun run = run_cli("avatar sites --avatar makehuman:" + dir + " -o " + theirs);
  ASSERT_EQ(run.status, 0) << run.output;
  std::ifstream a(ours), b(theirs);
  const nlohmann::json da = nlohmann::json::parse(a), db = nlohmann::json::parse(b);
  std::filesystem::remove(ours);
  std::filesystem::remove(theirs);
  const auto chin = [](const nlohmann::json& j) { return j.at("sites").at("chin").at("position"); };
  EXPECT_NE(chin(da), chin(db));
  EXPECT_GT(chin(db).at(1).get<float>(), 1.3f);  // a standing adult's chin
  EXPECT_GT(chin(db).at(2).get<float>(), 0.0f);  // in front: the body faces +Z
  // On both bodies (of different proportions) the chin's front, the jaw's underside just below
  // and behind it, facing down, and the throat below that. MakeHuman's under_chin was once found
  // at eye height, facing up, by a ray placed by the default head's proportions.
  for (const nlohmann::json* j : {&da, &db}) {
    const auto& sites = j->at("sites");
    auto at = [&](const char* n, int axis) { return sites.at(n).at("position").at(axis).get<float>(); };
    EXPECT_LT(at("under_chin", 1), at("chin", 1));
    EXPECT_GT(at("under_chin", 1), at("chin", 1) - 0.04f);
    EXPECT_LT(at("under_chin", 2), at("chin", 2) - 0.01f);
    EXPECT_LT(sites.at("under_chin").at("normal").at(1).get<float>(), -0.7f);
    EXPECT_LT(at("neck", 1), at("under_chin", 1) - 0.01f);
    EXPECT_LT(at("neck", 2), at("chin", 2) - 0.03f);
  }
}
