// The scene command as a request of the command layer: refused before any work with the category
// and the field (what the CLI turns into exit 2 and the server into HTTP 400), input errors at
// their file:line:col, and the same request read from JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gestura/app/scene.hpp"
#include "support/build_paths.hpp"

namespace {

using namespace gestura::app;
namespace fs = std::filesystem;

std::string example() { return gestura::test::source_dir() + "/data/scenes/living_room.json"; }

template <class F>
ErrorReport error_of(F&& f) {
  try {
    f();
  } catch (...) {
    return classify_current();
  }
  return {ErrorCategory::internal, {}, "no error"};
}

SceneRequest checked(const std::string& scene) {
  SceneRequest r;
  r.source.scene = scene;
  r.check = true;
  return r;
}

TEST(SceneRequest, RefusesFieldsThatDoNotGoTogether) {
  SceneRequest r = checked(example());
  EXPECT_NO_THROW(validate(r));

  r.source.script = example();
  r.source.do_text = "anna walks to chair";
  ErrorReport e = error_of([&] { validate(r); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "do");

  r = checked(example());
  r.sheet = true;
  e = error_of([&] { validate(r); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "sheet");
  r.output = "out.gif";
  e = error_of([&] { validate(r); });
  EXPECT_EQ(e.place.field, "output") << "a sheet is a PNG";
  EXPECT_NE(e.message.find("not .png"), std::string::npos) << e.message;

  r = checked(example());
  r.output = "scene.txt";
  EXPECT_EQ(error_of([&] { validate(r); }).place.field, "output");
  r.output = "scene.mp4";
  r.size = {321, 240};
  EXPECT_EQ(error_of([&] { validate(r); }).place.field, "output") << "MP4 needs even sizes";

  r = checked(example());
  r.msaa = 3;
  EXPECT_EQ(error_of([&] { validate(r); }).place.field, "msaa");
  r = checked(example());
  r.fps = 0;
  EXPECT_EQ(error_of([&] { validate(r); }).place.field, "fps");
  r = checked(example());
  r.camera = ",";
  EXPECT_EQ(error_of([&] { validate(r); }).place.field, "camera");
}

TEST(SceneRequest, MissingFilesAreNotFoundAtTheirField) {
  SceneRequest r = checked("/no/such/scene.json");
  ErrorReport e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::not_found);
  EXPECT_EQ(e.place.field, "scene");

  r = checked(example());
  r.source.script = "/no/such/script.txt";
  e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::not_found);
  EXPECT_EQ(e.place.field, "script");

  // An output whose folder is missing fails before the performance, as an output error.
  r = checked(example());
  r.check = false;
  r.output = "/no/such/folder/scene.png";
  e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::output);
  EXPECT_EQ(e.place.field, "output");

  r = checked("");
  e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "scene");
}

TEST(SceneRequest, MalformedScenesAndScriptsAreInputErrorsAtTheirPlace) {
  const fs::path bad = fs::temp_directory_path() / ("gestura_scene_request_" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream out(bad);
    out << "{\n  \"objects\": [\n    {\"shape\": \"box\", \"size\": [1, -2, 1]}\n  ]\n}\n";
  }
  ErrorReport e = error_of([&] { run(checked(bad.string())); });
  fs::remove(bad);
  EXPECT_EQ(e.category, ErrorCategory::input);
  EXPECT_EQ(e.place.source.to_string().rfind(bad.string() + ":3:", 0), 0u) << e.place.source.to_string() << " " << e.message;

  // A binary script file: refused as text that is not UTF-8, naming the byte.
  const fs::path binary = fs::temp_directory_path() / ("gestura_scene_request_" + std::to_string(::getpid()) + ".txt");
  {
    std::ofstream out(binary, std::ios::binary);
    out << "anna walks to chair\n" << '\xff' << '\xfe' << '\0' << "x";
  }
  SceneRequest r = checked(example());
  r.source.script = binary.string();
  e = error_of([&] { run(r); });
  fs::remove(binary);
  EXPECT_EQ(e.category, ErrorCategory::input);
  EXPECT_EQ(e.place.field, "script");
  EXPECT_NE(e.message.find("UTF-8"), std::string::npos) << e.message;

  r = checked(example());
  r.source.do_text = "anna walks to the attic";
  e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::input);
  EXPECT_NE(e.message.find("'attic' is no place"), std::string::npos) << e.message;

  r = checked(example());
  r.camera = "plan,ceiling";
  e = error_of([&] { run(r); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "camera");
  EXPECT_NE(e.message.find("ceiling"), std::string::npos) << e.message;
}

TEST(SceneRequest, ReadsFromJsonAndSummarisesTheScene) {
  const SceneRequest r = request_from_json<SceneRequest>(
      {{"scene", example()}, {"do", "anna walks to chair; ben turns to anna"}, {"camera", "plan,section"}, {"check", true}});
  EXPECT_EQ(r.source.do_text, "anna walks to chair; ben turns to anna");
  const SceneResult result = run(r);
  ASSERT_EQ(result.summary.size(), 2u);
  EXPECT_NE(result.summary[0].find("2 characters"), std::string::npos) << result.summary[0];
  EXPECT_EQ(result.summary[1], "script: 2 statements, 2 actions");
  EXPECT_TRUE(result.performance.log.empty()) << "check performs nothing";

  const ErrorReport e = error_of([] { request_from_json<SceneRequest>({{"scene", "x.json"}, {"wings", 2}}); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "wings");
}

TEST(SceneRequest, PerformsAScriptAndLogsItsActions) {
  SceneRequest r;
  r.source.scene = example();
  r.source.do_text = "anna walks to the middle";
  const SceneResult result = run(r);
  EXPECT_GT(result.performance.duration, 1.0f);
  EXPECT_EQ(result.warnings, 0);
  const nlohmann::json json = to_json(result);
  ASSERT_TRUE(json["log"].is_array());
  bool walked = false;
  for (const auto& entry : json["log"]) walked |= entry["text"].get<std::string>().find("anna walks to middle") != std::string::npos;
  EXPECT_TRUE(walked) << json.dump(2);
  EXPECT_FALSE(json.contains("written"));
}

}  // namespace
