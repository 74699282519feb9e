// SiGML: real files read into the typed model, non-manual tiers, the gestural form, and malformed
// XML that must give gestura::Error naming the line.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/sigml.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura::sign;

std::string isl(const std::string& name) { return read_text_file(gestura::test::shared_data() + "/sigml-isl/" + name); }

int error_line(const std::string& xml) {
  try {
    read_sigml(xml, "test.sigml");
  } catch (const gestura::Error& e) {
    return e.where().line;
  }
  return -1;
}

// australia.sigml, checked by hand: flat hand up, palm up-left, beside the forehead, close; the
// mouth picture is the spoken word in SAMPA.
TEST(Sigml, AustraliaManualAndMouthPicture) {
  const std::vector<SigmlSign> signs = read_sigml(isl("australia.sigml"), "australia.sigml");
  ASSERT_EQ(signs.size(), 1u);
  const SigmlSign& s = signs[0];
  EXPECT_EQ(s.gloss, "Australia");
  EXPECT_EQ(s.line, 3);
  ASSERT_EQ(s.nonmanual.size(), 1u);
  EXPECT_EQ(s.nonmanual[0].tier, NonManualTier::mouth_picture);
  EXPECT_EQ(s.nonmanual[0].value, "O:stre_IljV");
  EXPECT_EQ(s.nonmanual[0].line, 5);
  EXPECT_EQ(s.symbols.front(), Symbol::flathand);
  EXPECT_EQ(s.symbol_lines.front(), 8);
  const Posture& p = s.manual.main().posture;
  EXPECT_EQ(p.handshape.dominant->form.basic, BasicHandshape::Flat);
  EXPECT_EQ(p.orientation.dominant->extended_finger, Direction::U);
  EXPECT_EQ(p.orientation.dominant->palm, Direction::UL);
  EXPECT_EQ(p.location.dominant->site, Site::forehead);
  EXPECT_EQ(p.location.dominant->side, Side::beside);
  EXPECT_EQ(p.location.dominant->proximity, Proximity::close);
  const Motion& first = *s.manual.main().actions.at(0).motion();
  EXPECT_EQ(first.kind, MotionKind::replacement);
  EXPECT_EQ(first.new_orientation->extended_finger, Direction::IL);
  EXPECT_EQ(first.new_orientation->extended_finger_between, Direction::U);
  EXPECT_EQ(first.new_orientation->palm, Direction::D);
}

TEST(Sigml, GesturalTableSign) {
  const std::vector<SigmlSign> signs = read_sigml(isl("Table.AUS.sigml"), "Table.AUS.sigml");
  ASSERT_EQ(signs.size(), 1u);
  const SigmlSign& s = signs[0];
  EXPECT_TRUE(s.gestural);
  const ManualSign& m = s.manual.main();
  EXPECT_EQ(m.symmetry.kind, SymmetryKind::mirrored_lr);
  EXPECT_EQ(m.posture.handshape.dominant->form.basic, BasicHandshape::Flat);
  EXPECT_EQ(m.posture.handshape.dominant->form.thumb, ThumbModifier::Across);
  EXPECT_EQ(m.posture.orientation.dominant->extended_finger, Direction::O);
  EXPECT_EQ(m.posture.orientation.dominant->palm, Direction::D);
  EXPECT_EQ(m.posture.hands_contact, Proximity::touch);
  ASSERT_EQ(m.actions.size(), 3u);
  EXPECT_EQ(m.actions[0].motion()->direction, Direction::R);
  EXPECT_EQ(m.actions[1].motion()->kind, MotionKind::replacement);
  EXPECT_EQ(m.actions[1].motion()->new_orientation->palm, Direction::L);
  EXPECT_EQ(m.actions[2].motion()->direction, Direction::D);
}

