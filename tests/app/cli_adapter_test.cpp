// The command line as a thin adapter over the command layer: CLI11 conventions (--x=y, --version),
// usage errors exit 2 naming the flag, and text from standard input or a file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/build_paths.hpp"
#include "support/cli.hpp"

namespace {

using gestura::test::CliRun;
using gestura::test::run_cli;
namespace fs = std::filesystem;

std::string temp_file(const std::string& name, const std::string& content) {
  const fs::path path = fs::temp_directory_path() / ("gestura_cli_adapter_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

TEST(CliAdapter, VersionAndHelp) {
  const CliRun version = run_cli("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.output.rfind("gestura ", 0), 0u) << version.output;
  const CliRun overview = run_cli("--help");
  EXPECT_EQ(overview.status, 0);
  EXPECT_NE(overview.output.find("say"), std::string::npos);
  const CliRun say = run_cli("say --help");
  EXPECT_EQ(say.status, 0);
  EXPECT_NE(say.output.find("gestura say"), std::string::npos) << say.output;
  EXPECT_NE(say.output.find("-o,--output OUT"), std::string::npos) << say.output;
  EXPECT_NE(say.output.find("--speed S"), std::string::npos) << say.output;
  EXPECT_NE(say.output.find("(0.25..2)"), std::string::npos) << "ranges come from the field table: " << say.output;
  EXPECT_NE(say.output.find("--no-mouthing"), std::string::npos) << say.output;
  EXPECT_NE(say.output.find("standard input"), std::string::npos) << say.output;
}

TEST(CliAdapter, UsageErrorsExitTwoNamingTheFlag) {
  struct Case {
    const char* args;
    const char* named;
  };
  for (const Case& c : {Case{"say --fps abc hello", "--fps: 'abc' is not a whole number"},
                        Case{"say --fps=500 hello", "--fps: 500 is outside 1..120"},
                        Case{"say --speed 3 hello", "--speed"},
                        Case{"say --bogus hello", "--bogus"},
                        Case{"say", "TEXT"},
                        Case{"say hello there", "there"},
                        Case{"say hello --size 10x10", "--size"},
                        Case{"say hello --sex robot", "--sex"},
                        Case{"sign -o x.json", "exactly one of --hamnosys, --names, --sigml"},
                        Case{"sign --names hamflathand -o x.txt", "--output: x.txt"},
                        Case{"nosuchcommand", "unknown command"}}) {
    const CliRun r = run_cli(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.named), std::string::npos) << c.args << "\n" << r.output;
  }
}

TEST(CliAdapter, FlagValuesMayBeJoinedWithEquals) {
  const std::string out = (fs::temp_directory_path() / "gestura_cli_equals.json").string();
  const CliRun r = run_cli("sign --names=hamflathand,hamextfingeru,hampalml,hamchest --speed=2 --fps=10 --output=" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out));
  std::ifstream in(out);
  EXPECT_EQ(nlohmann::json::parse(in).at("fps"), 10);
  fs::remove(out);
}

TEST(CliAdapter, SayReadsTextFromStandardInputOrAFile) {
  const CliRun piped = gestura::test::run_command("echo 'Where do you live?' | '" + gestura::test::cli_path() + "' say -");
  ASSERT_EQ(piped.status, 0) << piped.output;
  EXPECT_NE(piped.output.find("WHERE"), std::string::npos) << piped.output;
  const std::string file = temp_file("say.txt", "Where do you live?\n");
  const CliRun from_file = run_cli("say --file " + file);
  ASSERT_EQ(from_file.status, 0) << from_file.output;
  EXPECT_NE(from_file.output.find("LIVE"), std::string::npos) << from_file.output;
  const CliRun both = run_cli("say hello --file " + file);
  EXPECT_EQ(both.status, 2) << both.output;
  const CliRun missing = run_cli("say --file /nonexistent/words.txt");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("/nonexistent/words.txt: no such file"), std::string::npos) << missing.output;
  // A megabyte of text is read, then refused by say's own limit, by name, not cut short.
  const std::string big = temp_file("big.txt", std::string(1 << 20, 'a'));
  const CliRun too_long = run_cli("say --file " + big);
  EXPECT_EQ(too_long.status, 1);
  EXPECT_NE(too_long.output.find("1048576 bytes of text; say signs at most 16384"), std::string::npos) << too_long.output;
  fs::remove(file);
  fs::remove(big);
}

}  // namespace
