// say and sign through the command layer: what each request refuses before any work (with the
// field and category), and what a run returns — the performance, not printed text.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "gestura/app/say.hpp"
#include "gestura/app/sign.hpp"
#include "gestura/app/workspace.hpp"

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

// One workspace for the file: the avatar and the signer are built once.
Workspace& workspace() {
  static Workspace w;
  return w;
}

RunContext context() {
  RunContext c;
  c.workspace = &workspace();
  return c;
}

TEST(SayRequest, RefusesBeforeAnyWorkNamingTheField) {
  SayRequest empty;
  empty.text = "   ";
  EXPECT_EQ(error_of([&] { validate(empty); }).place.field, "text");

  SayRequest huge;
  huge.text = std::string(gestura::kMaxSayBytes + 1, 'a');
  const ErrorReport big = error_of([&] { validate(huge); });
  EXPECT_EQ(big.category, ErrorCategory::too_large);
  EXPECT_EQ(big.http_status(), 413);
  EXPECT_NE(big.message.find("16384"), std::string::npos) << "names the limit: " << big.message;

  SayRequest jpg;
  jpg.text = "hello";
  jpg.output.output = "out.JPG";
  const ErrorReport picture = error_of([&] { validate(jpg); });
  EXPECT_EQ(picture.category, ErrorCategory::usage);
  EXPECT_EQ(picture.place.field, "output");
  EXPECT_NE(picture.message.find(".png"), std::string::npos) << "names what it writes: " << picture.message;

  SayRequest odd;
  odd.text = "hello";
  odd.output.output = "out.MP4";  // the extension's case does not matter
  odd.output.picture.size = {641, 360};
  const ErrorReport even = error_of([&] { validate(odd); });
  EXPECT_EQ(even.place.field, "output");
  EXPECT_NE(even.message.find("even"), std::string::npos) << even.message;
  odd.output.picture.size = {640, 360};
  EXPECT_NO_THROW(validate(odd));
}

TEST(SayRequest, RunReturnsTheTimedGlossesAndTheClip) {
  SayRequest request;
  request.text = "Where do you live?";
  const SayResult result = run(request, context());
  ASSERT_EQ(result.performance.glosses.size(), 3u);
  EXPECT_EQ(result.performance.glosses.back().gloss, "WHERE");
  EXPECT_GT(result.performance.clip.duration, 1.0f);
  EXPECT_FALSE(result.written) << "no output asked for, none written";
  const nlohmann::json j = to_json(result);
  EXPECT_EQ(j.at("glosses").size(), 3u);
  EXPECT_EQ(j.at("glosses")[2].at("gloss"), "WHERE");
}

TEST(SayRequest, InvalidTextIsAnInputErrorAtTheTextField) {
  SayRequest request;
  request.text = "caf\xC3";
  const ErrorReport e = error_of([&] { run(request, context()); });
  EXPECT_EQ(e.category, ErrorCategory::input);
  EXPECT_EQ(e.place.field, "text");
  EXPECT_NE(e.message.find("UTF-8"), std::string::npos) << e.message;
}

TEST(SignRequest, NeedsExactlyOneSourceAndAnOutput) {
  SignRequest none;
  none.output.output = "x.json";
  EXPECT_EQ(error_of([&] { validate(none); }).category, ErrorCategory::usage);
  SignRequest two = none;
  two.source.hamnosys = "\xee\x80\x81";
  two.source.names = "hamflathand";
  EXPECT_NE(error_of([&] { validate(two); }).message.find("exactly one"), std::string::npos);
  SignRequest no_output;
  no_output.source.names = "hamflathand";
  EXPECT_EQ(error_of([&] { validate(no_output); }).place.field, "output");
  SignRequest gloss_alone;
  gloss_alone.source.names = "hamflathand";
  gloss_alone.source.gloss = "MOTHER";
  gloss_alone.output.output = "x.json";
  EXPECT_EQ(error_of([&] { validate(gloss_alone); }).place.field, "gloss");
}

TEST(SignRequest, BadNotationIsAnInputErrorAtItsSymbol) {
  SignRequest request;
  request.source.names = "hamflathand,hamnotasymbol";
  request.output.output = (fs::temp_directory_path() / "gestura_app_bad_sign.json").string();
  const ErrorReport e = error_of([&] { run(request, context()); });
  EXPECT_EQ(e.category, ErrorCategory::input);
  EXPECT_EQ(e.place.field, "names");
  EXPECT_EQ(e.place.source.index, 1) << e.message;
  EXPECT_FALSE(fs::exists(request.output.output));
}

TEST(SignRequest, RunPerformsAndWritesTheSign) {
  SignRequest request;
  request.source.names = "hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch";
  request.output.output = (fs::temp_directory_path() / "gestura_app_mother.json").string();
  const SignResult result = run(request, context());
  EXPECT_GT(result.synthesis.plan.sign_end, result.synthesis.plan.sign_start);
  EXPECT_EQ(result.written.path, request.output.output);
  EXPECT_GT(fs::file_size(request.output.output), 1000u);
  EXPECT_EQ(result.written.frames, result.synthesis.stats.frames);
  fs::remove(request.output.output);
}

TEST(RunContext, AStoppedRenderLeavesNoFileAndSaysCancelled) {
  SignRequest request;
  request.source.names = "hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch";
  request.output.output = (fs::temp_directory_path() / "gestura_app_stopped.gif").string();
  request.output.picture.size = {64, 64};
  std::stop_source stop;
  std::atomic<int> reports = 0;
  RunContext c = context();
  c.stop = stop.get_token();
  c.progress = [&](const ProgressUpdate& p) {
    EXPECT_GT(p.total, 10);
    if (++reports == 3) stop.request_stop();
  };
  const ErrorReport e = error_of([&] { run(request, c); });
  EXPECT_EQ(e.category, ErrorCategory::cancelled);
  EXPECT_EQ(e.exit_code(), 130);
  EXPECT_EQ(reports.load(), 3) << "progress came frame by frame and stopped at the request";
  EXPECT_FALSE(fs::exists(request.output.output));
}

}  // namespace
