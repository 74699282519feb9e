#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/sign/phonology_handshape.hpp"
#include "support/shared_data.hpp"

using namespace gestura;

namespace {

using gestura::test::shared_data;

std::vector<BasicHandshape> all_basic() {
  std::vector<BasicHandshape> v;
  for (std::size_t k = 0; k < kBasicHandshapeCount; ++k) v.push_back(static_cast<BasicHandshape>(k));
  return v;
}
std::vector<AslHandshape> all_asl() {
  std::vector<AslHandshape> v;
  for (std::size_t k = 0; k < kAslHandshapeCount; ++k) v.push_back(static_cast<AslHandshape>(k));
  return v;
}

// Sum of absolute angle differences, plus a full radian for each differing contact/crossing flag.
float difference(const HandPosture& a, const HandPosture& b) {
  float d = std::abs(a.thumb.cmc_flexion - b.thumb.cmc_flexion) + std::abs(a.thumb.cmc_abduction - b.thumb.cmc_abduction) +
            std::abs(a.thumb.cmc_opposition - b.thumb.cmc_opposition) + std::abs(a.thumb.mcp - b.thumb.mcp) +
            std::abs(a.thumb.ip - b.thumb.ip);
  for (std::size_t f = 0; f < 4; ++f)
    d += std::abs(a.fingers[f].mcp - b.fingers[f].mcp) + std::abs(a.fingers[f].pip - b.fingers[f].pip) +
         std::abs(a.fingers[f].dip - b.fingers[f].dip) + std::abs(a.spread[f] - b.spread[f]);
  if (a.thumb_tip_contacts != b.thumb_tip_contacts) d += 1.0f;
  if (a.middle_crosses_index != b.middle_crosses_index) d += 1.0f;
  return d;
}

std::vector<std::string> codepoint_names() {
  std::ifstream in(shared_data() + "/hamnosys/codepoints.tsv");
  EXPECT_TRUE(in.good()) << "set GESTURA_SHARED_DATA to the shared data folder";
  std::vector<std::string> names;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) names.push_back(line.substr(0, line.find('\t')));
  return names;
}

}  // namespace

TEST(PhonologyHandshape, EveryTableEntryAndModifierCombinationIsWithinAnatomicalLimits) {
  const ThumbModifier thumbs[] = {ThumbModifier::Default, ThumbModifier::Out, ThumbModifier::Across, ThumbModifier::Opposed};
  const FingerBending bendings[] = {FingerBending::Bent,       FingerBending::Round,        FingerBending::Hooked,
                                    FingerBending::DoubleBent, FingerBending::DoubleHooked, FingerBending::HalfBent};
  for (BasicHandshape shape : all_basic()) {
    for (ThumbModifier t : thumbs) {
      EXPECT_EQ(anatomical_violation(make_handshape(shape, t)), "") << to_string(shape) << " " << to_string(t);
      for (FingerBending b : bendings)
        EXPECT_EQ(anatomical_violation(make_handshape(shape, t, b)), "") << to_string(shape) << " " << to_string(b);
    }
  }
  for (AslHandshape shape : all_asl()) EXPECT_EQ(anatomical_violation(asl_handshape(shape)), "") << to_string(shape);
}

TEST(PhonologyHandshape, LimitsAreTheStatedAnatomicalRanges) {
  EXPECT_NEAR(kFingerLimits.mcp.max, 90.0f * kPi / 180.0f, 1e-6f);
  EXPECT_NEAR(kFingerLimits.pip.max, 110.0f * kPi / 180.0f, 1e-6f);
  EXPECT_NEAR(kFingerLimits.dip.max, 80.0f * kPi / 180.0f, 1e-6f);
  EXPECT_EQ(kFingerLimits.mcp.min, 0.0f);
}

