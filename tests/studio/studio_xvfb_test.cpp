// The studio itself under a virtual X server, driven by --script (UI actions replayed one per
// frame): a handshape change bends the preview's fingers and, saved, changes the database row;
// undo restores both; notation that does not parse is shown at its symbol and never saved; a killed
// studio offers its draft back. Screenshots go to $GESTURA_STUDIO_SCREENSHOTS when set (docs/studio.md
// uses them), else to a temporary directory. Skipped only where xvfb-run is not installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "gestura/lexicon/lexicon.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/studio_under_xvfb.hpp"
#include "support/png_file.hpp"

namespace gestura {
namespace {

namespace fs = std::filesystem;
using gestura::test::run_command;
using gestura::testing::TempDir;
using gestura::test::have_xvfb;
using gestura::test::read_json_file;
using gestura::test::shot_dir;
using gestura::test::run_studio;





std::optional<std::string> stored_names(const std::string& db, const std::string& gloss) {
  Lexicon lex = Lexicon::open(db);
  const auto row = lex.find(gloss, "ase", 1);
  if (!row) return std::nullopt;
  std::string names;
  for (const sign::Symbol s : sign::symbols_from_unicode(row->notation)) names += (names.empty() ? "" : ",") + std::string(sign::symbol_name(s));
  return names;
}


std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(StudioUnderXvfb, AHandshapeChangeBendsThePreviewAndSavesTheRowAndUndoRestoresBoth) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir);
  const std::string j = dir.file("");
  const auto r = run_studio(dir, db, "edit.txt",
                            "new\n"
                            "set gloss TESTFLEX\n"
                            "set keywords flex test\n"
                            "set names hamflathand,hamextfingeru,hampalml,hamchest\n"
                            "save\n"
                            "wait 1\n"
                            "dump " + j + "flat.json\n"
                            "select-symbol 0\n"
                            "palette hamfist\n"  // a click on the palette replaces the selected symbol
                            "wait 1\n"
                            "dump " + j + "fist.json\n"
                            "save\n"
                            "dump " + j + "saved.json\n"
                            "screenshot " + shots + "/studio-edit.png\n"
                            "undo\n"  // the save
                            "dump " + j + "undo_save.json\n"
                            "undo\n"  // the handshape
                            "wait 1\n"
                            "dump " + j + "undo_symbol.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto flat = read_json_file(j + "flat.json"), fist = read_json_file(j + "fist.json"), saved = read_json_file(j + "saved.json"),
             undo_save = read_json_file(j + "undo_save.json"), undo_symbol = read_json_file(j + "undo_symbol.json");
  ASSERT_TRUE(flat.is_object() && fist.is_object() && saved.is_object() && undo_save.is_object() && undo_symbol.is_object());

  // The preview: a fist bends the right hand's fingers far more than a flat hand.
  ASSERT_TRUE(flat["preview"]["has_clip"].get<bool>()) << flat.dump();
  ASSERT_TRUE(fist["preview"]["has_clip"].get<bool>()) << fist.dump();
  const float flat_flex = flat["preview"]["flexion_right"], fist_flex = fist["preview"]["flexion_right"];
  EXPECT_GT(fist_flex, flat_flex + 150.0f) << "flat " << flat_flex << " fist " << fist_flex;
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamchest", fist["draft"]["names"]);

  // The database: the first save stored the flat hand, the second the fist, undo put the flat hand back.
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", flat["db_names"]);
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamchest", saved["db_names"]);
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", undo_save["db_names"]);
  EXPECT_EQ("hamfist,hamextfingeru,hampalml,hamchest", undo_save["draft"]["names"]);
  // ... and the preview with it.
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", undo_symbol["draft"]["names"]);
  const float undone_flex = undo_symbol["preview"]["flexion_right"];
  EXPECT_NEAR(flat_flex, undone_flex, 1.0f);
  // Read independently of the studio after it quit: the row is the flat hand again.
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", stored_names(db, "TESTFLEX").value_or("(none)"));

  const auto image = gestura::test::read_png(shots + "/studio-edit.png", 3);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(1280, image.width);
  EXPECT_EQ(800, image.height);
}

TEST(StudioUnderXvfb, ANonManualTierMovesThePreviewsFaceAndHeadIsSavedAsSigmlAndUndoRestoresBoth) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  std::ofstream(j + "mixed.sigml") << "<sigml>\n"
                                      "<hns_sign gloss=\"TESTMOUTH\"><hamnosys_nonmanual><hnm_mouthpicture picture=\"hUs\"/></hamnosys_nonmanual>\n"
                                      "<hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamchest/></hamnosys_manual></hns_sign>\n"
                                      "<hns_sign gloss=\"TESTBROKEN\"><hamnosys_manual><hamextfingeru/><hamparend/></hamnosys_manual></hns_sign>\n"
                                      "</sigml>\n";
  const auto r = run_studio(dir, db, "nonmanual.txt",
                            "new\n"
                            "set gloss TESTNM\n"
                            "set keywords question\n"
                            "set names hamflathand,hamextfingeru,hampalml,hamchest\n"
                            "save\n"
                            "wait 1\n"
                            "dump " + j + "plain.json\n"
                            "nonmanual eyebrows RB\n"
                            "nonmanual head NO\n"
                            "nonmanual mouth-picture kw\"Est\n"  // a character SiGML cannot hold: refused
                            "wait 1\n"
                            "dump " + j + "nm.json\n"
                            "save\n"
                            "dump " + j + "saved.json\n"
                            "export " + j + "out.sigml\n"
                            "export " + j + "out.jsonl\n"
                            "time 1.0\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-nonmanual.png\n"
                            "undo\n"  // the save
                            "dump " + j + "undo_save.json\n"
                            "undo\n"  // the head
                            "undo\n"  // the brows
                            "wait 1\n"
                            "dump " + j + "undo_nm.json\n"
                            "import " + j + "out.sigml\n"  // the exported SiGML back: the row with its tiers
                            "open TESTNM\n"
                            "wait 1\n"
                            "dump " + j + "imported.json\n"
                            "import " + j + "mixed.sigml\n"  // one good sign, one whose notation does not parse
                            "dump " + j + "mixed.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto plain = read_json_file(j + "plain.json"), nm = read_json_file(j + "nm.json"), saved = read_json_file(j + "saved.json"),
             undo_save = read_json_file(j + "undo_save.json"), undo_nm = read_json_file(j + "undo_nm.json"),
             imported = read_json_file(j + "imported.json");
  ASSERT_TRUE(plain.is_object() && nm.is_object() && saved.is_object() && undo_save.is_object() && undo_nm.is_object() &&
              imported.is_object());
  ASSERT_TRUE(plain["preview"]["has_clip"].get<bool>()) << plain.dump();
  ASSERT_TRUE(nm["preview"]["has_clip"].get<bool>()) << nm.dump();

  // The preview: raised brows lift the brow channels, a nod turns the head.
  auto brow = [](const nlohmann::json& d) { return d["preview"]["face"].value("browInnerUp_L", 0.0f); };
  auto head = [](const nlohmann::json& d) {
    return std::max(d["preview"]["head_degrees"].value("skullbase", 0.0f), d["preview"]["head_degrees"].value("vc4", 0.0f));
  };
  EXPECT_GT(brow(nm), brow(plain) + 0.4f) << nm["preview"]["face"].dump();
  EXPECT_GT(head(nm), head(plain) + 4.0f) << nm["preview"]["head_degrees"].dump();
  ASSERT_EQ(2u, nm["draft"]["nonmanuals"].size()) << nm["draft"].dump();  // the bad mouth picture was refused
  EXPECT_EQ("head", nm["draft"]["nonmanuals"][0]["tier"]);
  EXPECT_EQ("eyebrows", nm["draft"]["nonmanuals"][1]["tier"]);

  // The database: HamNoSys before, SiGML with the tiers after the save, HamNoSys again after undo.
  EXPECT_EQ("hamnosys", plain["db_kind"]);
  EXPECT_EQ("sigml", saved["db_kind"]);
  EXPECT_NE(std::string::npos, saved["db_notation"].get<std::string>().find("<hnm_eyebrows tag=\"RB\""));
  EXPECT_NE(std::string::npos, saved["db_notation"].get<std::string>().find("<hnm_head tag=\"NO\""));
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", saved["db_names"]);
  EXPECT_EQ("hamnosys", undo_save["db_kind"]);
  EXPECT_EQ(2u, undo_save["draft"]["nonmanuals"].size());
  // ... and the preview with the draft.
  EXPECT_TRUE(undo_nm["draft"]["nonmanuals"].empty());
  EXPECT_NEAR(brow(plain), brow(undo_nm), 0.02f);
  EXPECT_NEAR(head(plain), head(undo_nm), 0.5f);

  // Exported: the SiGML file holds the sign with its tiers, the JSON lines its SiGML; imported back
  // it opens with them.
  const std::string sigml = read_text(j + "out.sigml");
  EXPECT_NE(std::string::npos, sigml.find("gloss=\"TESTNM\"")) << sigml;
  EXPECT_NE(std::string::npos, sigml.find("hnm_head"));
  EXPECT_NE(std::string::npos, read_text(j + "out.jsonl").find("\"sigml\""));
  EXPECT_EQ("sigml", imported["db_kind"]) << imported["status"];
  EXPECT_EQ(2u, imported["draft"]["nonmanuals"].size()) << imported["status"];
  EXPECT_EQ("hamflathand,hamextfingeru,hampalml,hamchest", imported["draft"]["names"]);

  // A file with a sign that does not parse: the good one is stored, the bad one skipped with its line.
  const auto mixed = read_json_file(j + "mixed.json");
  ASSERT_TRUE(mixed.is_object());
  const std::string status = mixed["status"];
  EXPECT_NE(std::string::npos, status.find("imported 1 signs")) << status;
  EXPECT_NE(std::string::npos, status.find("skipped 1")) << status;
  EXPECT_NE(std::string::npos, status.find("mixed.sigml:4")) << status;
  {
    Lexicon lex = Lexicon::open(db);
    EXPECT_TRUE(lex.find("TESTMOUTH", "ase", 1).has_value());
    EXPECT_FALSE(lex.find("TESTBROKEN", "ase", 1).has_value());
  }

  const auto image = gestura::test::read_png(shots + "/studio-nonmanual.png", 3);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(1280, image.width);
}

TEST(StudioUnderXvfb, NotationThatDoesNotParseIsShownAtItsSymbolAndNeverSaved) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "bad.txt",
                            "new\n"
                            "set gloss TESTBAD\n"
                            "set names hamflathand,hamextfingeru,hamparend,hamchest\n"
                            "wait 1\n"
                            "save\n"
                            "screenshot " + shots + "/studio-error.png\n"
                            "dump " + j + "bad.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto bad = read_json_file(j + "bad.json");
  ASSERT_TRUE(bad.is_object());
  ASSERT_TRUE(bad["notation_error"].is_object()) << bad.dump();
  EXPECT_EQ(2, bad["notation_error"]["symbol"]);
  EXPECT_EQ(2, bad["preview"]["error"]["symbol"]);
  EXPECT_FALSE(bad["preview"]["has_clip"].get<bool>());
  const std::string status = bad["status"];
  EXPECT_NE(std::string::npos, status.find("not saved")) << status;
  EXPECT_NE(std::string::npos, status.find("symbol 2")) << status;
  EXPECT_TRUE(bad["db_names"].is_null());
  EXPECT_FALSE(stored_names(db, "TESTBAD").has_value());
  EXPECT_TRUE(bad["dirty"].get<bool>());  // the draft is kept