TEST(Sigml, AllNonManualTiersTyped) {
  const std::string xml = R"(<sigml><hns_sign gloss="q">
<hamnosys_nonmanual>
  <hnm_shoulder tag="UB"/><hnm_body tag="RL"/><hnm_head tag="NO"/><hnm_eyegaze tag="AD"/>
  <hnm_eyebrows tag="RB"/><hnm_eyelids tag="WB"/><hnm_nose tag="WR"/><hnm_cheeks tag="PB"/>
  <hnm_mouthgesture tag="C01"/><hnm_mouthpicture picture="haUs"/>
</hamnosys_nonmanual>
<hamnosys_manual><hamfist/><hamextfingero/><hampalmd/></hamnosys_manual></hns_sign></sigml>)";
  const std::vector<SigmlSign> signs = read_sigml(xml);
  ASSERT_EQ(signs.at(0).nonmanual.size(), 10u);
  EXPECT_EQ(signs[0].nonmanual[2].tier, NonManualTier::head);
  EXPECT_EQ(signs[0].nonmanual[2].value, "NO");
  EXPECT_EQ(signs[0].nonmanual[4].tier, NonManualTier::eyebrows);
  EXPECT_EQ(signs[0].nonmanual[8].tier, NonManualTier::mouth_gesture);
  EXPECT_EQ(signs[0].nonmanual[8].value, "C01");
  EXPECT_EQ(signs[0].nonmanual[9].value, "haUs");
}

TEST(Sigml, GesturalNonManualTiersAreSequencesWithParallelGroups) {
  const std::string xml = R"(<sigml><hamgestural_sign gloss="g">
<sign_nonmanual>
  <head_tier><head_movement movement="NO"/><head_movement movement="SH"/></head_tier>
  <facialexpr_tier><facial_expr_par><eye_brows movement="RB"/><eye_lids movement="WB"/></facial_expr_par></facialexpr_tier>
  <eyegaze_tier><eye_gaze direction="HI"/></eyegaze_tier>
  <mouthing_tier><neutral/><mouth_picture picture="haUs"/></mouthing_tier>
</sign_nonmanual>
<sign_manual><handconfig handshape="fist"/><handconfig extfidir="o" palmor="d"/></sign_manual>
</hamgestural_sign></sigml>)";
  const std::vector<SigmlSign> signs = read_sigml(xml);
  const std::vector<NonManual>& nm = signs.at(0).nonmanual;
  ASSERT_EQ(nm.size(), 6u);
  EXPECT_EQ(nm[0].tier, NonManualTier::head);
  EXPECT_EQ(nm[0].value, "NO");
  EXPECT_EQ(nm[0].line, 3);
  EXPECT_FLOAT_EQ(nm[0].to, 0.5f);  // the first of two in its tier
  EXPECT_FLOAT_EQ(nm[1].from, 0.5f);
  EXPECT_FLOAT_EQ(nm[1].to, 1.0f);
  EXPECT_EQ(nm[2].tier, NonManualTier::eyebrows);  // a parallel group: both over the whole sign
  EXPECT_EQ(nm[3].tier, NonManualTier::eyelids);
  EXPECT_FLOAT_EQ(nm[3].from, 0.0f);
  EXPECT_FLOAT_EQ(nm[3].to, 1.0f);
  EXPECT_EQ(nm[4].tier, NonManualTier::eye_gaze);
  EXPECT_EQ(nm[4].value, "HI");
  EXPECT_EQ(nm[5].tier, NonManualTier::mouth_picture);  // after a neutral first half
  EXPECT_FLOAT_EQ(nm[5].from, 0.5f);
  // Unknown elements are errors that name their line.
  const std::string bad = R"(<sigml><hamgestural_sign gloss="g">
<sign_nonmanual><head_tier>
<wiggle movement="NO"/></head_tier></sign_nonmanual>
<sign_manual><handconfig handshape="fist"/></sign_manual></hamgestural_sign></sigml>)";
  const std::vector<SigmlEntry> entries = read_sigml_entries(bad, "bad.sigml");
  ASSERT_TRUE(entries.at(0).error.has_value());
  EXPECT_EQ(entries[0].error->where().line, 3);
}