TEST(PhonologyHandshape, ViolationsAreReportedByJoint) {
  HandPosture h = basic_handshape(BasicHandshape::Flat);
  h.finger(Finger::Middle).pip = 2.5f;  // 143°
  EXPECT_NE(anatomical_violation(h).find("middle pip"), std::string::npos);
  h = basic_handshape(BasicHandshape::Flat);
  h.finger(Finger::Index).mcp = -0.3f;  // hyperextension beyond our range
  EXPECT_NE(anatomical_violation(h).find("index mcp"), std::string::npos);
  h = basic_handshape(BasicHandshape::Flat);
  h.thumb.ip = std::nanf("");
  EXPECT_NE(anatomical_violation(h).find("thumb ip"), std::string::npos);
}

TEST(PhonologyHandshape, FistAndFlatAreOpposites) {
  const HandPosture fist = basic_handshape(BasicHandshape::Fist), flat = basic_handshape(BasicHandshape::Flat);
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_GT(fist.fingers[f].mcp, deg(60));
    EXPECT_GT(fist.fingers[f].pip, deg(80));
    EXPECT_LT(flat.fingers[f].mcp, deg(5));
    EXPECT_LT(flat.fingers[f].pip, deg(5));
    EXPECT_LT(flat.fingers[f].dip, deg(5));
  }
}

TEST(PhonologyHandshape, DistinctShapesDiffer) {
  const auto basic = all_basic();
  for (std::size_t a = 0; a < basic.size(); ++a)
    for (std::size_t b = a + 1; b < basic.size(); ++b)
      EXPECT_GT(difference(basic_handshape(basic[a]), basic_handshape(basic[b])), deg(10))
          << to_string(basic[a]) << " vs " << to_string(basic[b]);
  const auto asl = all_asl();
  for (std::size_t a = 0; a < asl.size(); ++a)
    for (std::size_t b = a + 1; b < asl.size(); ++b)
      EXPECT_GT(difference(asl_handshape(asl[a]), asl_handshape(asl[b])), deg(10))
          << to_string(asl[a]) << " vs " << to_string(asl[b]);
}

TEST(PhonologyHandshape, SelectedFingersMatchTheFormsNames) {
  const HandPosture f2 = basic_handshape(BasicHandshape::Finger2);
  EXPECT_LT(f2.finger(Finger::Index).mcp, deg(5));
  EXPECT_GT(f2.finger(Finger::Middle).mcp, deg(60));
  const HandPosture f23s = basic_handshape(BasicHandshape::Finger23Spread), f23 = basic_handshape(BasicHandshape::Finger23);
  EXPECT_GT(f23s.spread[0] + f23s.spread[1], deg(20));  // V: ≥ 20° between index and middle
  EXPECT_NEAR(f23.spread[0] + f23.spread[1], 0.0f, 1e-6f);
  EXPECT_EQ(basic_handshape(BasicHandshape::Pinch12).thumb_tip_contacts, finger_bit(Finger::Index));
  EXPECT_EQ(basic_handshape(BasicHandshape::PinchAll).thumb_tip_contacts, kAllFourFingers);
  // The openings grow pinch < open pinch < cee < open cee: less index flexion each step.
  const float pinch = basic_handshape(BasicHandshape::Pinch12).finger(Finger::Index).pip;
  const float pinch_open = basic_handshape(BasicHandshape::Pinch12Open).finger(Finger::Index).pip;
  const float cee = basic_handshape(BasicHandshape::Cee12).finger(Finger::Index).pip;
  const float cee_open = basic_handshape(BasicHandshape::Cee12Open).finger(Finger::Index).pip;
  EXPECT_GT(pinch, pinch_open);
  EXPECT_GT(pinch_open, cee);
  EXPECT_GT(cee, cee_open);
}

