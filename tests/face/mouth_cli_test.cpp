// The mouth command, and what happens when eSpeak NG's data is missing (eSpeak is initialised once
// per process, so only a fresh process can show it).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace {

struct CliRun {
  int status;
  std::string output;
};

CliRun run_cli(const std::string& env, const std::string& args) {
  const std::string command = env + " " + std::string(GESTURA_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 512> buffer{};
  while (pipe && fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {WEXITSTATUS(status), out};
}

}  // namespace

TEST(FaceMouthCli, PrintsPhonemesAndChannels) {
  const CliRun r = run_cli("", "mouth mom --start 1 --end 1.6");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("phonemes: m '0 m"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("PP           peak 1.00"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("jaw_open"), std::string::npos) << r.output;
}

TEST(FaceMouthCli, MissingEspeakDataIsAClearError) {
  const CliRun r = run_cli("GESTURA_ESPEAK_DATA=/nonexistent/espeak", "mouth hello");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("eSpeak NG data not found in '/nonexistent/espeak'"), std::string::npos) << r.output;
}

TEST(FaceMouthCli, BadFlagsAreRefused) {
  EXPECT_EQ(run_cli("", "mouth mom --end soon").status, 1);
  EXPECT_EQ(run_cli("", "mouth mom --start 2 --end 1").status, 1);
  EXPECT_EQ(run_cli("", "mouth").status, 1);
}