TEST(Sigml, MalformedXmlNamesTheLine) {
  const std::string good = isl("absorb.sigml");
  // Truncated mid-document: the parser reports where it stopped.
  const std::string truncated = good.substr(0, good.size() / 2);
  EXPECT_GT(error_line(truncated), 0);
  EXPECT_EQ(error_line("<sigml>\n<hns_sign gloss=\"x\">\n<hamnosys_manual>\n<hamflathand>\n</hamnosys_manual>"), 5);
  EXPECT_EQ(error_line("<sigml>\n<hns_sign gloss=\"x\">\n<hamnosys_manual>\n<hamflathand/>\n<hamwobble/>\n</hamnosys_manual></hns_sign></sigml>"), 5);
  EXPECT_EQ(error_line("<html>\n</html>"), 1);
  EXPECT_EQ(error_line("<sigml>\n<hns_sign gloss=\"x\">\n<hamnosys_manual>\n<hamflathand/>\n<hamextfingeru/>\n<hamparend/>\n</hamnosys_manual></hns_sign></sigml>"), 6);
  EXPECT_GT(error_line(""), -1);
}

TEST(Sigml, OneBadSignKeepsItsOwnError) {
  const std::string xml =
      "<sigml>\n<hns_sign gloss=\"a\"><hamnosys_manual><hamfist/><hamextfingero/></hamnosys_manual></hns_sign>\n"
      "<hns_sign gloss=\"b\"><hamnosys_manual><hamreplace/></hamnosys_manual></hns_sign>\n</sigml>";
  const std::vector<SigmlEntry> entries = read_sigml_entries(xml, "two.sigml");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_TRUE(entries[0].sign);
  EXPECT_FALSE(entries[1].sign);
  EXPECT_EQ(entries[1].line, 3);
  EXPECT_EQ(entries[1].error->where().line, 3);
  EXPECT_EQ(entries[1].error->where().index, 1);  // end of input after hamreplace
}

TEST(Sigml, BinaryJunkAndMegabyteInputGiveErrors) {
  std::mt19937 rng(99);
  std::string junk(1u << 20, '\0');
  for (char& c : junk) c = static_cast<char>(rng());
  EXPECT_THROW(read_sigml_entries(junk, "junk.sigml"), gestura::Error);
  // 1 MB of well-formed XML whose one sign is far too long: rejected with a line, not parsed.
  std::string big = "<sigml><hns_sign gloss=\"big\"><hamnosys_manual>\n";
  while (big.size() < (1u << 20)) big += "<hamflathand/>\n";
  big += "</hamnosys_manual></hns_sign></sigml>";
  const auto entries = read_sigml_entries(big, "big.sigml");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_FALSE(entries[0].sign);
  EXPECT_GT(entries[0].error->where().line, 1);
}

// Seeded byte mutations of a real file: each either reads or throws gestura::Error with a line.
TEST(Sigml, FuzzedBytesNeverCrash) {
  const std::string good = isl("australia.sigml");
  std::mt19937 rng(5);
  int errors = 0;
  for (int i = 0; i < 2000; ++i) {
    std::string text = good;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits; ++k) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[at] = static_cast<char>(rng()); break;
        case 1: text.erase(at, 1 + rng() % 16); break;
        default: text.resize(at); break;
      }
      if (text.empty()) text.push_back('<');
    }
    try {
      for (const SigmlEntry& e : read_sigml_entries(text, "fuzz.sigml"))
        if (!e.sign) {
          ++errors;
          EXPECT_GT(e.error->where().line, 0) << e.error->what();
        }
    } catch (const gestura::Error& e) {
      ++errors;
      EXPECT_GT(e.where().line, 0) << e.what();
    }
  }
  EXPECT_GT(errors, 1000);
}

}  // namespace