TEST(PhonologyHandshape, ThumbModifiersMoveTheThumbWhereTheyNameIt) {
  const HandPosture out = make_handshape(BasicHandshape::Fist, ThumbModifier::Out);
  const HandPosture across = make_handshape(BasicHandshape::Fist, ThumbModifier::Across);
  const HandPosture opposed = make_handshape(BasicHandshape::Fist, ThumbModifier::Opposed);
  EXPECT_LT(out.thumb.cmc_flexion, deg(-20));                 // radial, away from the hand
  EXPECT_GT(across.thumb.cmc_flexion, deg(20));               // toward the little finger
  EXPECT_GT(opposed.thumb.cmc_abduction, across.thumb.cmc_abduction);  // lifted off the palm
  EXPECT_GT(opposed.thumb.cmc_opposition, deg(30));
  // Fingers untouched by a thumb modifier.
  EXPECT_EQ(out.finger(Finger::Index).mcp, basic_handshape(BasicHandshape::Fist).finger(Finger::Index).mcp);
  // A moved thumb gives up the pinch contact.
  EXPECT_EQ(make_handshape(BasicHandshape::Pinch12, ThumbModifier::Out).thumb_tip_contacts, 0);
}

TEST(PhonologyHandshape, BendingActsOnTheSelectedFingersOnly) {
  const HandPosture bent = make_handshape(BasicHandshape::Finger2, ThumbModifier::Default, FingerBending::Bent);
  EXPECT_NEAR(bent.finger(Finger::Index).mcp, deg(80), 1e-5f);
  EXPECT_LT(bent.finger(Finger::Index).pip, deg(10));
  EXPECT_EQ(bent.finger(Finger::Middle).mcp, basic_handshape(BasicHandshape::Finger2).finger(Finger::Middle).mcp);
  const HandPosture hooked = make_handshape(BasicHandshape::Flat, ThumbModifier::Default, FingerBending::Hooked);
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_LT(hooked.fingers[f].mcp, deg(5));
    EXPECT_GT(hooked.fingers[f].pip, deg(80));
  }
  HandPosture h = basic_handshape(BasicHandshape::Flat);
  apply_bending(h, finger_bit(Finger::Thumb) | finger_bit(Finger::Pinky), FingerBending::DoubleHooked);
  EXPECT_GT(h.finger(Finger::Pinky).pip, deg(100));
  EXPECT_EQ(h.finger(Finger::Ring).pip, 0.0f);
  EXPECT_EQ(h.thumb.ip, basic_handshape(BasicHandshape::Flat).thumb.ip);
  // Double-bent flexes MCP and PIP but not DIP much; round flexes all three moderately.
  const FingerFlexion db = bending_flexion(FingerBending::DoubleBent), round = bending_flexion(FingerBending::Round);
  EXPECT_GT(db.mcp, deg(45));
  EXPECT_GT(db.pip, deg(45));
  EXPECT_LT(db.dip, deg(30));
  EXPECT_GT(round.dip, deg(15));
  EXPECT_LT(round.mcp, deg(60));
}

TEST(PhonologyHandshape, AslShapesHaveTheirDefiningFeatures) {
  EXPECT_TRUE(asl_handshape(AslHandshape::R).middle_crosses_index);
  EXPECT_LT(asl_handshape(AslHandshape::L).thumb.cmc_flexion, 0.0f);            // thumb out
  EXPECT_GT(asl_handshape(AslHandshape::S).thumb.cmc_flexion, 0.0f);           // thumb across…
  EXPECT_GT(asl_handshape(AslHandshape::S).thumb.mcp, deg(30));                 // …bent over the fingers
  EXPECT_LT(asl_handshape(AslHandshape::A).thumb.cmc_flexion, 0.0f);            // thumb alongside
  EXPECT_EQ(asl_handshape(AslHandshape::Six).thumb_tip_contacts, finger_bit(Finger::Pinky));
  EXPECT_EQ(asl_handshape(AslHandshape::Seven).thumb_tip_contacts, finger_bit(Finger::Ring));
  EXPECT_EQ(asl_handshape(AslHandshape::Eight).thumb_tip_contacts, finger_bit(Finger::Middle));
  EXPECT_EQ(asl_handshape(AslHandshape::F).thumb_tip_contacts, finger_bit(Finger::Index));
  // Y: only the pinky straight among the fingers.
  const HandPosture y = asl_handshape(AslHandshape::Y);
  EXPECT_LT(y.finger(Finger::Pinky).mcp, deg(5));
  EXPECT_GT(y.finger(Finger::Index).mcp, deg(60));
  // O closes further than C.
  EXPECT_GT(asl_handshape(AslHandshape::O).finger(Finger::Index).pip, asl_handshape(AslHandshape::C).finger(Finger::Index).pip);
}

