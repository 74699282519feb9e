// The studio's model without a window: drafts, symbol edits, save as a transaction, undo/redo of
// edits and of database writes, notation that does not parse never saved, recovery files, scripts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "gestura/core/error.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/studio/recovery.hpp"
#include "gestura/studio/script.hpp"
#include "gestura/studio/studio_model.hpp"
#include "lexicon/temp_dir.hpp"

namespace gestura::studio {
namespace {

using gestura::testing::TempDir;

std::optional<SignEntry> row_in(const std::string& db, const std::string& gloss, int variant = 1) {
  Lexicon lex = Lexicon::open(db);
  return lex.find(gloss, "ase", variant);
}

SignDraft house_draft() {
  SignDraft d;
  d.gloss = "TESTHOUSE";
  d.language = "ase";
  d.names = "hamflathand,hamextfingeru,hampalml,hamchest";
  d.keywords = "house, home";
  d.meaning = "a building people live in";
  d.source = "test";
  d.licence = "CC0-1.0";
  return d;
}

TEST(StudioModel, SavesADraftAsARowAndUndoRemovesIt) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model({}, db);
  ASSERT_TRUE(model.writable()) << model.status();
  model.edit("type", house_draft());
  ASSERT_TRUE(model.save()) << model.status();
  auto row = row_in(db, "TESTHOUSE");
  ASSERT_TRUE(row);
  EXPECT_EQ(to_entry(house_draft()).notation, row->notation);
  ASSERT_EQ(2u, row->keywords.size());
  EXPECT_EQ("house", row->keywords[0].word);
  EXPECT_EQ("a building people live in", row->keywords[0].meaning);
  EXPECT_FALSE(model.dirty());

  ASSERT_TRUE(model.undo());  // the save
  EXPECT_FALSE(row_in(db, "TESTHOUSE"));
  ASSERT_TRUE(model.redo());
  EXPECT_TRUE(row_in(db, "TESTHOUSE"));
}

TEST(StudioModel, ReplacingASymbolThenSavingChangesTheRowAndUndoRestoresBoth) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model({}, db);
  model.edit("type", house_draft());
  ASSERT_TRUE(model.save());
  const std::string before = row_in(db, "TESTHOUSE")->notation;

  ASSERT_TRUE(model.replace_symbol(0, "hamfist"));
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamchest", model.draft().names);
  EXPECT_TRUE(model.dirty());
  ASSERT_TRUE(model.save());
  const std::string after = row_in(db, "TESTHOUSE")->notation;
  EXPECT_NE(before, after);

  ASSERT_TRUE(model.undo());  // the save: the row is as before
  EXPECT_EQ(before, row_in(db, "TESTHOUSE")->notation);
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamchest", model.draft().names);
  ASSERT_TRUE(model.undo());  // the symbol
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", model.draft().names);
  ASSERT_TRUE(model.redo());
  ASSERT_TRUE(model.redo());
  EXPECT_EQ(after, row_in(db, "TESTHOUSE")->notation);
}

TEST(StudioModel, NotationThatDoesNotParseIsNeverSaved) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model({}, db);
  SignDraft d = house_draft();
  d.names = "hamflathand,hamparend,hamchest";  // a closing bracket without its opening one
  model.edit("type", d);
  const auto error = notation_error(model.draft());
  ASSERT_TRUE(error);
  EXPECT_EQ(1, error->symbol);
  EXPECT_FALSE(model.save());
  EXPECT_NE(std::string::npos, model.status().find("symbol 1")) << model.status();
  EXPECT_FALSE(row_in(db, "TESTHOUSE"));
  EXPECT_EQ(d, model.draft());  // the draft stays
  EXPECT_TRUE(model.dirty());

  d.names = "hamflathand,hamchest,hambogus";
  model.edit("type", d);
  ASSERT_TRUE(notation_error(model.draft()));
  EXPECT_EQ(2, notation_error(model.draft())->symbol);
}

TEST(StudioModel, RenamingReplacesTheOriginalRowInOneStepAndDeleteIsUndoable) {
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model({}, db);
  model.edit("type", house_draft());
  ASSERT_TRUE(model.save());
  SignDraft d = model.draft();
  d.gloss = "TESTHOME";
  model.edit("rename", d);
  ASSERT_TRUE(model.save());
  EXPECT_FALSE(row_in(db, "TESTHOUSE"));
  EXPECT_TRUE(row_in(db, "TESTHOME"));
  ASSERT_TRUE(model.remove());
  EXPECT_FALSE(row_in(db, "TESTHOME"));
  ASSERT_TRUE(model.undo());
  EXPECT_TRUE(row_in(db, "TESTHOME"));
  ASSERT_TRUE(model.undo());  // the rename's save
  EXPECT_TRUE(row_in(db, "TESTHOUSE"));
  EXPECT_FALSE(row_in(db, "TESTHOME"));
}