  // The symbol is marked in red in the notation panel (the error chip's colour).
  const auto image = gestura::test::read_png(shots + "/studio-error.png", 3);
  ASSERT_TRUE(image.loaded());
  int red = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = image.width / 2; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      red += p[0] > 170 && p[1] < 60 && p[2] < 60;
    }
  EXPECT_GT(red, 200) << "no red error chip in the notation panel";
}

TEST(StudioUnderXvfb, AKilledStudioOffersItsDraftBack) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto killed = run_studio(dir, db, "kill.txt",
                                 "new\n"
                                 "set gloss TESTDRAFT\n"
                                 "set names hamfist,hamthumboutmod,hamextfingeru,hampalml,hamchin\n"
                                 "wait 2\n"
                                 "kill\n");
  EXPECT_NE(0, killed.status) << killed.output;
  ASSERT_TRUE(fs::exists(db + ".studio-draft.json"));
  EXPECT_FALSE(stored_names(db, "TESTDRAFT").has_value());

  const auto again = run_studio(dir, db, "recover.txt",
                                "wait 2\n"
                                "screenshot " + shots + "/studio-recovery.png\n"
                                "dump " + j + "offered.json\n"
                                "recover\n"
                                "wait 1\n"
                                "dump " + j + "recovered.json\n"
                                "quit\n");
  ASSERT_EQ(0, again.status) << again.output;
  const auto offered = read_json_file(j + "offered.json"), recovered = read_json_file(j + "recovered.json");
  ASSERT_TRUE(offered.is_object() && recovered.is_object());
  EXPECT_TRUE(offered["recovery_offered"].get<bool>());
  EXPECT_EQ("", offered["draft"]["gloss"]);  // nothing restored before the user says so
  EXPECT_FALSE(recovered["recovery_offered"].get<bool>());
  EXPECT_EQ("TESTDRAFT", recovered["draft"]["gloss"]);
  EXPECT_EQ("hamfist,hamthumboutmod,hamextfingeru,hampalml,hamchin", recovered["draft"]["names"]);
  EXPECT_TRUE(recovered["dirty"].get<bool>());
  EXPECT_TRUE(recovered["preview"]["has_clip"].get<bool>());
  // Quitting with the draft still unsaved keeps it for next time.
  EXPECT_TRUE(fs::exists(db + ".studio-draft.json"));
}

