// The studio's timeline, figure and IK editors under a virtual X server, driven by --script: a key
// dragged to another time moves the peak of the exported BVH there (and undo moves it back); a
// sign's bar made longer makes the exported motion longer by as much; the timeline saved as a clip
// sign is played by the learning mode (topic "your signs"), signed in a sentence and played by the
// dictionary; the figure editor's saved
// skeleton renders with `gestura render` and receives a motion with `gestura retarget`, while a
// skeleton file that does not parse is refused with nothing lost; dragging the right hand with IK
// puts the wrist within 1 cm of the target and undo puts it back. Screenshots go to
// $GESTURA_STUDIO_SCREENSHOTS when set (docs/studio.md uses them). Skipped where xvfb-run is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/lexicon/lexicon.hpp"
#include "gestura/studio/timeline_clip_sign.hpp"
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
using gestura::test::peak_time;
using gestura::test::read_json_file;
using gestura::test::shot_dir;
using gestura::test::run_studio;






TEST(StudioTimelineUnderXvfb, RetimingAKeyMovesItInTheExportedBvhAndABarRetimesTheUtterance) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "timeline.txt",
                            "mode timeline\n"
                            "timeline-say hello my name is\n"
                            "export-timeline " + j + "say1.bvh\n"
                            "dump " + j + "say1.json\n"
                            "bar-duration 1 1.5\n"  // HELLO (bar 0 is the way in) lasts 1.5 s
                            "export-timeline " + j + "say2.bvh\n"
                            "dump " + j + "say2.json\n"
                            "timeline-clear\n"
                            "undo\n"  // the clear
                            "undo\n"  // the bar
                            "dump " + j + "say3.json\n"
                            "timeline-clear\n"
                            "key r_elbow.x 0 0\n"
                            "key r_elbow.x 1.0 -100\n"
                            "key r_elbow.x 2.0 0\n"
                            "export-timeline " + j + "a.bvh\n"
                            "move-key r_elbow.x 1 0.5\n"
                            "key-interp r_elbow.x 1 kb 0.3 0 -0.5\n"
                            "export-timeline " + j + "b.bvh\n"
                            "dump " + j + "moved.json\n"
                            "undo\n"  // the interpolation
                            "undo\n"  // the move
                            "export-timeline " + j + "c.bvh\n"
                            "save-clip-sign TESTWAVE\n"
                            // The clip sign in the learning mode, in a sentence and in the dictionary.
                            "mode learn\n"
                            "topic your signs\n"
                            "word TESTWAVE\n"
                            "dump " + j + "learn-word.json\n"
                            "sentence hello testwave\n"
                            "dump " + j + "learn-sentence.json\n"
                            "mode edit\n"
                            "open TESTWAVE\n"
                            "time 1.0\n"
                            "wait 2\n"
                            "dump " + j + "dictionary.json\n"
                            "screenshot " + shots + "/studio-clip-sign.png\n"
                            "mode timeline\n"  // the clip sign picked in the dictionary is open here
                            "time 0.8\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-clip-sign-timeline.png\n"
                            "timeline-say hello my name is\n"  // the keys over an utterance, for the screenshot
                            "key l_elbow.x 0.6 -80\n"
                            "key-interp r_elbow.x 1 kb 0.5 0 0\n"
                            "time 0.7\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-timeline.png\n"
                            "export-timeline " + j + "bad.xyz\n"
                            "dump " + j + "bad.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto say1 = read_json_file(j + "say1.json"), say2 = read_json_file(j + "say2.json"), say3 = read_json_file(j + "say3.json"),
             moved = read_json_file(j + "moved.json"), bad = read_json_file(j + "bad.json");
  ASSERT_TRUE(say1.is_object() && say2.is_object() && say3.is_object() && moved.is_object() && bad.is_object());

  // The utterance as bars: the way in, then HELLO; made 1.5 s long, the motion lasts that much longer.
  const auto& bars = say1["timeline"]["bars"];
  ASSERT_GE(bars.size(), 3u) << say1.dump();
  EXPECT_EQ("HELLO", bars[1]["label"]);
  const float old_bar = bars[1]["duration"], grow = 1.5f - old_bar;
  EXPECT_NEAR(1.5f, say2["timeline"]["bars"][1]["duration"].get<float>(), 1e-4f);
  const BvhFile say1_bvh = load_bvh(j + "say1.bvh"), say2_bvh = load_bvh(j + "say2.bvh");
  EXPECT_NEAR(say1_bvh.clip.duration + grow, say2_bvh.clip.duration, 1.5f / 30.0f);
  EXPECT_NEAR(old_bar, say3["timeline"]["bars"][1]["duration"].get<float>(), 1e-4f);  // undone

  // Keys: the elbow's peak is where its key is.
  const BvhFile a = load_bvh(j + "a.bvh"), b = load_bvh(j + "b.bvh"), c = load_bvh(j + "c.bvh");
  EXPECT_NEAR(1.0f, peak_time(a, "r_elbow"), 0.5f / 30.0f);
  EXPECT_NEAR(0.5f, peak_time(b, "r_elbow"), 0.5f / 30.0f);
  EXPECT_NEAR(1.0f, peak_time(c, "r_elbow"), 0.5f / 30.0f);  // after undo
  EXPECT_EQ("kb", moved["timeline"]["channels"]["r_elbow.x"][1]["interpolation"]);
  EXPECT_NEAR(0.5f, moved["timeline"]["channels"]["r_elbow.x"][1]["time"].get<float>(), 1e-4f);

  // The clip sign in the lexicon, its motion the timeline's.
  Lexicon lex = Lexicon::open(db);
  const auto row = lex.find("TESTWAVE", "ase", 1);
  ASSERT_TRUE(row.has_value());
  EXPECT_EQ(NotationKind::clip, row->notation_kind);
  const Clip stored = studio::clip_of(*row);
  const Skeleton skeleton = build_avatar_skeleton();
  const int elbow = skeleton.find("r_elbow");
  ASSERT_LT(static_cast<std::size_t>(elbow), stored.rotations.size());
  const quat at_peak = sample_track(stored.rotations[static_cast<std::size_t>(elbow)], 1.0f);
  EXPECT_NEAR(-100.0f, glm::degrees(joint_angles(skeleton, elbow, at_peak).x), 1.0f);

  // The learning mode has it among the user's signs and plays its motion; a sentence signs it
  // between its other signs; the dictionary plays it (it has no notation to open).
  const auto word = read_json_file(j + "learn-word.json"), sentence = read_json_file(j + "learn-sentence.json"),
             dictionary = read_json_file(j + "dictionary.json");
  ASSERT_TRUE(word.is_object() && sentence.is_object() && dictionary.is_object());
  EXPECT_EQ("your signs", word["learning"]["topic"]);
  EXPECT_EQ("TESTWAVE", word["learning"]["title"]);
  EXPECT_NEAR(stored.duration, word["learning"]["duration"].get<float>(), 0.05f);
  std::vector<std::string> glosses;
  for (const auto& g : sentence["learning"]["glosses"]) glosses.push_back(g["gloss"]);
  ASSERT_EQ(2u, glosses.size()) << sentence["learning"].dump();
  EXPECT_EQ("HELLO", glosses[0]);
  EXPECT_EQ("TESTWAVE", glosses[1]);
  EXPECT_GT(sentence["learning"]["glosses"][1]["end"].get<float>() - sentence["learning"]["glosses"][1]["start"].get<float>(), 1.9f);
  EXPECT_EQ("TESTWAVE", dictionary["clip_sign_shown"]);
  EXPECT_NE(std::string::npos, dictionary["status"].get<std::string>().find("clip sign TESTWAVE")) << dictionary["status"];
  // Picked in the dictionary, the clip sign is opened in the timeline editor: its motion the source,
  // one bar as long as the clip, saved back under its gloss.
  EXPECT_EQ("TESTWAVE", dictionary["timeline"]["title"]);
  EXPECT_EQ("TESTWAVE", dictionary["timeline"]["clip_gloss"]);
  bool bar_found = false;
  for (const auto& b : dictionary["timeline"]["bars"])
    if (b["label"] == "TESTWAVE") {
      bar_found = true;
      EXPECT_NEAR(stored.duration, b["duration"].get<float>(), 0.05f);
    }
  EXPECT_TRUE(bar_found) << dictionary["timeline"].dump();

  // An output the exporter does not write is refused, naming why.
  EXPECT_NE(std::string::npos, bad["status"].get<std::string>().find("not exported")) << bad["status"];
  EXPECT_FALSE(fs::exists(j + "bad.xyz"));
  const auto image = gestura::test::read_png(shots + "/studio-timeline.png", 3);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(1280, image.width);
}