TEST(StudioModel, TypingInOneFieldIsOneUndoStepUntilSealed) {
  TempDir dir;
  StudioModel model({}, dir.file("user.sqlite"));
  SignDraft d = model.draft();
  for (const char* text : {"H", "HO", "HOU"}) {
    d.gloss = text;
    model.edit("edit gloss", d, "gloss");
  }
  model.seal();
  d.gloss = "HOUSE";
  model.edit("edit gloss", d, "gloss");
  ASSERT_TRUE(model.undo());
  EXPECT_EQ("HOU", model.draft().gloss);
  ASSERT_TRUE(model.undo());
  EXPECT_EQ("", model.draft().gloss);
  EXPECT_FALSE(model.undo());
}

TEST(StudioModel, BuiltInSignsOpenReadOnlyAndSaveIntoTheUserLexicon) {
  const auto files = builtin_lexicon_files();
  ASSERT_FALSE(files.empty());
  TempDir dir;
  const std::string db = dir.file("user.sqlite");
  StudioModel model(files, db);
  const auto rows = model.browse(BrowseFilter{.text = "house"});
  ASSERT_FALSE(rows.empty());
  EXPECT_TRUE(rows.front().builtin);
  ASSERT_TRUE(model.open(key_of(rows.front().entry))) << model.status();
  EXPECT_TRUE(model.draft().from_builtin);
  EXPECT_FALSE(model.remove());  // built-in rows cannot be deleted
  ASSERT_TRUE(model.save()) << model.status();
  EXPECT_TRUE(row_in(db, rows.front().entry.gloss, rows.front().entry.variant));
  const auto again = model.find(key_of(rows.front().entry));
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->builtin);  // the user's copy now hides the built-in one

  const auto fists = model.browse(BrowseFilter{.handshape = "hamfist"});
  ASSERT_FALSE(fists.empty());
  for (const BrowseRow& r : fists) EXPECT_NE(std::string::npos, draft_from_entry(r.entry, true).names.find("hamfist"));
}

TEST(StudioModel, ACorruptUserLexiconLeavesTheStudioReadOnlyAndTheFileUntouched) {
  TempDir dir;
  const std::string db = dir.write("broken.sqlite", std::string("this is not a database, but it is mine\n"));
  StudioModel model({}, db);
  EXPECT_FALSE(model.writable());
  EXPECT_FALSE(model.user_error().empty());
  model.edit("type", house_draft());
  EXPECT_FALSE(model.save());
  std::ifstream in(db);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ("this is not a database, but it is mine\n", text);
}

TEST(StudioRecovery, ADraftWrittenIsReadBackAndABadFileIsAnErrorNamingIt) {
  TempDir dir;
  const std::string path = recovery_path(dir.file("user.sqlite"));
  EXPECT_FALSE(read_recovery(path));
  SignDraft d = house_draft();
  d.origin = EntryKey{"TESTHOUSE", "ase", 2};
  write_recovery(path, d);
  const auto back = read_recovery(path);
  ASSERT_TRUE(back);
  EXPECT_EQ(d, *back);
  discard_recovery(path);
  EXPECT_FALSE(read_recovery(path));

  std::ofstream(path) << "{\"draft\": {\"gloss\": 12}}";
  try {
    read_recovery(path);
    FAIL() << "a bad recovery file was read";
  } catch (const Error& e) {
    EXPECT_EQ(path, e.where().file);
  }
  EXPECT_TRUE(std::filesystem::exists(path));  // left for the user
}

TEST(StudioScript, ParsesActionsAndNamesTheLineOfAMistake) {
  const auto steps = parse_script("# a comment\nopen HOUSE ase\n\nset keywords house, home  \nreplace-symbol 0 hamfist\nsave\n", "s.txt");
  ASSERT_EQ(4u, steps.size());
  EXPECT_EQ(2, steps[0].line);
  EXPECT_EQ((std::vector<std::string>{"HOUSE", "ase"}), steps[0].args);
  EXPECT_EQ((std::vector<std::string>{"keywords", "house, home"}), steps[1].args);
  EXPECT_EQ("replace-symbol", steps[2].action);
  try {
    parse_script("save\nfly away\n", "s.txt");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(2, e.where().line);
    EXPECT_NE(std::string::npos, e.message().find("fly"));
  }
  EXPECT_THROW(parse_script("save now\n", "s.txt"), Error);
  EXPECT_THROW(parse_script("replace-symbol 0\n", "s.txt"), Error);
}

}  // namespace
}  // namespace gestura::studio

