// The mouth command, and what happens when eSpeak NG's data is missing (eSpeak is initialised once
// per process, so only a fresh process can show it).
#include <gtest/gtest.h>

#include <string>

#include "support/cli.hpp"

using gestura::test::CliRun;
using gestura::test::run_cli;

TEST(FaceMouthCli, PrintsPhonemesAndChannels) {
  const CliRun r = run_cli("mouth mom --start 1 --end 1.6");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("phonemes: m '0 m"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("PP           peak 1.00"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("jaw_open"), std::string::npos) << r.output;
}

TEST(FaceMouthCli, MissingEspeakDataIsAClearError) {
  const CliRun r = run_cli("mouth hello", "GESTURA_ESPEAK_DATA=/nonexistent/espeak");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("eSpeak NG data not found in '/nonexistent/espeak'"), std::string::npos) << r.output;
}

TEST(FaceMouthCli, BadFlagsAreRefused) {
  EXPECT_EQ(run_cli("mouth mom --end soon").status, 2);
  EXPECT_EQ(run_cli("mouth mom --start 2 --end 1").status, 2);
  EXPECT_EQ(run_cli("mouth").status, 2);
}
