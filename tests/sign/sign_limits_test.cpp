// The caps on one sign's work: repetitions, actions once repetitions are unrolled, and signs that
// would repeat without end. Hostile notation is refused where it is read, with the symbol and the
// limit named; every real sign we have stays far below the caps.
#include "gestura/sign/sign_limits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_planner.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/sign/sigml.hpp"
#include "support/build_paths.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura;
using namespace gestura::sign;

constexpr const char* kFlatHandMovingOut = "hamflathand,hamextfingeru,hampalml,hamchest,hammoveo";

std::string repeated(const std::string& what, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += "," + what;
  return out;
}

Error parse_error(const std::string& names) {
  try {
    parse_hamnosys_names(names);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "parsed: " << names;
  return Error("");
}

TEST(SignLimits, TheIssuesAmplificationIsRefusedAtTheRepetitionPastTheCap) {
  // A flat hand moving out, then hamrepeatfromstart ×2,000: once a 30-minute sign.
  const Error e = parse_error(std::string(kFlatHandMovingOut) + repeated("hamrepeatfromstart", 2000));
  EXPECT_NE(std::string(e.what()).find("kMaxRepetitions"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().index, 5 + kMaxRepetitions);  // the 17th repetition symbol
  // Up to the cap the sign reads, and performs 2 actions per repetition (back, and again).
  const HamSign ok = parse_hamnosys_names(std::string(kFlatHandMovingOut) + repeated("hamrepeatfromstart", kMaxRepetitions));
  EXPECT_EQ(performed_actions(ok), 1 + 2 * kMaxRepetitions);
}

TEST(SignLimits, NestedRepetitionsCannotMultiplyPastTheCap) {
  // Each group repeats the group inside it 3 times (hamrepeatfromstartseveral = twice more, plus
  // one more): 4 levels of 3 repetitions, 12 symbols, would perform thousands of actions.
  std::string names = "hamflathand,hamextfingeru,hampalml,hamchest";
  std::string inner = "hammoveo";
  for (int level = 0; level < 4; ++level)
    inner = "hamseqbegin," + inner + ",hamrepeatfromstartseveral,hamrepeatfromstart,hamseqend";
  const Error e = parse_error(names + "," + inner);
  EXPECT_NE(std::string(e.what()).find("kMaxPerformedActions"), std::string::npos) << e.what();
  EXPECT_GE(e.where().index, 4);
}

TEST(SignLimits, ARepetitionCannotRepeatTheGroupItIsIn) {
  // The repetition opening the group would, when the group is repeated, repeat the group itself:
  // the planner would recurse until the stack ran out.
  const Error e = parse_error(
      "hamflathand,hamextfingeru,hampalml,hamchest,hamseqbegin,hamrepeatfromstart,hammoveo,hamseqend,"
      "hamrepeatfromstart");
  EXPECT_NE(std::string(e.what()).find("repeat the group it is written in"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().index, 5);
}

TEST(SignLimits, GesturalSigmlHasTheSameCaps) {
  std::string xml =
      "<sigml><hamgestural_sign gloss=\"many\"><sign_manual><handconfig handshape=\"flat\"/>"
      "<directedmotion direction=\"o\"/>";
  for (int i = 0; i < 40; ++i) xml += "<rpt_motion repetition=\"fromstart\"/>";
  xml += "</sign_manual></hamgestural_sign></sigml>";
  const std::vector<SigmlEntry> entries = read_sigml_entries(xml, "many.sigml");
  ASSERT_EQ(entries.size(), 1u);
  ASSERT_TRUE(entries[0].error.has_value());
  const std::string message = entries[0].error->what();
  EXPECT_NE(message.find("many.sigml:1"), std::string::npos) << message;
  EXPECT_TRUE(message.find("kMaxRepetitions") != std::string::npos ||
              message.find("kMaxPerformedActions") != std::string::npos)
      << message;
}

TEST(SignLimits, SignDurationCapNamesTheLimit) {
  EXPECT_NO_THROW(check_sign_duration(2.5f));
  try {
    check_sign_duration(1769.0f);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("kMaxSignSeconds"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_sign_duration(std::nanf("")), Error);
}

// Under the action caps a sign can still last long: nested repetitions of a movement, planned at the
// slowest tempo. The planner refuses it naming kMaxSignSeconds; at normal tempo it plans.
TEST(SignLimits, ThePlannerRefusesASignLongerThanTheDurationCap) {
  std::string inner = "hammoveo";
  for (int level = 0; level < 3; ++level)
    inner = "hamseqbegin," + inner + ",hamrepeatfromstartseveral,hamseqend";
  const HamSign sign = parse_hamnosys_names("hamflathand,hamextfingeru,hampalml,hamchest," + inner);
  ASSERT_LE(performed_actions(sign), kMaxPerformedActions);
  static const Avatar avatar = build_avatar();
  const SigningRig rig = make_signing_rig(avatar);
  const SignPlan normal = plan_sign(sign, rig);
  EXPECT_LT(normal.duration(), kMaxSignSeconds);
  PlanOptions slowest;
  slowest.speed = 0.25f;
  try {
    const SignPlan slow = plan_sign(sign, rig, slowest);
    ADD_FAILURE() << "a sign of " << slow.duration() << " s was planned (normal tempo: " << normal.duration() << " s)";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("kMaxSignSeconds"), std::string::npos) << e.what();
  }
}

// Real signs are far from the caps: the busiest uses under a tenth of them.
TEST(SignLimits, RealSignsStayFarBelowTheCaps) {
  int most_actions = 0, signs = 0;
  auto measure = [&](const HamSign& sign) {
    most_actions = std::max(most_actions, performed_actions(sign));
    ++signs;
  };
  std::ifstream lexicon(test::shared_data() + "/hamnosys/signs.jsonl");
  ASSERT_TRUE(lexicon);
  for (std::string line; std::getline(lexicon, line);) {
    try {
      measure(parse_hamnosys_unicode(nlohmann::json::parse(line).at("hamnosys").get<std::string>()));
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
  std::ifstream builtin(test::source_dir() + "/data/lexicon/ase.jsonl");
  for (std::string line; std::getline(builtin, line);) {
    const auto j = nlohmann::json::parse(line);
    const std::string names = j.value("names", "");
    if (!names.empty()) measure(parse_hamnosys_names(names));
  }
  for (const auto& file : std::filesystem::directory_iterator(test::shared_data() + "/sigml-isl")) {
    std::ifstream in(file.path());
    std::stringstream text;
    text << in.rdbuf();
    for (const SigmlEntry& e : read_sigml_entries(text.str(), file.path().filename().string()))
      if (e.sign) measure(e.sign->manual);
  }
  std::printf("%d signs, at most %d actions performed (cap %d)\n", signs, most_actions, kMaxPerformedActions);
  EXPECT_GT(signs, 4500);
  EXPECT_LT(most_actions, kMaxPerformedActions / 10);
}

}  // namespace
