// Every command family's request refuses what it cannot do before any work, with the category and
// the field — the same answer the CLI turns into exit 2 and the server into HTTP 400.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gestura/app/avatar.hpp"
#include "gestura/app/check.hpp"
#include "gestura/app/compress.hpp"
#include "gestura/app/convert.hpp"
#include "gestura/app/fingerspell.hpp"
#include "gestura/app/gloss.hpp"
#include "gestura/app/info.hpp"
#include "gestura/app/lexicon.hpp"
#include "gestura/app/mouth.hpp"
#include "gestura/app/reach.hpp"
#include "gestura/app/render.hpp"
#include "gestura/app/retarget.hpp"
#include "gestura/app/subtitles.hpp"

namespace {

using namespace gestura::app;
namespace fs = std::filesystem;

template <class F>
ErrorReport error_of(F&& f) {
  try {
    f();
  } catch (...) {
    return classify_current();
  }
  return {ErrorCategory::internal, {}, "no error"};
}

// A usage error at `field`, from validate and so from run.
template <class R>
void expect_refused(const R& request, const std::string& field, const std::string& says = "") {
  const ErrorReport e = error_of([&] { validate(request); });
  EXPECT_EQ(e.category, ErrorCategory::usage) << e.message;
  EXPECT_EQ(e.place.field, field) << e.message;
  if (!says.empty()) {
    EXPECT_NE(e.message.find(says), std::string::npos) << e.message;
  }
  EXPECT_EQ(error_of([&] { run(request); }).place.field, field) << "run validates first";
}

TEST(Requests, ConvertChoosesFormatsByExtension) {
  ConvertRequest r;
  r.input = "in.bvh";
  r.output = "out.fbx";
  expect_refused(r, "output", ".bap");
  r.output = "out.json";
  expect_refused(r, "output", "--openpose");
  r.input = "in.obj";
  r.output = "out.bvh";
  expect_refused(r, "input", ".bvh");
  r.input = "/nonexistent/in.BVH";
  EXPECT_NO_THROW(validate(r));
  EXPECT_EQ(error_of([&] { run(r); }).category, ErrorCategory::not_found);
}

TEST(Requests, InfoKnowsItsFormats) {
  InfoRequest r;
  expect_refused(r, "file", "missing");
  r.file = "a.txt";
  expect_refused(r, "file", ".gcl");
  r.file = "a.gcl";
  r.depth = -1;
  expect_refused(r, "depth");
}

TEST(Requests, CheckTakesLexiconsAndSigml) {
  CheckRequest r;
  r.file = "signs.csv";
  expect_refused(r, "file", ".jsonl or .sigml");
  r.file = "signs.JSONL";
  r.max_errors = -5;
  expect_refused(r, "max_errors");
  r.max_errors = 0;
  EXPECT_NO_THROW(validate(r));
}

TEST(Requests, RenderAndViewPictures) {
  RenderRequest r;
  r.output.output = "x.jpg";
  expect_refused(r, "output", ".png, .gif, .mp4 or .webm");
  r.output.output = "x.bvh";
  expect_refused(r, "output", "pictures");
  r.output.output = "x.png";
  r.msaa = 3;
  expect_refused(r, "msaa");
  r.msaa = 4;
  r.subject.rest = true;
  r.subject.test_motion = true;
  expect_refused(r, "", "show one thing");
  r.subject.test_motion = false;
  r.color = {"skin=#zzzzzz"};
  expect_refused(r, "color");
  ViewRequest v;
  v.camera = {gestura::CameraPreset::Front, gestura::CameraPreset::Side};
  expect_refused(v, "camera");
}

TEST(Requests, SubtitlesNeedSubtitlesAndAVideo) {
  SubtitlesRequest r;
  r.input = "talk.txt";
  r.output = "talk.mp4";
  expect_refused(r, "input", ".srt or .vtt");
  r.input = "talk.SRT";
  r.output = "talk.gif";
  expect_refused(r, "output", ".mp4 or .webm");
  r.output = "talk.mp4";
  r.max_speed = 3.0f;
  expect_refused(r, "max_speed");
}

TEST(Requests, AvatarExportIsBinaryGltf) {
  AvatarRequest r;
  r.action = AvatarAction::export_glb;
  expect_refused(r, "output", "missing");
  r.output = "avatar.obj";
  expect_refused(r, "output", ".glb");
  r.action = AvatarAction::info;
  expect_refused(r, "output");
  r.output.clear();
  r.avatar.params.height = 3.0f;
  expect_refused(r, "height", "2.5");
}

TEST(Requests, AvatarLooksListTheBuiltInLooksWithoutBuildingAnAvatar) {
  AvatarRequest r;
  r.action = AvatarAction::looks;
  r.output = "looks.json";
  expect_refused(r, "output");
  r.output.clear();
  const AvatarResult result = run(r);
  ASSERT_GE(result.looks.size(), 5u);  // the default and at least four looks
  EXPECT_EQ(result.looks.front().name, "default");
  EXPECT_EQ(result.avatar.mesh.vertex_count(), 0u);
  EXPECT_EQ(to_json(result, AvatarAction::looks)["looks"].size(), result.looks.size());
  EXPECT_EQ(TextCodec<AvatarAction>::parse("looks"), AvatarAction::looks);
  EXPECT_EQ(TextCodec<AvatarAction>::format(AvatarAction::looks), "looks");
  // A look is the generated avatar: its parameters are checked, its key tells looks apart.
  AvatarChoice ana, ben;
  ana.avatar = "ana";
  ben.avatar = "ben";
  EXPECT_TRUE(ana.generated());
  EXPECT_NE(ana.key(), ben.key());
  ana.params.build = 2.0f;
  EXPECT_EQ(error_of([&] { validate(ana); }).place.field, "build");
  AvatarChoice unknown;
  unknown.avatar = "zed";
  EXPECT_FALSE(unknown.generated());
}

TEST(Requests, LexiconQueriesAndChanges) {
  LexiconQuery q;
  q.kind = LexiconQueryKind::show;
  expect_refused(q, "text", "gloss");
  q.kind = LexiconQueryKind::list;
  q.prefix = true;
  expect_refused(q, "prefix");
  LexiconAddRequest add;
  add.gloss = "HELLO";
  expect_refused(add, "lang");
  add.lang = "ase";
  expect_refused(add, "hamnosys", "exactly one");
  LexiconRemoveRequest remove;
  remove.gloss = "HELLO";
  expect_refused(remove, "lang");
}

TEST(Requests, LexiconChangesReportConflictsAndAbsence) {
  const std::string db = (fs::temp_directory_path() / "gestura_app_requests.sqlite").string();
  fs::remove(db);
  LexiconAddRequest add;
  add.gloss = "TESTSIGN";
  add.lang = "ase";
  add.hamnosys = "\xee\x80\x81\xee\x80\xa0\xee\x80\xbe\xee\x81\x92";  // flat hand, fingers up, palm left, at the chest
  add.db = db;
  ASSERT_EQ(run(add).count, 1u);
  const ErrorReport again = error_of([&] { run(add); });
  EXPECT_EQ(again.category, ErrorCategory::conflict) << again.message;
  EXPECT_EQ(again.http_status(), 409);
  LexiconRemoveRequest remove;
  remove.gloss = "NOSUCHSIGN";
  remove.lang = "ase";
  remove.db = db;
  EXPECT_EQ(error_of([&] { run(remove); }).category, ErrorCategory::not_found);
  LexiconQuery missing_db;
  missing_db.db = "/nonexistent/lexicon.sqlite";
  const ErrorReport none = error_of([&] { run(missing_db); });
  EXPECT_EQ(none.category, ErrorCategory::not_found);
  EXPECT_EQ(none.place.field, "db");
  fs::remove(db);
}

TEST(Requests, NumbersOfTheOtherCommandsAreBounded) {
  FingerspellRequest f;
  f.text = "hello";
  f.speed = 5.0f;
  expect_refused(f, "speed");
  MouthRequest m;
  m.word = "mom";
  m.start = 1.0f;
  m.end = 0.5f;
  expect_refused(m, "end");
  ReachRequest reach;
  expect_refused(reach, "target", "missing");
  reach.target = gestura::vec3(0.2f, 1.2f, 0.3f);
  reach.frames = 0;
  expect_refused(reach, "frames");
  CompressRequest c;
  c.input = "synthetic";
  c.error_cm = 0.0f;
  expect_refused(c, "error_cm");
  DecompressRequest d;
  d.input = "in.gcl";
  d.output = "out.bvh";
  expect_refused(d, "skeleton", "missing");
  RetargetRequest rt;
  rt.input = "in.bvh";
  expect_refused(rt, "output");
  GlossRequest g;
  g.text = std::string(kMaxGlossBytes + 1, 'a');
  EXPECT_EQ(error_of([&] { validate(g); }).category, ErrorCategory::too_large);
}

TEST(Requests, ResultsAreData) {
  GlossRequest g;
  g.text = "Where do you live?";
  const GlossResult glossed = run(g);
  EXPECT_EQ(glossed.translation.text(), "IX-2 LIVE WHERE");
  const nlohmann::json j = to_json(glossed);
  EXPECT_EQ(j.at("glosses").size(), 3u);

  FingerspellRequest f;
  f.text = "José";
  const FingerspellResult spelled = run(f);
  ASSERT_EQ(spelled.letters.size(), 4u);
  EXPECT_EQ(spelled.letters[3].letter, 'E');
  EXPECT_FALSE(spelled.performance) << "no output: timings only";

  MouthRequest m;
  m.word = "mom";
  const MouthResult mouthed = run(m);
  EXPECT_FALSE(mouthed.phonemes.empty());
  EXPECT_FALSE(mouthed.clip.channels.empty());
}

}  // namespace
