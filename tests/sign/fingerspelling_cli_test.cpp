// The `gestura fingerspell` command end to end.
#include <gtest/gtest.h>

#include "support/cli.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace {

using gestura::test::CliRun;
using gestura::test::run_cli;

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
  EXPECT_EQ(flag.status, 1);
  EXPECT_NE(flag.output.find("--alphabet must be asl or bsl"), std::string::npos) << flag.output;
  const CliRun rate = run_cli("fingerspell --rate fast abc");
  EXPECT_EQ(rate.status, 1);
  EXPECT_NE(rate.output.find("--rate needs a positive number"), std::string::npos) << rate.output;
  EXPECT_EQ(run_cli("fingerspell").status, 1);
  EXPECT_EQ(run_cli("fingerspell --rate").status, 1);
}