TEST(StudioUnderXvfb, BrowsesTheBuiltInLexiconByHandshapeAndShowsEveryPanel) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "tour.txt",
                            "filter handshape hamfinger2\n"
                            "dump " + j + "filtered.json\n"
                            "filter handshape -\n"
                            "search thank\n"
                            "open THANK-YOU\n"
                            "panel Palette\n"
                            "camera three-quarter\n"
                            "time 0.9\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-browse.png\n"
                            "dump " + j + "tour.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto filtered = read_json_file(j + "filtered.json"), tour = read_json_file(j + "tour.json");
  ASSERT_TRUE(filtered.is_object() && tour.is_object());
  EXPECT_GT(filtered["browse_count"].get<int>(), 5);
  EXPECT_EQ("THANK-YOU", tour["draft"]["gloss"]) << tour["status"];
  EXPECT_TRUE(tour["draft"]["from_builtin"].get<bool>());
  EXPECT_TRUE(tour["preview"]["has_clip"].get<bool>());
  const auto image = gestura::test::read_png(shots + "/studio-browse.png", 3);
  ASSERT_TRUE(image.loaded());
  // The preview (the middle of the window) shows the avatar, not a flat background.
  int differing = 0;
  const std::uint8_t* corner = image.at(image.width / 5 + 20, 60);
  for (int y = 80; y < image.height / 2; y += 4) {
    const std::uint8_t* p = image.at(image.width / 2, y);
    differing += std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) > 30;
  }
  EXPECT_GT(differing, 10);
}