#include "gestura/studio/palette.hpp"

namespace gestura::studio {
namespace {

TEST(StudioPalette, EverySymbolIsInExactlyOneGroupAndGroupsFollowTheNotation) {
  std::map<sign::Symbol, int> seen;
  for (const PaletteGroup& g : palette_groups())
    for (const sign::Symbol s : g.symbols) ++seen[s];
  for (const sign::SymbolInfo& info : sign::symbol_table()) EXPECT_EQ(1, seen[info.symbol]) << info.name;
  ASSERT_GE(palette_groups().size(), 11u);
  EXPECT_EQ("Handshape", palette_groups()[0].title);
  EXPECT_EQ(sign::Symbol::fist, palette_groups()[0].symbols.front());
  EXPECT_EQ("flathand", short_name(sign::Symbol::flathand));
}

}  // namespace
}  // namespace gestura::studio

#include "gestura/studio/learning.hpp"

namespace gestura::studio {
namespace {

TEST(StudioLearning, TopicsComeFromTheLexiconsCategoriesWithTheirSentences) {
  TempDir dir;
  const std::string lexicon = dir.write("x.jsonl",
                                        "{\"gloss\":\"RED\",\"lang\":\"ase\",\"category\":\"colour\",\"names\":\"hamfinger2,hamextfingeru,hampalml,hamlips\",\"description\":\"index brushes down the lips\",\"keywords\":[\"red\"]}\n"
                                        "{\"gloss\":\"BLUE\",\"lang\":\"ase\",\"category\":\"colour\",\"names\":\"hamfinger2345,hamextfingeru,hampalml,hamneutralspace\",\"keywords\":[\"blue\"]}\n"
                                        "\n"
                                        "{\"gloss\":\"HELLO\",\"lang\":\"ase\",\"names\":\"hamflathand,hamextfingeru,hampalmd,hamforehead\"}\n");
  const std::string sentences = dir.write("s.json", "{\"_about\":\"x\",\"colour\":[\"I like red.\"],\"nothing\":[\"x\"]}");
  const auto topics = load_topics({lexicon}, sentences);
  ASSERT_EQ(2u, topics.size());
  EXPECT_EQ("colour", topics[0].name);
  ASSERT_EQ(2u, topics[0].words.size());
  EXPECT_EQ("index brushes down the lips", topics[0].words[0].description);
  EXPECT_EQ((std::vector<std::string>{"I like red."}), topics[0].sentences);
  EXPECT_EQ("other", topics[1].name);

  const std::string bad = dir.write("bad.jsonl", "{\"gloss\":\"A\"}\nnot json\n");
  try {
    load_topics({bad}, "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(2, e.where().line);
  }
}

TEST(StudioLearning, TheQuizAsksWordsOfTheTopicAndCountsRightAnswers) {
  Topic t{"t", {}, {}};
  for (const char* g : {"A", "B", "C", "D", "E", "F"}) t.words.push_back(LessonWord{g, "ase", "hamfist", "", {}});
  Quiz quiz(t, 7);
  std::string previous;
  for (int i = 0; i < 20; ++i) {
    const std::string gloss = quiz.word().gloss;
    EXPECT_NE(previous, gloss);
    ASSERT_EQ(4u, quiz.choices().size());
    EXPECT_NE(quiz.choices().end(), std::find(quiz.choices().begin(), quiz.choices().end(), gloss));
    if (i % 2) EXPECT_TRUE(quiz.answer(gloss));
    else EXPECT_FALSE(quiz.answer(gloss == "A" ? "B" : "A"));
    EXPECT_FALSE(quiz.answer(gloss) != quiz.answered().value());  // the first answer stands
    previous = gloss;
    quiz.next();
  }
  EXPECT_EQ(10, quiz.right());
  EXPECT_EQ(21, quiz.asked());
}

}  // namespace
}  // namespace gestura::studio

#include "gestura/studio/pose_editor.hpp"

namespace gestura::studio {
namespace {

Skeleton two_arms() {
  Skeleton s;
  const int root = s.add_joint("humanoid_root", -1, vec3(0.0f));
  for (const char* side : {"l", "r"}) {
    const float x = side[0] == 'l' ? 0.2f : -0.2f;
    const int shoulder = s.add_joint(std::string(side) + "_shoulder", root, vec3(x, 1.4f, 0.0f));
    const int elbow = s.add_joint(std::string(side) + "_elbow", shoulder, vec3(0.0f, -0.3f, 0.0f));
    s.add_joint(std::string(side) + "_wrist", elbow, vec3(0.0f, -0.25f, 0.0f));
    s.dofs[shoulder] = JointDofs{RotationOrder::XYZ, 7, vec3(deg(-90.0f)), vec3(deg(90.0f))};
    s.dofs[elbow] = JointDofs{RotationOrder::XYZ, 3, vec3(deg(-150.0f), deg(-90.0f), 0.0f), vec3(0.0f, deg(90.0f), 0.0f)};
  }
  return s;
}

TEST(StudioPoseEditor, AnglesStayInsideTheJointLimitsAndUndoRestores) {
  const Skeleton s = two_arms();
  PoseEditor editor(s, {"smile_l", "smile_r"});
  const int elbow = s.find("r_elbow");
  ASSERT_TRUE(editor.set_angles_degrees(elbow, vec3(-60.0f, 30.0f, 45.0f)));
  EXPECT_NEAR(-60.0f, editor.angles_degrees(elbow).x, 0.01f);
  EXPECT_NEAR(30.0f, editor.angles_degrees(elbow).y, 0.01f);
  EXPECT_NEAR(0.0f, editor.angles_degrees(elbow).z, 0.01f);  // a locked axis stays at 0
  ASSERT_TRUE(editor.set_angles_degrees(elbow, vec3(-200.0f, 0.0f, 0.0f)));
  EXPECT_NEAR(-150.0f, editor.angles_degrees(elbow).x, 0.01f);  // clamped to the limit
  EXPECT_EQ(1, editor.pivot_axis(elbow));  // the forearm lies along y
  EXPECT_EQ(0, editor.bend_axis(elbow));
  EXPECT_FALSE(editor.set_angles_degrees(s.find("r_wrist"), vec3(10.0f)));  // no free axis
  ASSERT_TRUE(editor.undo());
  EXPECT_NEAR(-60.0f, editor.angles_degrees(elbow).x, 0.01f);
  ASSERT_TRUE(editor.undo());
  EXPECT_NEAR(0.0f, editor.angles_degrees(elbow).x, 0.01f);
  EXPECT_FALSE(editor.undo());
  ASSERT_TRUE(editor.redo());
  EXPECT_NEAR(-60.0f, editor.angles_degrees(elbow).x, 0.01f);
}

TEST(StudioPoseEditor, MirroringMovesTheRightArmsPoseToTheLeftReflected) {
  const Skeleton s = two_arms();
  PoseEditor editor(s, {"smile_l", "smile_r"});
  editor.set_angles_degrees(s.find("r_shoulder"), vec3(-40.0f, 20.0f, 30.0f));
  editor.set_morph(1, 0.8f);
  editor.mirror();
  std::vector<mat4> model(s.size());
  editor.model(model);
  const vec3 left_wrist = vec3(model[s.find("l_wrist")][3]), right_wrist = vec3(model[s.find("r_wrist")][3]);
  // The left wrist is where the right one was, reflected in x = 0; the right arm is at rest.
  PoseEditor reference(s, {});
  reference.set_angles_degrees(s.find("r_shoulder"), vec3(-40.0f, 20.0f, 30.0f));
  std::vector<mat4> ref(s.size());
  reference.model(ref);
  const vec3 was = vec3(ref[s.find("r_wrist")][3]);
  EXPECT_NEAR(-was.x, left_wrist.x, 1e-4f);
  EXPECT_NEAR(was.y, left_wrist.y, 1e-4f);
  EXPECT_NEAR(was.z, left_wrist.z, 1e-4f);
  EXPECT_NEAR(-0.2f, right_wrist.x, 1e-4f);
  EXPECT_NEAR(0.8f, editor.morph_weights()[0], 1e-6f);
  EXPECT_NEAR(0.0f, editor.morph_weights()[1], 1e-6f);
  EXPECT_TRUE(is_hand_joint("r_index2", 'r'));
  EXPECT_FALSE(is_hand_joint("r_index2", 'l'));
  EXPECT_FALSE(is_hand_joint("r_wrist", 'r'));
}

}  // namespace
}  // namespace gestura::studio
