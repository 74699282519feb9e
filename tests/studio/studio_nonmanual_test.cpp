// The notation editor's non-manual tiers: a draft's tiers become a SiGML row (and a row without
// them stays HamNoSys), a SiGML row opens with its tiers, setting a tier is one undo step whose
// save and undo change the row, a value SiGML cannot hold is refused, and the preview performs
// the tiers (raised brows move the brow channels, a nod the head).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/studio/learning.hpp"
#include "gestura/studio/sign_preview.hpp"
#include "gestura/studio/studio_model.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/signing_avatar.hpp"

namespace gestura::studio {
namespace {

using gestura::testing::TempDir;
using sign::NonManualTier;

SignDraft brows_draft() {
  SignDraft d;
  d.gloss = "TESTNM";
  d.language = "ase";
  d.names = "hamflathand,hamextfingeru,hampalml,hamchest";
  d.keywords = "question";
  d.nonmanuals = {{NonManualTier::head, "NO"}, {NonManualTier::eyebrows, "RB"}, {NonManualTier::mouth_picture, "hUs"}};
  return d;
}

std::optional<SignEntry> row_in(const std::string& db, const std::string& gloss) {
  Lexicon lex = Lexicon::open(db);
  return lex.find(gloss, "ase", 1);
}

TEST(StudioNonManual, ADraftWithTiersIsASigmlRowThatReadsBackWithTheSameTiers) {
  const SignEntry e = to_entry(brows_draft());
  ASSERT_EQ(NotationKind::sigml, e.notation_kind);
  EXPECT_NE(std::string::npos, e.notation.find("<hnm_eyebrows tag=\"RB\""));
  EXPECT_NE(std::string::npos, e.notation.find("<hnm_mouthpicture picture=\"hUs\""));
  EXPECT_NE(std::string::npos, e.notation.find("<hamflathand"));
  // The synthesis' own SiGML reader sees the same sign.
  const auto signs = sign::read_sigml(e.notation);
  ASSERT_EQ(1u, signs.size());
  ASSERT_EQ(3u, signs[0].nonmanual.size());
  EXPECT_EQ(NonManualTier::head, signs[0].nonmanual[0].tier);
  EXPECT_EQ("NO", signs[0].nonmanual[0].value);
  EXPECT_EQ(4u, signs[0].symbols.size());

  const SignDraft back = draft_from_entry(e, false);
  EXPECT_EQ(brows_draft().names, back.names);
  EXPECT_EQ(brows_draft().nonmanuals, back.nonmanuals);

  SignDraft plain = brows_draft();
  plain.nonmanuals.clear();
  EXPECT_EQ(NotationKind::hamnosys, to_entry(plain).notation_kind);

  // The autosaved draft keeps them too.
  EXPECT_EQ(brows_draft(), draft_from_json(to_json(brows_draft())));
}

TEST(StudioNonManual, SettingATierIsOneUndoStepAndSaveAndUndoChangeTheRow) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model({}, db);
  SignDraft d = brows_draft();
  d.nonmanuals.clear();
  model.edit("type", d);
  ASSERT_TRUE(model.save()) << model.status();
  ASSERT_EQ(NotationKind::hamnosys, row_in(db, "TESTNM")->notation_kind);

  ASSERT_TRUE(model.set_nonmanual(NonManualTier::eyebrows, "FU")) << model.status();
  EXPECT_NE(std::string::npos, model.status().find("furrowed"));
  ASSERT_TRUE(model.set_nonmanual(NonManualTier::head, "SH"));
  // In the tiers' order, whatever order they were set in.
  ASSERT_EQ(2u, model.draft().nonmanuals.size());
  EXPECT_EQ(NonManualTier::head, model.draft().nonmanuals[0].tier);
  ASSERT_TRUE(model.save()) << model.status();
  auto row = row_in(db, "TESTNM");
  ASSERT_EQ(NotationKind::sigml, row->notation_kind);
  EXPECT_NE(std::string::npos, row->notation.find("<hnm_head tag=\"SH\""));

  ASSERT_TRUE(model.undo());  // the save: the HamNoSys row is back
  EXPECT_EQ(NotationKind::hamnosys, row_in(db, "TESTNM")->notation_kind);
  ASSERT_TRUE(model.undo());  // the head
  EXPECT_EQ(1u, model.draft().nonmanuals.size());
  ASSERT_TRUE(model.undo());  // the brows
  EXPECT_TRUE(model.draft().nonmanuals.empty());
  ASSERT_TRUE(model.redo());
  ASSERT_TRUE(model.redo());
  ASSERT_TRUE(model.redo());  // the save again
  EXPECT_EQ(NotationKind::sigml, row_in(db, "TESTNM")->notation_kind);

