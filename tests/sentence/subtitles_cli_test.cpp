// gestura subtitles end to end: a 2-cue SRT becomes a video as long as the programme; malformed
// subtitles and bad options exit 1 naming the problem, leaving no output.
extern "C" {
#include <libavformat/avformat.h>
}

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "support/cli.hpp"

namespace fs = std::filesystem;

namespace {

using gestura::test::CliRun;

CliRun subtitles(const std::string& args) { return gestura::test::run_cli("subtitles " + args); }

class SubtitlesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gestura_subtitles_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& content) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

int count_video_frames(const std::string& path) {
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return -1;
  avformat_find_stream_info(format, nullptr);
  int frames = 0;
  AVPacket* packet = av_packet_alloc();
  while (av_read_frame(format, packet) >= 0) {
    ++frames;
    av_packet_unref(packet);
  }
  av_packet_free(&packet);
  avformat_close_input(&format);
  return frames;
}

}  // namespace

TEST_F(SubtitlesCli, MalformedSubtitlesExitOneWithThePlace) {
  const std::string out = path("out.mp4");
  const CliRun bad_time = subtitles(file("a.srt", "1\n00:00:01,000 --> 00:00:0x,000\nHello\n") + " -o " + out);
  EXPECT_EQ(bad_time.status, 1);
  EXPECT_NE(bad_time.output.find("a.srt:2:18: bad end time '00:00:0x,000'"), std::string::npos) << bad_time.output;
  const CliRun no_header = subtitles(file("b.vtt", "00:01.000 --> 00:02.000\nHi\n") + " -o " + out);
  EXPECT_EQ(no_header.status, 1);
  EXPECT_NE(no_header.output.find("b.vtt:1:1: expected the 'WEBVTT' header"), std::string::npos) << no_header.output;
  const CliRun binary = subtitles(file("c.srt", std::string("\x7f" "ELF\x02\x01\x01\0\0", 9)) + " -o " + out);
  EXPECT_EQ(binary.status, 1);
  EXPECT_NE(binary.output.find("c.srt:1:1: binary data"), std::string::npos) << binary.output;
  const CliRun empty = subtitles(file("d.srt", "\n\n") + " -o " + out);
  EXPECT_EQ(empty.status, 1);
  EXPECT_NE(empty.output.find("no subtitle cues"), std::string::npos) << empty.output;
  const CliRun missing = subtitles(path("none.srt") + " -o " + out);
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("none.srt"), std::string::npos) << missing.output;
  std::string words;
  for (int i = 0; i < 4000; ++i) words += "word ";
  const CliRun too_long = subtitles(file("e.srt", "1\n00:00:01,000 --> 00:00:05,000\n" + words + "\n") + " -o " + out);
  EXPECT_EQ(too_long.status, 1);
  EXPECT_NE(too_long.output.find("e.srt:2: cue 1: text too long"), std::string::npos) << too_long.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(SubtitlesCli, BadOptionsExitTwo) {
  const std::string srt = file("ok.srt", "1\n00:00:01,000 --> 00:00:02,000\nHello\n");
  for (const std::string& flags :
       {std::string("-o ") + path("x.gif"), std::string("-o ") + path("x.mp4") + " --max-speed 3",
        std::string("-o ") + path("x.mp4") + " --max-speed fast", std::string("-o ") + path("x.mp4") + " --size 321x240",
        std::string("-o ") + path("x.mp4") + " --fps 0", std::string("-o ") + path("x.mp4") + " --bogus",
        std::string("")}) {
    const CliRun r = subtitles(srt + " " + flags);
    EXPECT_EQ(r.status, 2) << flags << "\n" << r.output;
    EXPECT_NE(r.output.find("gestura subtitles: "), std::string::npos) << r.output;
  }
  const CliRun unknown_ext = subtitles(file("x.txt", "hello") + " -o " + path("x.mp4"));
  EXPECT_EQ(unknown_ext.status, 2);
  EXPECT_NE(unknown_ext.output.find(".srt or .vtt"), std::string::npos) << unknown_ext.output;
}

TEST_F(SubtitlesCli, RendersTwoCuesToAVideoAsLongAsTheProgramme) {
  const std::string srt = file("two.srt",
                               "1\r\n00:00:00,500 --> 00:00:03,500\r\nHello.\r\n\r\n"
                               "2\r\n00:00:04,000 --> 00:00:07,000\r\n<i>Thank you.</i>\r\n");
  const std::string out = path("two.mp4");
  const CliRun r = subtitles(srt + " -o " + out + " --size 320x240 --fps 10");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 cues, 0 not fitted; programme 7.00 s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("HELLO"), std::string::npos) << r.output;
  EXPECT_EQ(count_video_frames(out), 71);  // 7 s at 10 fps, both ends included
}
