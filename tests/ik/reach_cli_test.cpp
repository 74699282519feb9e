// The `gestura reach` command end to end: solves, reports, writes a BVH, and rejects bad flags.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct CliRun {
  int status;
  std::string output;
};

CliRun run(const std::string& args) {
  const std::string command = std::string(GESTURA_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 512> buffer{};
  while (pipe && fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {WEXITSTATUS(status), out};
}

double residual_of(const std::string& output) {
  const auto at = output.find("residual ");
  return at == std::string::npos ? -1.0 : std::stod(output.substr(at + 9));
}

TEST(IkReachCli, EachSolverReachesAPointInFront) {
  for (const char* solver : {"dls", "ccd", "combined", "two-bone"}) {
    const CliRun r = run(std::string("reach --target 0.3,1.2,0.35 --solver ") + solver);
    ASSERT_EQ(r.status, 0) << r.output;
    const double residual = residual_of(r.output);
    EXPECT_GE(residual, 0.0) << r.output;
    EXPECT_LT(residual, 1e-4) << solver << "\n" << r.output;
    EXPECT_NE(r.output.find("iterations"), std::string::npos);
  }
}

TEST(IkReachCli, WritesAReadableBvh) {
  const std::string path = ::testing::TempDir() + "reach_test.bvh";
  const CliRun r = run("reach --target 0.25,1.0,0.3 --frames 10 -o " + path);
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().rfind("HIERARCHY", 0), 0u);
  EXPECT_NE(text.str().find("Frames: 11"), std::string::npos);
}

TEST(IkReachCli, UnreachableTargetReportsClosestReach) {
  const CliRun r = run("reach --target 3,1,1");
  ASSERT_EQ(r.status, 0) << r.output;
  // Shoulder at (0.18, 1.4, 0), arm 0.65 m long: the closest reach leaves |target − shoulder| − 0.65.
  EXPECT_NEAR(residual_of(r.output), 2.3687, 2e-3) << r.output;
  EXPECT_NE(r.output.find("closest reach"), std::string::npos);
}

TEST(IkReachCli, BadFlagsAreClearErrors) {
  for (const char* args : {"reach", "reach --target 1,2", "reach --target a,b,c", "reach --target 0,1,0 --solver fabrik",
                           "reach --target 0,1,0 --frames -3", "reach --target 0,1,0 --bogus"}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_NE(r.output.find("gestura reach: "), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