TEST(StudioTimelineUnderXvfb, TheFiguresSavedSkeletonRendersAndRetargetsAndABrokenFileLosesNothing) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const std::string broken = dir.write("broken.bvh", "HIERARCHY\nROOT hips\n{\n  OFFSET 0 zero 0\n");
  const auto r = run_studio(dir, db, "figure.txt",
                            "mode figure\n"
                            "figure-joint l_shoulder\n"
                            "figure-mirror\n"
                            "figure-joint r_wrist\n"
                            "figure-offset -0.05 -0.27 0\n"  // a longer forearm
                            "figure-limits x -40 30\n"
                            "figure-dh\n"
                            "figure-save " + j + "figure.bvh\n"
                            "figure-joint l_index1\n"
                            "figure-copy\n"
                            "dump " + j + "copied.json\n"
                            "undo\n"
                            "figure-load " + broken + "\n"
                            "dump " + j + "broken.json\n"
                            "figure-joint r_wrist\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-figure.png\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto copied = read_json_file(j + "copied.json"), after = read_json_file(j + "broken.json");
  ASSERT_TRUE(copied.is_object() && after.is_object());
  EXPECT_EQ("l_index1_copy", copied["figure"]["joint"]["name"]);
  const int joints = after["figure"]["joints"];
  EXPECT_EQ(copied["figure"]["joints"].get<int>() - 4, joints);  // the copy (index 1-3 and tip) undone
  // The broken file: a message naming it, the figure as it was.
  EXPECT_NE(std::string::npos, after["status"].get<std::string>().find("broken.bvh")) << after["status"];
  EXPECT_EQ(j + "figure.bvh", after["figure"]["file"]);
  // The saved skeleton is a BVH both commands accept.
  ASSERT_TRUE(fs::exists(j + "figure.bvh") && fs::exists(j + "figure.figure.json"));
  const auto render = run_command(gestura::test::cli_path() + " render " + j + "figure.bvh -o " + j + "render.png --size 320x180");
  ASSERT_EQ(0, render.status) << render.output;
  EXPECT_TRUE(gestura::test::read_png(j + "render.png", 3).loaded());
  const auto retarget = run_command(gestura::test::cli_path() + " retarget " + j + "figure.bvh --to " + j + "figure.bvh -o " + j + "moved.bvh");
  ASSERT_EQ(0, retarget.status) << retarget.output;
  const BvhFile saved = load_bvh(j + "figure.bvh");
  const int wrist = saved.skeleton.find("r_wrist");
  ASSERT_GE(wrist, 0);
  EXPECT_NEAR(-0.27f, saved.skeleton.rest_translations[static_cast<std::size_t>(wrist)].y, 1e-5f);
  const auto side = read_json_file(j + "figure.figure.json");
  EXPECT_NEAR(30.0f, side["joints"]["r_wrist"]["max_degrees"][0].get<float>(), 1e-3f);
  EXPECT_TRUE(side["joints"]["r_wrist"].contains("dh"));
}