TEST(PhonologyHandshape, TheThumbIsNotAFingerFlexion) {
  HandPosture h;
  EXPECT_THROW(h.finger(Finger::Thumb), std::out_of_range);
}

TEST(PhonologyHandshape, MixInterpolatesComponentwise) {
  const HandPosture a = basic_handshape(BasicHandshape::Flat), b = basic_handshape(BasicHandshape::Fist);
  const HandPosture m = mix(a, b, 0.5f);
  EXPECT_NEAR(m.finger(Finger::Ring).pip, 0.5f * b.finger(Finger::Ring).pip, 1e-6f);
  EXPECT_NEAR(mix(a, b, 0.0f).finger(Finger::Index).mcp, 0.0f, 1e-6f);
  EXPECT_NEAR(mix(a, b, 1.0f).finger(Finger::Index).mcp, b.finger(Finger::Index).mcp, 1e-6f);
}

TEST(PhonologyHandshape, NamesRoundTripAndHamNoSysSymbolNamesParse) {
  for (BasicHandshape s : all_basic()) EXPECT_EQ(parse_basic_handshape(to_string(s)), s);
  for (AslHandshape s : all_asl()) EXPECT_EQ(parse_asl_handshape(to_string(s)), s);
  EXPECT_EQ(parse_basic_handshape("hamflathand"), BasicHandshape::Flat);
  EXPECT_EQ(parse_basic_handshape("hamceeopen"), BasicHandshape::Cee12Open);
  EXPECT_EQ(parse_thumb_modifier("hamthumbopenmod"), ThumbModifier::Opposed);
  EXPECT_EQ(parse_finger_bending("hamfingerhookmod"), FingerBending::Hooked);
  EXPECT_EQ(parse_finger_bending("hamfingerstraightmod"), FingerBending::Bent);  // the glyph is a base-bent finger
  EXPECT_EQ(parse_finger_bending("hamfingerbendmod"), FingerBending::Round);
  EXPECT_EQ(parse_finger_bending("dblhooked"), FingerBending::DoubleHooked);
  for (std::size_t k = 0; k < kFingerBendingCount; ++k) {
    const auto b = static_cast<FingerBending>(k);
    EXPECT_EQ(parse_finger_bending(to_string(b)), b);
  }
  EXPECT_EQ(parse_basic_handshape("hamfist2"), std::nullopt);
  EXPECT_EQ(parse_basic_handshape(""), std::nullopt);
  EXPECT_EQ(parse_thumb_modifier(""), std::nullopt);

  // Every handshape and handshape-modifier symbol of HamNoSys 4 (the shared codepoint table)
  // maps onto our enumerations.
  int handshapes = 0, modifiers = 0;
  for (const std::string& name : codepoint_names()) {
    const bool is_shape = name == "hamfist" || name == "hamflathand" || name.rfind("hamfinger2", 0) == 0 ||
                          name.rfind("hampinch", 0) == 0 || name.rfind("hamcee", 0) == 0;
    if (is_shape) {
      EXPECT_TRUE(parse_basic_handshape(name).has_value()) << name;
      ++handshapes;
    }
    if (name.rfind("hamthumb", 0) == 0 && name.find("mod") != std::string::npos) {
      EXPECT_TRUE(parse_thumb_modifier(name).has_value()) << name;
      ++modifiers;
    }
    if (name == "hamfingerstraightmod" || name == "hamfingerbendmod" || name == "hamfingerhookmod" ||
        name == "hamdoublebent" || name == "hamdoublehooked") {
      EXPECT_TRUE(parse_finger_bending(name).has_value()) << name;
      ++modifiers;
    }
  }
  EXPECT_EQ(handshapes, 12);
  EXPECT_EQ(modifiers, 8);
}