TEST(StudioUnderXvfb, ExportsTheSignAsPerformedAndRefusesAnUnknownFormat) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), j = dir.file("");
  const auto r = run_studio(dir, db, "export.txt",
                            "new\n"
                            "set names hamfinger2,hamextfingeru,hampalml,hamchin,hammoveo\n"
                            "export-sign " + j + "sign.bvh\n"
                            "dump " + j + "exported.json\n"
                            "export-sign " + j + "sign.xyz\n"
                            "dump " + j + "refused.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto exported = read_json_file(j + "exported.json"), refused = read_json_file(j + "refused.json");
  ASSERT_TRUE(exported.is_object() && refused.is_object());
  EXPECT_NE(std::string::npos, exported["status"].get<std::string>().find("exported")) << exported["status"];
  std::ifstream bvh(j + "sign.bvh");
  std::string text((std::istreambuf_iterator<char>(bvh)), std::istreambuf_iterator<char>());
  EXPECT_EQ(0u, text.find("HIERARCHY"));
  const auto frames_at = text.find("Frames:");
  ASSERT_NE(std::string::npos, frames_at);
  EXPECT_GT(std::stoi(text.substr(frames_at + 7)), 10);
  EXPECT_NE(std::string::npos, refused["status"].get<std::string>().find("not exported")) << refused["status"];
  EXPECT_FALSE(fs::exists(j + "sign.xyz"));
}

