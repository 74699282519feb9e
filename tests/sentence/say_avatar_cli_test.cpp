// gestura say on either avatar: the MakeHuman body signs the same sentence through the same pipeline.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

std::string makehuman_dir() { return gestura::test::shared_data() + "/makehuman"; }

// Largest distance the joint `name` travels from its first-frame position in a joint-position JSON.
double travel(const nlohmann::json& motion, const std::string& name) {
  const auto& joints = motion.at("joints");
  std::size_t j = 0;
  while (j < joints.size() && joints[j] != name) ++j;
  EXPECT_LT(j, joints.size()) << name << " missing";
  if (j == joints.size()) return 0.0;
  const auto& first = motion.at("frames").at(0).at(j);
  double most = 0.0;
  for (const auto& frame : motion.at("frames")) {
    const double dx = frame[j][0].get<double>() - first[0].get<double>();
    const double dy = frame[j][1].get<double>() - first[1].get<double>();
    const double dz = frame[j][2].get<double>() - first[2].get<double>();
    most = std::max(most, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return most;
}

}  // namespace

TEST(SayAvatarCli, MakeHumanAvatarSignsTheSentenceWithItsRightHand) {
  if (!std::filesystem::exists(makehuman_dir() + "/base.obj")) GTEST_SKIP() << "no MakeHuman assets";
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "gestura_say_makehuman.json";
  const auto run = gestura::test::run_cli("say 'My name is Anna.' --avatar makehuman:" + makehuman_dir() + " -o " +
                                          out.string());
  ASSERT_EQ(run.status, 0) << run.output;
  std::ifstream in(out);
  const nlohmann::json motion = nlohmann::json::parse(in);
  EXPECT_GT(motion.at("frames").size(), 30u);
  EXPECT_GT(travel(motion, "r_wrist"), 0.15) << "the dominant hand should leave rest and sign";
  EXPECT_LT(travel(motion, "l_ankle"), 0.01) << "the feet stay put";
  std::filesystem::remove(out);
}

TEST(SayAvatarCli, UnknownAvatarIsNamedBeforeAnyWork) {
  const auto run = gestura::test::run_cli("say hello --avatar robot -o /tmp/gestura_say_robot.json");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("robot"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists("/tmp/gestura_say_robot.json"));
}

TEST(SayAvatarCli, BadOutputOrAvatarFlagsAreNamedAndWriteNothing) {
  const std::string txt = "/tmp/gestura_say_bad_output.txt";
  const auto wrong_kind = gestura::test::run_cli("say hello -o " + txt);
  EXPECT_EQ(wrong_kind.status, 2) << "a usage error";
  EXPECT_NE(wrong_kind.output.find(txt), std::string::npos) << wrong_kind.output;
  EXPECT_NE(wrong_kind.output.find(".mp4"), std::string::npos) << "lists what it can write: " << wrong_kind.output;
  EXPECT_FALSE(std::filesystem::exists(txt));
  const auto no_value = gestura::test::run_cli("say hello --avatar");
  EXPECT_EQ(no_value.status, 2) << "a usage error";
  EXPECT_NE(no_value.output.find("--avatar"), std::string::npos) << no_value.output;
  const std::string srt = "/tmp/gestura_say_avatar_cue.srt";
  std::ofstream(srt) << "1\n00:00:00,000 --> 00:00:02,000\nHello\n";
  const auto subtitles = gestura::test::run_cli("subtitles " + srt + " --avatar robot -o /tmp/gestura_say_robot.mp4");
  EXPECT_EQ(subtitles.status, 1);
  EXPECT_NE(subtitles.output.find("robot"), std::string::npos) << subtitles.output;
  EXPECT_FALSE(std::filesystem::exists("/tmp/gestura_say_robot.mp4"));
  std::filesystem::remove(srt);
}
