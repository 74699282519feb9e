#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

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