TEST(StudioUnderXvfb, ThePoseEditorKeepsJointsInTheirLimitsFormsHandsAndMirrors) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "pose.txt",
                            "mode pose\n"
                            "pose-joint r_elbow\n"
                            "pose-angles -300 0 0\n"
                            "dump " + j + "limit.json\n"
                            "pose-joint r_shoulder\n"
                            "pose-angles -60 0 40\n"
                            "pose-hand r hamfist\n"
                            "dump " + j + "fist.json\n"
                            "pose-mirror\n"
                            "wait 1\n"
                            "screenshot " + shots + "/studio-pose.png\n"
                            "dump " + j + "mirrored.json\n"
                            "undo\n"
                            "dump " + j + "undone.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto limit = read_json_file(j + "limit.json"), fist = read_json_file(j + "fist.json"), mirrored = read_json_file(j + "mirrored.json"),
             undone = read_json_file(j + "undone.json");
  ASSERT_TRUE(limit.is_object() && fist.is_object() && mirrored.is_object() && undone.is_object());
  // The elbow asked to bend 300 degrees stops at its limit (a real elbow bends less than 160).
  const float elbow = limit["pose"]["angles"][0];
  EXPECT_GT(elbow, -160.0f);
  EXPECT_LT(elbow, -90.0f);
  // A fist preset bends the right fingers; mirroring moves pose and hand to the left.
  const float right = fist["pose"]["flexion_right"], left = fist["pose"]["flexion_left"];
  EXPECT_GT(right, left + 150.0f);
  EXPECT_NEAR(right, mirrored["pose"]["flexion_left"].get<float>(), 1.0f);
  EXPECT_NEAR(left, mirrored["pose"]["flexion_right"].get<float>(), 1.0f);
  EXPECT_NEAR(0.0f, mirrored["pose"]["angles"][0].get<float>(), 0.01f);  // the right shoulder is at rest now
  // Undo brings the pose before the mirror back.
  EXPECT_NEAR(right, undone["pose"]["flexion_right"].get<float>(), 1.0f);
  EXPECT_NEAR(-60.0f, undone["pose"]["angles"][0].get<float>(), 0.01f);
}

TEST(StudioUnderXvfb, LearningModePlaysWordsAndSentencesAndScoresTheSelfTest) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "learn.txt",
                            "topic greeting\n"
                            "word HELLO\n"
                            "wait 1\n"
                            "dump " + j + "word.json\n"
                            "sentence Hello, nice to meet you.\n"
                            "speed 0.5\n"
                            "time 1.5\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-learn.png\n"
                            "dump " + j + "sentence.json\n"
                            "quiz 5\n"
                            "wait 1\n"
                            "dump " + j + "quiz.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto word = read_json_file(j + "word.json"), sentence = read_json_file(j + "sentence.json"), quiz = read_json_file(j + "quiz.json");
  ASSERT_TRUE(word.is_object() && sentence.is_object() && quiz.is_object());
  EXPECT_TRUE(word["learning"]["active"].get<bool>());
  EXPECT_EQ("greeting", word["learning"]["topic"]);
  ASSERT_EQ(1u, word["learning"]["glosses"].size());
  EXPECT_EQ("HELLO", word["learning"]["glosses"][0]["gloss"]);
  // A sentence is several signs, one bar each, in order.
  const auto& bars = sentence["learning"]["glosses"];
  ASSERT_GE(bars.size(), 3u) << sentence.dump();
  EXPECT_EQ("HELLO", bars[0]["gloss"]);
  for (std::size_t i = 1; i < bars.size(); ++i) EXPECT_GE(bars[i]["start"].get<float>(), bars[i - 1]["start"].get<float>());
  // The self-test: the right gloss is among the choices, the word is from the topic.
  const auto& q = quiz["learning"]["quiz"];
  ASSERT_TRUE(q.is_object()) << quiz.dump();
  const std::string answer = q["word"];
  const auto choices = q["choices"].get<std::vector<std::string>>();
  EXPECT_EQ(4u, choices.size());
  EXPECT_NE(choices.end(), std::find(choices.begin(), choices.end(), answer));

  // Answering: once wrong, then (next question) right.
  std::string wrong;
  for (const std::string& c : choices)
    if (c != answer) wrong = c;
  const auto r2 = run_studio(dir, db, "answer.txt",
                             "topic greeting\nquiz 5\nanswer " + wrong + "\ndump " + j + "a1.json\n");
  ASSERT_EQ(0, r2.status) << r2.output;
  const auto a1 = read_json_file(j + "a1.json");
  ASSERT_TRUE(a1.is_object());
  EXPECT_EQ(answer, a1["learning"]["quiz"]["word"]);  // the same seed asks the same word
  EXPECT_FALSE(a1["learning"]["quiz"]["answered"].get<bool>());
  EXPECT_EQ(0, a1["learning"]["quiz"]["right"]);
  EXPECT_NE(std::string::npos, a1["status"].get<std::string>().find("it was " + answer));
}

}  // namespace
}  // namespace gestura
