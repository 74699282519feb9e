// Commands that make motion show it: `gestura view` performs a sign from HamNoSys (a scripted
// screenshot under Xvfb shows the raised hand's skin in front of the dark shirt, where the figure at
// rest shows none), `gestura reach -o` writes a video with one frame per motion frame, and an output
// extension nobody writes is a clear error that leaves no file.
#include <gtest/gtest.h>
extern "C" {
#include <libavformat/avformat.h>
}

#include <filesystem>
#include <string>

#include <unistd.h>

#include "support/cli.hpp"
#include "support/png_file.hpp"
#include "support/build_paths.hpp"


namespace {

namespace fs = std::filesystem;

using gestura::test::CliRun;
using gestura::test::run_cli;
using gestura::test::run_command;

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("gestura_motion_output_" + std::to_string(::getpid()) + "_" + name);
}

constexpr const char* kFlatHandAtChest = "hamflathand,hamextfingeru,hampalml,hamchest";

// Skin-coloured pixels (warm: red over green over blue by a margin; not the grey background, not
// the slate shirt) in the chest band below the neck: rows 45%..75%, middle half of the columns.
// Measured on 320x240 shots: 451 with the flat hand at the chest, 0 at rest.
int skin_pixels_at_chest(const std::string& png) {
  const gestura::test::PngPixels image = gestura::test::read_png(png, 3);
  if (!image.loaded()) return -1;
  const int w = image.width, h = image.height;
  int skin = 0;
  for (int y = h * 45 / 100; y < h * 3 / 4; ++y)
    for (int x = w / 4; x < w * 3 / 4; ++x) {
      const std::uint8_t* p = image.at(x, y);
      skin += p[0] > 90 && p[0] > p[1] + 15 && p[1] > p[2] && p[0] > p[2] + 35;
    }
  return skin;
}

TEST(MotionOutputCli, ViewPerformsASignFromSymbolNames) {
  if (run_command("command -v xvfb-run").status != 0) GTEST_SKIP() << "xvfb-run not installed";
  // The middle of the sign, from the same synthesis as `gestura sign` reports it.
  const fs::path json = temp_file("sign.json");
  const CliRun sign = run_cli(std::string("sign --names ") + kFlatHandAtChest + " -o " + json.string());
  fs::remove(json);
  ASSERT_EQ(sign.status, 0) << sign.output;
  const auto at = sign.output.find("(sign ");
  ASSERT_NE(at, std::string::npos) << sign.output;
  const float sign_start = std::stof(sign.output.substr(at + 6));
  const float sign_end = std::stof(sign.output.substr(sign.output.find("–", at) + std::string("–").size()));
  ASSERT_LT(sign_start, sign_end) << sign.output;

  auto screenshot = [](const std::string& what, const std::string& name) {
    const fs::path shot = temp_file(name);
    const CliRun r = run_command(std::string("timeout 120 xvfb-run -a ") + gestura::test::cli_path() + " view " + what +
                                 " --size 320x240 --background '#808080' --frames 3 --screenshot " + shot.string());
    EXPECT_EQ(r.status, 0) << r.output;
    const int skin = skin_pixels_at_chest(shot.string());
    fs::remove(shot);
    return skin;
  };
  const int signing = screenshot("--names " + std::string(kFlatHandAtChest) + " --at " +
                                     std::to_string(0.5f * (sign_start + sign_end)), "sign.png");
  const int resting = screenshot("--rest", "rest.png");
  ASSERT_GE(resting, 0);
  EXPECT_GT(signing, 150) << "the hand at the chest is skin in front of the shirt";
  EXPECT_GT(signing, 4 * resting + 100);
}

TEST(MotionOutputCli, ViewSignsEnglishText) {
  if (run_command("command -v xvfb-run").status != 0) GTEST_SKIP() << "xvfb-run not installed";
  // NAME is signed with both H hands in front of the chest: find when from say's timeline, then
  // look there.
  const CliRun timeline = run_cli("say 'My name'");
  ASSERT_EQ(timeline.status, 0) << timeline.output;
  const auto line = timeline.output.find("NAME");
  ASSERT_NE(line, std::string::npos) << timeline.output;
  const std::string row = timeline.output.substr(timeline.output.rfind('\n', line) + 1);
  const float start = std::stof(row), end = std::stof(row.substr(row.find("–") + std::string("–").size()));
  const fs::path shot = temp_file("text.png");
  const CliRun r = run_command(std::string("timeout 120 xvfb-run -a ") + gestura::test::cli_path() + " view 'My name' --at " +
                               std::to_string(0.5f * (start + end)) +
                               " --size 320x240 --background '#808080' --frames 3 --screenshot " + shot.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_GT(skin_pixels_at_chest(shot.string()), 150) << "the hands in front of the chest";
  fs::remove(shot);
  // A name that looks like a motion file is read as one (and fails clearly when it is missing).
  const CliRun missing = run_cli("view no-such-clip.bvh --screenshot /dev/null");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("no-such-clip.bvh"), std::string::npos) << missing.output;
}

TEST(MotionOutputCli, ViewRejectsABadSignAndTwoSubjects) {
  const CliRun bad = run_cli("view --names hamflathand,hamnotasymbol --screenshot /dev/null");
  EXPECT_EQ(bad.status, 1) << "bad notation is bad input";
  EXPECT_NE(bad.output.find("hamnotasymbol"), std::string::npos) << bad.output;
  const CliRun both = run_cli("view --rest --names hamflathand --screenshot /dev/null");
  EXPECT_EQ(both.status, 2) << "a usage error";
  EXPECT_NE(both.output.find("show one thing"), std::string::npos) << both.output;
}

int video_frames(const std::string& path) {
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return -1;
  int frames = 0;
  AVPacket* packet = av_packet_alloc();
  while (av_read_frame(format, packet) >= 0) {
    frames += format->streams[packet->stream_index]->codecpar->codec_type == AVMEDIA_TYPE_VIDEO;
    av_packet_unref(packet);
  }
  av_packet_free(&packet);
  avformat_close_input(&format);
  return frames;
}

TEST(MotionOutputCli, ReachWritesAVideoWithOneFramePerMotionFrame) {
  const fs::path video = temp_file("reach.mp4");
  const CliRun r =
      run_cli("reach --target 0.25,1.2,0.35 --frames 12 --fps 24 --size 160x120 -o " + video.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(video_frames(video.string()), 13) << r.output;  // frames 0..12 of the motion
  fs::remove(video);
}

TEST(MotionOutputCli, UnknownOutputExtensionIsAClearErrorAndWritesNothing) {
  const fs::path out = temp_file("reach.avi");
  const CliRun reach = run_cli("reach --target 0.25,1.2,0.35 -o " + out.string());
  EXPECT_EQ(reach.status, 2) << "a usage error";
  EXPECT_NE(reach.output.find(out.string() + ": cannot write"), std::string::npos) << reach.output;
  EXPECT_NE(reach.output.find(".mp4"), std::string::npos) << "lists what it can write: " << reach.output;
  EXPECT_FALSE(fs::exists(out));
  const CliRun sign = run_cli(std::string("sign --names ") + kFlatHandAtChest + " -o " + out.string());
  EXPECT_EQ(sign.status, 2) << "a usage error";
  EXPECT_NE(sign.output.find("cannot write"), std::string::npos) << sign.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