  // Clearing a tier, and a value SiGML cannot hold: refused, the draft unchanged.
  ASSERT_TRUE(model.set_nonmanual(NonManualTier::head, ""));
  EXPECT_EQ(1u, model.draft().nonmanuals.size());
  const SignDraft before = model.draft();
  EXPECT_FALSE(model.set_nonmanual(NonManualTier::mouth_picture, "a\"><x"));
  EXPECT_NE(std::string::npos, model.status().find("Mouth picture"));
  EXPECT_EQ(before, model.draft());
}

TEST(StudioNonManual, AnImportedSigmlSignOpensWithItsTiersAndAGesturalOneSaysWhyNot) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  {
    Lexicon lex = Lexicon::open(db);
    ImportOptions options;
    options.language = "ase";
    import_sigml_text(lex,
                      "<sigml><hns_sign gloss=\"nm_test\"><hamnosys_nonmanual><hnm_eyegaze tag=\"HI\"/>"
                      "<hnm_mouthpicture picture=\"tEst\"/></hamnosys_nonmanual><hamnosys_manual><hamfist/>"
                      "<hamextfingeru/><hampalml/><hamshoulders/></hamnosys_manual></hns_sign></sigml>",
                      "test.sigml", options);
  }
  StudioModel model({}, db);
  ASSERT_TRUE(model.open(EntryKey{"nm_test", "ase", 1})) << model.status();
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamshoulders", model.draft().names);
  ASSERT_EQ(2u, model.draft().nonmanuals.size());
  EXPECT_EQ(NonManualTier::eye_gaze, model.draft().nonmanuals[0].tier);
  EXPECT_EQ("tEst", model.draft().nonmanuals[1].value);

  SignEntry gestural;
  gestural.gloss = "G";
  gestural.notation_kind = NotationKind::sigml;
  gestural.notation = "<hamgestural_sign gloss=\"G\"><sign_manual><handconfig handshape=\"fist\"/></sign_manual></hamgestural_sign>";
  try {
    draft_from_entry(gestural, false);
    FAIL() << "a gestural sign opened as symbols";
  } catch (const Error& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find("gestural")) << e.what();
  }
}

TEST(StudioNonManual, ASigmlSignOfTheUserIsALessonWordWithItsTiers) {
  const SignEntry e = to_entry(brows_draft());
  const Topic topic = user_topic(std::span(&e, 1));
  ASSERT_EQ(1u, topic.words.size());
  EXPECT_EQ(brows_draft().names, topic.words[0].names);
  EXPECT_EQ(brows_draft().nonmanuals, topic.words[0].nonmanuals);
}

TEST(StudioNonManual, ThePreviewPerformsTheTiers) {
  const SigningRig& rig = test::signing_avatar().rig;
  SignDraft d = brows_draft();
  d.nonmanuals.clear();
  const SignPreview plain = preview_sign(d, rig);
  d.nonmanuals = {{NonManualTier::eyebrows, "RB"}};
  const SignPreview raised = preview_sign(d, rig);
  ASSERT_TRUE(plain.clip && raised.clip);
  auto peak = [](const SignPreview& p, const std::string& channel) {
    const int c = p.clip->find_channel(channel);
    float out = 0.0f;
    if (c < 0) return out;
    for (int k = 0; k <= 20; ++k)
      out = std::max(out, sample_track(p.clip->channels[static_cast<std::size_t>(c)],
                                       p.sign_start + (p.sign_end - p.sign_start) * k / 20.0f));
    return out;
  };
  EXPECT_GT(peak(raised, "browInnerUp_L"), peak(plain, "browInnerUp_L") + 0.3f);
  // An unknown code is a problem listed beside the preview, not an error.
  d.nonmanuals = {{NonManualTier::eyebrows, "ZZ"}};
  const SignPreview unknown = preview_sign(d, rig);
  ASSERT_TRUE(unknown.clip);
  EXPECT_FALSE(unknown.error);
  EXPECT_FALSE(unknown.problems.empty());
}

}  // namespace
}  // namespace gestura::studio
