// `gestura compress` end to end: writes a loadable .gcl within the bound, rejects bad input.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "gestura/compress/compressed_clip.hpp"

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

TEST(CompressCli, WritesAClipWithinTheBound) {
  const std::string path = ::testing::TempDir() + "cli.gcl";
  const CliRun r = run("compress synthetic:2 -o " + path + " --error-cm 0.05");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto at = r.output.find("error:       max ");
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_LE(std::stod(r.output.substr(at + 17)), 0.05);
  const gestura::CompressedClip c = gestura::load_gcl(path);
  EXPECT_EQ(c.joint_count(), 67u);
  EXPECT_EQ(c.frame_count(), 61u);
  std::remove(path.c_str());
}

TEST(CompressCli, BadInputIsAClearError) {
  for (const char* args : {"compress", "compress synthetic --error-cm 0", "compress synthetic --error-cm x",
                           "compress synthetic:-1", "compress synthetic --bogus", "compress a b", "compress synthetic -o"}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_NE(r.output.find("gestura compress: "), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
