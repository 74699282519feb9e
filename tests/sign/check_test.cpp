// `gestura check` and the library behind it: counts, one line per failing sign, robustness to bad
// lines, and the synthesis step (S is counted only when the caller passes one).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

#include "gestura/sign/sign_check.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "support/signing_avatar.hpp"
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
  // ISL HILL asks for a hand turn the arm does not make at its place: the IK residual check says so.
  // (ABSORB did too until the wrist's ulnar range and the elbow's flexion were corrected.)
  const CliRun r = run_cli("check " + gestura::test::shared_data() + "/sigml-isl/hill.sigml");
  EXPECT_NE(r.output.find("hill: synthesis failed: IK: hand"), std::string::npos) << r.output;
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

TEST(SignCheck, AClipSignIsListedNotFailed) {
  // A clip sign exported from a user lexicon (the studio's timeline made it): no notation to check.
  const std::string text =
      "{\"gloss\":\"one\",\"names\":\"hamflathand,hamextfingeru,hampalml\"}\n"
      "{\"gloss\":\"WAVE\",\"clip_base64\":\"R0NMAAEAAAA=\"}\n"
      "{\"gloss\":\"bad\"}\n";
  const CheckReport r = check_jsonl(text, "t.jsonl");
  EXPECT_EQ(r.signs, 3);
  EXPECT_EQ(r.parsed, 1);
  EXPECT_EQ(r.clips, 1);
  EXPECT_EQ(r.failed, 1);  // the line without any notation
  bool listed = false;
  for (const std::string& n : r.notes) listed = listed || n.find("t.jsonl:2: WAVE: clip sign") != std::string::npos;
  EXPECT_TRUE(listed);
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

// `check` synthesizes on every core (GESTURA_THREADS sets how many); the report must be the serial
// one: counts, failures in file order, notes, and where max_failures stops.
CheckReport check_with_threads(const std::string& text, const CheckOptions& options, const char* threads) {
  setenv("GESTURA_THREADS", threads, 1);
  CheckReport r = check_jsonl(text, "t.jsonl", options);
  unsetenv("GESTURA_THREADS");
  return r;
}

void expect_same_report(const CheckReport& a, const CheckReport& b) {
  EXPECT_EQ(a.signs, b.signs);
  EXPECT_EQ(a.parsed, b.parsed);
  EXPECT_EQ(a.synthesized, b.synthesized);
  EXPECT_EQ(a.failed, b.failed);
  EXPECT_EQ(a.failures, b.failures);
  EXPECT_EQ(a.notes, b.notes);
  EXPECT_EQ(a.stopped, b.stopped);
}

TEST(SignCheck, EveryCoreGivesTheSerialReport) {
  // A stand-in step that fails two-handed signs and takes longer on them (so threads finish out of
  // order); every 17th line is not a sign at all.
  const char* notations[] = {"hamflathand,hamextfingeru,hampalml", "hamsymmlr,hamfist,hamextfingero,hampalmd",
                             "hamfist,hamextfingeru,hampalml"};
  std::string text;
  for (int i = 0; i < 200; ++i)
    text += i % 17 == 5 ? std::string("not json\n")
                        : "{\"gloss\":\"S" + std::to_string(i) + "\",\"names\":\"" + notations[i % 3] + "\"}\n";
  CheckOptions options;
  options.synthesize = [](const HamSign& s, std::span<const NonManual>) -> std::optional<std::string> {
    if (s.main().symmetry.kind == SymmetryKind::none) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    return "two-handed";
  };
  const CheckReport serial = check_with_threads(text, options, "1");
  const CheckReport parallel = check_with_threads(text, options, "4");
  EXPECT_EQ(serial.signs, 200);
  EXPECT_GT(serial.failed, 60);
  expect_same_report(serial, parallel);
  options.max_failures = 25;
  const CheckReport serial_stop = check_with_threads(text, options, "1");
  const CheckReport parallel_stop = check_with_threads(text, options, "4");
  EXPECT_TRUE(serial_stop.stopped);
  EXPECT_EQ(serial_stop.failed, 25);
  expect_same_report(serial_stop, parallel_stop);
}

TEST(SignCheck, RealSynthesisOnEveryCoreMatchesSerial) {
  // The first 24 signs of the shared DGS/PJM lexicon on the default avatar's rig, with real failures among them.
  std::ifstream in(gestura::test::shared_data() + "/hamnosys/signs.jsonl");
  std::string text, line;
  for (int i = 0; i < 24 && std::getline(in, line); ++i) text += line + "\n";
  ASSERT_FALSE(text.empty());
  CheckOptions options;
  options.synthesize = gestura::sign::SynthesisCheck(gestura::synthesis_check(gestura::test::signing_avatar().rig));
  const CheckReport serial = check_with_threads(text, options, "1");
  const CheckReport parallel = check_with_threads(text, options, "2");
  EXPECT_EQ(serial.signs, 24);
  EXPECT_GT(serial.synthesized, 0);
  expect_same_report(serial, parallel);
}

}  // namespace
