// The studio driven by the real mouse: synthetic X pointer events (xdotool) under a virtual X
// server instead of script actions. A timeline key dragged with the mouse moves the peak of the
// exported BVH to where it was dropped. Skipped where xvfb-run or xdotool is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gestura/io/bvh.hpp"
#include "lexicon/temp_dir.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/studio_under_xvfb.hpp"

namespace gestura {
namespace {

using gestura::test::have_xvfb;
using gestura::test::peak_time;
using gestura::test::read_json_file;
using gestura::test::run_command;
using gestura::testing::TempDir;


TEST(StudioMouseUnderXvfb, DraggingATimelineKeyWithTheMouseRetimesTheExport) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not installed";
  if (run_command("command -v xdotool").status != 0) GTEST_SKIP() << "xdotool not installed";
  TempDir dir;
  const std::string j = dir.file("");
  // The studio keys the elbow, says where key 1 is drawn, and waits until the mouse is done.
  const std::string script = dir.write("mouse.txt",
                                       "mode timeline\n"
                                       "key r_elbow.x 0 0\n"
                                       "key r_elbow.x 1.0 -100\n"
                                       "key r_elbow.x 2.0 0\n"
                                       "wait 3\n"
                                       "export-timeline " + j + "before.bvh\n"
                                       "where-key r_elbow.x 1 " + j + "key.txt\n"
                                       "wait-file " + j + "dragged\n"
                                       "wait 3\n"
                                       "export-timeline " + j + "after.bvh\n"
                                       "dump " + j + "after.json\n"
                                       "quit\n");
  // The mouse: press on the key, move 150 px left in steps (a frame or more apart), release.
  const std::string mouse = dir.write("mouse.sh",
                                      gestura::test::cli_path() + " studio " + j + "user.sqlite --size 1280x800 --script " + script + " &\n"
                                      "pid=$!\n"
                                      "for i in $(seq 900); do [ -s " + j + "key.txt ] && break; sleep 0.2; done\n"
                                      "read x y < " + j + "key.txt\n"
                                      "wid=$(xdotool search --sync --name 'gestura studio' | head -n 1)\n"
                                      "xdotool mousemove --window \"$wid\" \"$x\" \"$y\"; sleep 0.5\n"
                                      "xdotool mousedown 1; sleep 0.5\n"
                                      "for d in 30 60 90 120 150; do xdotool mousemove --window \"$wid\" $((x - d)) \"$y\"; sleep 0.4; done\n"
                                      "xdotool mouseup 1; sleep 0.5\n"
                                      "touch " + j + "dragged\n"
                                      "wait $pid\n");
  const auto r = run_command("timeout 300 xvfb-run -a -s '-screen 0 1400x900x24' sh " + mouse);
  ASSERT_EQ(0, r.status) << r.output;
  const auto after = read_json_file(j + "after.json");
  ASSERT_TRUE(after.is_object()) << r.output;
  const float dropped = after["timeline"]["channels"]["r_elbow.x"][1]["time"].get<float>();
  // The mouse moved the key (150 px of a timeline ~2 s wide is well over 0.2 s) and only in time.
  EXPECT_LT(dropped, 0.8f) << after["timeline"]["channels"]["r_elbow.x"].dump();
  EXPECT_GT(dropped, 0.0f);
  EXPECT_NEAR(-100.0f, after["timeline"]["channels"]["r_elbow.x"][1]["value"].get<float>(), 1e-3f);
  const BvhFile before = load_bvh(j + "before.bvh"), moved = load_bvh(j + "after.bvh");
  EXPECT_NEAR(1.0f, peak_time(before, "r_elbow"), 0.5f / 30.0f);
  EXPECT_NEAR(dropped, peak_time(moved, "r_elbow"), 0.5f / 30.0f + 1e-3f);
}

}  // namespace
}  // namespace gestura
