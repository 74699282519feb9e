// The `gestura fingerspell` command end to end: the printed letter timings, and with -o the
// performance written as joint positions like `gestura sign` writes them.
#include <gtest/gtest.h>

#include "support/cli.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using gestura::test::CliRun;
using gestura::test::run_cli;

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("gestura_fingerspell_" + std::to_string(::getpid()) + "_" + name);
}

struct Positions {
  nlohmann::json json;
  int joint(const std::string& name) const {
    const auto& joints = json.at("joints");
    for (std::size_t k = 0; k < joints.size(); ++k)
      if (joints[k] == name) return static_cast<int>(k);
    return -1;
  }
  // Largest distance a joint gets from where it is in the first frame.
  double travel(const std::string& name) const {
    const int j = joint(name);
    const auto& frames = json.at("frames");
    const auto& p0 = frames.front().at(static_cast<std::size_t>(j));
    double far = 0.0;
    for (const auto& f : frames) {
      const auto& p = f.at(static_cast<std::size_t>(j));
      far = std::max(far, std::hypot(p[0].get<double>() - p0[0].get<double>(), p[1].get<double>() - p0[1].get<double>(),
                                     p[2].get<double>() - p0[2].get<double>()));
    }
    return far;
  }
};

// Runs `fingerspell ARGS -o FILE.json`; returns the parsed file and the clip duration printed.
Positions spell_to_json(const std::string& args, double* duration) {
  const fs::path out = temp_file("out.json");
  const CliRun r = run_cli("fingerspell " + args + " -o " + out.string());
  EXPECT_EQ(r.status, 0) << r.output;
  const auto s = r.output.find(" letters, ");
  EXPECT_NE(s, std::string::npos) << r.output;
  if (s != std::string::npos) *duration = std::stod(r.output.substr(s + 10));
  std::ifstream in(out);
  Positions p{nlohmann::json::parse(in, nullptr, false)};
  fs::remove(out);
  return p;
}

}  // namespace

TEST(FingerspellingCli, PrintsOneTimedLinePerLetter) {
  const CliRun r = run_cli("fingerspell --alphabet asl hello");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ASL, 6.00 letters/s, 5 letters"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("slide"), std::string::npos) << r.output;  // the second L
  const CliRun b = run_cli("fingerspell --alphabet bsl --careful book");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_NE(b.output.find("BSL, 3.50 letters/s, 4 letters"), std::string::npos) << b.output;
  EXPECT_NE(b.output.find("ring tip"), std::string::npos) << b.output;  // O
}

TEST(FingerspellingCli, RejectsBadInputWithOneClearLine) {
  const CliRun digit = run_cli("fingerspell --alphabet bsl ab3");
  EXPECT_EQ(digit.status, 1);
  EXPECT_NE(digit.output.find("symbol 2: cannot fingerspell '3' in BSL"), std::string::npos) << digit.output;
  const CliRun flag = run_cli("fingerspell --alphabet xsl abc");
  EXPECT_EQ(flag.status, 2);
  EXPECT_NE(flag.output.find("--alphabet: 'xsl' is not asl or bsl"), std::string::npos) << flag.output;
  const CliRun rate = run_cli("fingerspell --rate fast abc");
  EXPECT_EQ(rate.status, 2);
  EXPECT_NE(rate.output.find("--rate: 'fast' is not a number"), std::string::npos) << rate.output;
  EXPECT_EQ(run_cli("fingerspell").status, 2);
  EXPECT_EQ(run_cli("fingerspell --rate").status, 2);
}

TEST(FingerspellingCli, WritesJointPositionsOfThePerformance) {
  double duration = 0.0;
  const Positions p = spell_to_json("JAZZ", &duration);
  ASSERT_FALSE(p.json.is_discarded());
  EXPECT_EQ(p.json.at("fps"), 30);
  for (const char* name : {"l_shoulder", "r_elbow", "r_wrist", "r_pinky3", "r_pinky_tip", "l_thumb_tip", "skullbase"})
    EXPECT_GE(p.joint(name), 0) << name;
  // Four letters (J and Z take two slots, the last one held: 1.27 s from the J's shape) between an
  // approach from rest and a return, each timed like a sign's (about 1 s): 2.5–3.5 s, one frame per
  // 1/30 s of it.
  EXPECT_GT(duration, 2.5);
  EXPECT_LT(duration, 3.5);
  const auto& frames = p.json.at("frames");
  EXPECT_NEAR(static_cast<double>(frames.size()), duration * 30.0 + 1.0, 1.01);
  for (const auto& f : frames) ASSERT_EQ(f.size(), p.json.at("joints").size());
  EXPECT_GT(p.travel("r_pinky_tip"), 0.3);  // up from rest to the spelling place
  EXPECT_LT(p.travel("l_wrist"), 0.01);     // ASL is one-handed
}

TEST(FingerspellingCli, BslMovesBothHands) {
  double duration = 0.0;
  const Positions p = spell_to_json("--alphabet bsl --careful hello", &duration);
  ASSERT_FALSE(p.json.is_discarded());
  EXPECT_GT(p.travel("r_wrist"), 0.2);
  EXPECT_GT(p.travel("l_wrist"), 0.2);
  // --speed 2 halves the time.
  double fast = 0.0;
  spell_to_json("--alphabet bsl --careful --speed 2 hello", &fast);
  EXPECT_NEAR(fast, 0.5 * duration, 0.05);
}

TEST(FingerspellingCli, RejectsBadOutputAndInput) {
  const fs::path junk = temp_file("junk.txt");
  const CliRun ext = run_cli("fingerspell abc -o " + junk.string());
  EXPECT_EQ(ext.status, 2);
  EXPECT_NE(ext.output.find("cannot write this kind of file"), std::string::npos) << ext.output;
  EXPECT_FALSE(fs::exists(junk));
  const CliRun sheet = run_cli("fingerspell abc --sheet -o " + temp_file("a.json").string());
  EXPECT_EQ(sheet.status, 2);
  EXPECT_NE(sheet.output.find("--sheet: needs a .png"), std::string::npos) << sheet.output;
  const CliRun speed = run_cli("fingerspell --speed 0 abc");
  EXPECT_EQ(speed.status, 2);
  EXPECT_NE(speed.output.find("--speed: 0 is outside 0.25..4"), std::string::npos) << speed.output;
  EXPECT_NE(run_cli("fingerspell --speed 9 abc").output.find("0.25..4"), std::string::npos);
  const CliRun empty = run_cli("fingerspell '  ' -o " + temp_file("e.json").string());
  EXPECT_EQ(empty.status, 2);
  EXPECT_NE(empty.output.find("nothing to spell"), std::string::npos) << empty.output;
  const CliRun binary = run_cli("fingerspell \"$(printf 'ab\\377\\001')\" -o " + temp_file("b.json").string());
  EXPECT_EQ(binary.status, 1);
  EXPECT_NE(binary.output.find("symbol 2: cannot fingerspell byte 0xFF"), std::string::npos) << binary.output;
  const CliRun fps = run_cli("fingerspell abc --fps 0 -o " + temp_file("f.json").string());
  EXPECT_EQ(fps.status, 2);
}