TEST(StudioTimelineUnderXvfb, DraggingTheHandWithIkReachesTheTargetKeysThePoseAndUndoRestores) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  TempDir dir;
  const std::string db = dir.file("user.sqlite"), shots = shot_dir(dir), j = dir.file("");
  const auto r = run_studio(dir, db, "ik.txt",
                            "mode pose\n"
                            "pose-drag-by r_wrist 0.08 0.25 0.25\n"
                            "dump " + j + "dragged.json\n"
                            "pose-drag-by l_ankle 0 0.15 0.1\n"
                            "camera three-quarter\n"
                            "wait 2\n"
                            "screenshot " + shots + "/studio-ik.png\n"
                            "dump " + j + "foot.json\n"
                            "undo\n"
                            "undo\n"
                            "dump " + j + "undone.json\n"
                            "redo\n"
                            "key-pose 0.8\n"
                            "dump " + j + "keyed.json\n"
                            "quit\n");
  ASSERT_EQ(0, r.status) << r.output;
  const auto dragged = read_json_file(j + "dragged.json"), foot = read_json_file(j + "foot.json"), undone = read_json_file(j + "undone.json"),
             keyed = read_json_file(j + "keyed.json");
  ASSERT_TRUE(dragged.is_object() && foot.is_object() && undone.is_object() && keyed.is_object());
  const auto vec = [](const nlohmann::json& v) { return vec3(v[0].get<float>(), v[1].get<float>(), v[2].get<float>()); };
  const vec3 end = vec(dragged["ik"]["end"]), target = vec(dragged["ik"]["target"]);
  EXPECT_EQ("r_wrist", dragged["ik"]["end_joint"]);
  EXPECT_LT(glm::length(end - target), 0.01f) << dragged["ik"].dump();
  EXPECT_EQ("l_ankle", foot["ik"]["end_joint"]);
  EXPECT_LT(glm::length(vec(foot["ik"]["end"]) - vec(foot["ik"]["target"])), 0.01f) << foot["ik"].dump();
  // Undo (twice: the foot, the hand): the wrist is back where it started, 0.08, 0.25, 0.25 m away.
  const Skeleton s = build_avatar_skeleton();
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  const vec3 rest_wrist(model[static_cast<std::size_t>(s.find("r_wrist"))][3]);
  const vec3 rest_ankle(model[static_cast<std::size_t>(s.find("l_ankle"))][3]);
  EXPECT_LT(glm::length(target - vec3(0.08f, 0.25f, 0.25f) - rest_wrist), 1e-4f);
  EXPECT_LT(glm::length(vec(undone["ik"]["r_wrist"]) - rest_wrist), 1e-4f) << undone["ik"].dump();
  EXPECT_LT(glm::length(vec(undone["ik"]["l_ankle"]) - rest_ankle), 1e-4f) << undone["ik"].dump();
  // Keyed at 0.8 s: the arm's channels have a key there.
  const auto& channels = keyed["timeline"]["channels"];
  ASSERT_TRUE(channels.contains("r_elbow.x")) << channels.dump();
  EXPECT_NEAR(0.8f, channels["r_elbow.x"][0]["time"].get<float>(), 1e-4f);
  EXPECT_TRUE(channels.contains("r_shoulder.x") || channels.contains("r_shoulder.z"));
}

}  // namespace
}  // namespace gestura
