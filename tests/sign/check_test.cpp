// `gestura check` and the library behind it: counts, one line per failing sign, robustness to bad
// lines, and the synthesis step (S is counted only when the caller passes one).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "gestura/sign/sign_check.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura::sign;

using gestura::test::CliRun;
using gestura::test::run_cli;

std::string temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / ("gestura_check_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

TEST(SignCheck, WholeLexiconFromTheCli) {
  const CliRun r = run_cli("check --parse-only " + gestura::test::shared_data() + "/hamnosys/signs.jsonl");
  EXPECT_NE(r.output.find("4070 signs: 4070 parsed, 0 synthesized, 0 failed"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 0);
}

TEST(SignCheck, SigmlSignIsSynthesizedFromTheCli) {
  const CliRun r = run_cli("check " + gestura::test::shared_data() + "/sigml-isl/cup.sigml");
  EXPECT_NE(r.output.find("1 signs: 1 parsed, 1 synthesized, 0 failed"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 0);
}

TEST(SignCheck, AHandThatMissesItsPlannedPostureIsReported) {
  // ISL ABSORB asks for a hand turn the arm cannot make at its place: the IK residual check says so.
  const CliRun r = run_cli("check " + gestura::test::shared_data() + "/sigml-isl/absorb.sigml");
  EXPECT_NE(r.output.find("absorb: synthesis failed: IK: hand"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 signs: 1 parsed, 0 synthesized, 1 failed"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 1);
}

TEST(SignCheck, BadLinesAreReportedAndTheRestChecked) {
  const std::string path = temp_file("bad.jsonl",
                                     "{\"gloss\":\"A\",\"hamnosys\":\"\xee\x80\x81\xee\x80\xa0\"}\n"
                                     "not json at all\n"
                                     "{\"gloss\":\"B\"}\n"
                                     "\n"
                                     "{\"gloss\":\"C\",\"names\":\"hamflathand,hamparend\"}\n"
                                     "\x01\x02\xff\n");
  const CliRun r = run_cli("check " + path);
  EXPECT_NE(r.output.find("bad.jsonl:2: not a JSON object"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.jsonl:3: B: no `hamnosys`"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.jsonl:5: C: symbol 1: hamparend without a matching opening bracket: expected hamparbegin"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("5 signs: 1 parsed, 1 synthesized, 4 failed"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 1);
}

TEST(SignCheck, MalformedSigmlAndBadArgumentsFailCleanly) {
  const std::string path = temp_file("broken.sigml", "<sigml>\n<hns_sign gloss=\"x\">\n<hamnosys_manual>\n");
  CliRun r = run_cli("check " + path);
  EXPECT_NE(r.output.find("broken.sigml:3:"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 1);
  r = run_cli("check");
  EXPECT_NE(r.output.find("FILE: missing"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 2) << "a usage error";
  r = run_cli("check --bogus x.sigml");
  EXPECT_NE(r.output.find("--bogus"), std::string::npos) << r.output;
  EXPECT_EQ(r.status, 2);
  r = run_cli("check " + temp_file("x.txt", "hello"));
  EXPECT_NE(r.output.find("expected .jsonl or .sigml"), std::string::npos);
}

TEST(SignCheck, SynthesisStepCountsWhenGiven) {
  const std::string text =
      "{\"gloss\":\"one\",\"names\":\"hamflathand,hamextfingeru,hampalml\"}\n"
      "{\"gloss\":\"two\",\"names\":\"hamsymmlr,hamfist,hamextfingero,hampalmd\"}\n";
  CheckReport r = check_jsonl(text, "t.jsonl");
  EXPECT_FALSE(r.synthesis_connected);
  EXPECT_EQ(r.synthesized, 0);
  // A stand-in synthesizer that handles only one-handed signs.
  CheckOptions options;
  options.synthesize = [](const HamSign& s, std::span<const NonManual>) -> std::optional<std::string> {
    if (s.main().symmetry.kind != SymmetryKind::none) return "two-handed signs not supported";
    return std::nullopt;
  };
  r = check_jsonl(text, "t.jsonl", options);
  EXPECT_TRUE(r.synthesis_connected);
  EXPECT_EQ(r.signs, 2);
  EXPECT_EQ(r.parsed, 2);
  EXPECT_EQ(r.synthesized, 1);
  EXPECT_EQ(r.failed, 1);
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0], "t.jsonl:2: two: synthesis failed: two-handed signs not supported");
}

}  // namespace
