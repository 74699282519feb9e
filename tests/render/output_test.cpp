// Files the renderer writes: PNG and contact sheets decode, MP4/WebM/GIF have exactly the frames
// and frame rate asked for, bad options and unwritable paths fail clearly and leave no file.
#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>

#include "gestura/core/error.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/render_job.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/png_file.hpp"
#include "support/test_figure.hpp"
#include "gestura/render/video_writer.hpp"


namespace gestura {
namespace {

namespace fs = std::filesystem;

class RenderOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    unsetenv("DISPLAY");
    dir_ = fs::temp_directory_path() / ("gestura_render_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Nothing but `expected` (no temporaries) in the directory.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static const RenderSubject& figure() {
    static const RenderSubject subject = make_test_figure(1);
    return subject;
  }
  fs::path dir_;
};

struct StreamInfo {
  std::string codec;
  int frames = 0;  // packets counted by reading the whole file
  AVRational rate{0, 1};
  double duration = 0.0;
};

StreamInfo probe(const std::string& path) {
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return {};
  avformat_find_stream_info(format, nullptr);
  StreamInfo info;
  if (format->nb_streams == 1) {
    AVStream* s = format->streams[0];
    info.codec = avcodec_get_name(s->codecpar->codec_id);
    info.rate = s->r_frame_rate;
    AVPacket* packet = av_packet_alloc();
    while (av_read_frame(format, packet) >= 0) {
      ++info.frames;
      av_packet_unref(packet);
    }
    av_packet_free(&packet);
    if (format->duration > 0) info.duration = double(format->duration) / AV_TIME_BASE;
  }
  avformat_close_input(&format);
  return info;
}

RenderJob job(const std::string& output, int w = 160, int h = 96, int fps = 30) {
  RenderJob j;
  j.output = output;
  j.size = {w, h};
  j.fps = fps;
  return j;
}

TEST_F(RenderOutput, PngDecodesWithTheRequestedSize) {
  const std::string out = path("still.png");
  render_to_file(figure(), job(out, 200, 120));
  const test::PngPixels image = test::read_png(out, 4);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(image.width, 200);
  EXPECT_EQ(image.height, 120);
  EXPECT_EQ(files(), std::vector<std::string>{"still.png"});
}

TEST_F(RenderOutput, ContactSheetIsOnePngOfSixteenDifferentTiles) {
  const std::string out = path("sheet.png");
  RenderJob j = job(out, 320, 192);
  j.sheet = true;
  EXPECT_EQ(render_to_file(figure(), j).frames, 16);
  const test::PngPixels image = test::read_png(out, 4);
  ASSERT_TRUE(image.loaded());
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 192);
  // The first tile (rest) and the sixth (mid-wave) differ: the sheet walks through the clip.
  int differing = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 80; ++x) differing += image.at(x, y)[0] != image.at(80 + x, 48 + y)[0];
  EXPECT_GT(differing, 40);
}

TEST_F(RenderOutput, Mp4HasExactFrameCountAndRate) {
  const std::string out = path("clip.mp4");
  const RenderReport report = render_to_file(figure(), job(out, 160, 96, 25));
  EXPECT_EQ(report.frames, 51);  // 2 s at 25 fps, both ends included
  const StreamInfo info = probe(out);
  EXPECT_EQ(info.codec, "h264");
  EXPECT_EQ(info.frames, 51);
  EXPECT_EQ(info.rate.num, 25);
  EXPECT_EQ(info.rate.den, 1);
  EXPECT_EQ(files(), std::vector<std::string>{"clip.mp4"});
}

TEST_F(RenderOutput, WebmHasExactFrameCountAndRate) {
  const std::string out = path("clip.webm");
  RenderJob j = job(out, 160, 96, 12);
  render_to_file(figure(), j);
  const StreamInfo info = probe(out);
  EXPECT_EQ(info.codec, "vp9");
  EXPECT_EQ(info.frames, 25);
  EXPECT_EQ(info.rate.num, 12);
  EXPECT_EQ(info.rate.den, 1);
}

TEST_F(RenderOutput, GifDecodesFrameByFrame) {
  const std::string out = path("clip.gif");
  render_to_file(figure(), job(out, 120, 72, 10));
  const StreamInfo info = probe(out);
  EXPECT_EQ(info.codec, "gif");
  EXPECT_EQ(info.frames, 21);
  EXPECT_NEAR(info.duration, 2.1, 0.05);
}

TEST_F(RenderOutput, RestPoseVideoLastsTheRequestedSeconds) {
  const std::string out = path("rest.mp4");
  RenderSubject rest = make_test_figure(1);
  rest.clip.reset();
  RenderJob j = job(out, 160, 96, 10);
  j.rest_seconds = 0.5f;
  render_to_file(rest, j);
  EXPECT_EQ(probe(out).frames, 6);
}

TEST_F(RenderOutput, BadSizesAreClearErrors) {
  for (const ImageSize size : {ImageSize{0, 0}, ImageSize{100000, 100000}, ImageSize{15, 100}, ImageSize{4097, 100},
                               ImageSize{4096, 4096}}) {
    try {
      check_image_size(size);
      ADD_FAILURE() << size.width << "x" << size.height << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(size.width) + "x" + std::to_string(size.height)), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(check_image_size({4096, 2304}));
  EXPECT_THROW(validate(job(path("a.png"), 0, 0)), Error);
  RenderJob fast = job(path("a.gif"));
  fast.fps = 1000;
  EXPECT_THROW(validate(fast), Error);
  RenderJob msaa = job(path("a.png"));
  msaa.msaa_samples = 3;
  EXPECT_THROW(validate(msaa), Error);
}

TEST_F(RenderOutput, UnwritablePathsFailAndLeaveNothing) {
  for (const std::string& out : {path("missing/dir/out.png"), path("missing/dir/out.mp4"), path("missing/out.gif")}) {
    EXPECT_THROW(render_to_file(figure(), job(out)), Error) << out;
  }
  EXPECT_TRUE(files().empty());
  // A directory in the target's place.
  fs::create_directory(path("taken.png"));
  EXPECT_THROW(render_to_file(figure(), job(path("taken.png"))), Error);
  EXPECT_EQ(files(), std::vector<std::string>{"taken.png"});
}

// Runs `gestura ARGS` so that `dir` is read-only for it although the tests run as root (who writes
// into any directory whatever its permissions): first in a private mount namespace in which `dir`
// is bound onto itself read-only, else as the unprivileged user nobody with `dir` at mode 0555.
// Returns the run and how it was made read-only, or nullopt when neither can be set up here.
std::optional<std::pair<test::CliRun, std::string>> run_as_root_on_read_only(const std::string& dir, const std::string& args) {
  const std::string script = dir + ".sh";
  std::ofstream(script) << "mount --bind \"$1\" \"$1\" && mount -o remount,bind,ro \"$1\" || exit 97\n"
                           "touch \"$1/probe\" 2>/dev/null && exit 98\n"
                           "echo read-only-mount\n"
                           "exec \"$2\" " << args << "\n";
  test::CliRun mounted = test::run_command("unshare -m sh '" + script + "' '" + dir + "' '" + test::cli_path() + "'");
  std::filesystem::remove(script);
  if (mounted.output.rfind("read-only-mount\n", 0) == 0) return std::pair{mounted, std::string("read-only bind mount")};
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  test::CliRun nobody = test::run_command("setpriv --reuid=65534 --regid=65534 --clear-groups sh -c 'echo unprivileged; exec \"$0\" " +
                                          args + "' '" + test::cli_path() + "' '" + dir + "'");
  fs::permissions(dir, fs::perms::owner_all);
  // 126/127: nobody may not run the binary where this checkout lies.
  if (nobody.output.rfind("unprivileged\n", 0) == 0 && nobody.status != 126 && nobody.status != 127)
    return std::pair{nobody, std::string("user nobody")};
  return std::nullopt;
}

TEST_F(RenderOutput, ReadOnlyDirectoryFailsAndLeavesNothing) {
  fs::create_directory(path("ro"));
  if (::geteuid() != 0) {
    fs::permissions(path("ro"), fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(render_to_file(figure(), job(path("ro/out.webm"))), Error);
    fs::permissions(path("ro"), fs::perms::owner_all);
    EXPECT_TRUE(fs::is_empty(path("ro")));
    return;
  }
  const auto run = run_as_root_on_read_only(path("ro"), "render --rest --size 64x64 -o \"$1/out.webm\"");
  if (!run) GTEST_SKIP() << "as root, but neither a mount namespace (unshare -m) nor user nobody (setpriv) is available";
  const auto& [r, how] = *run;
  EXPECT_EQ(r.status, 1) << how << "\n" << r.output;
  EXPECT_NE(r.output.find("cannot write"), std::string::npos) << how << "\n" << r.output;
  EXPECT_NE(r.output.find("ro/out.webm"), std::string::npos) << how << "\n" << r.output;
  EXPECT_TRUE(fs::is_empty(path("ro"))) << how << ": nothing left behind";
}

TEST_F(RenderOutput, FailedVideoLeavesNoFileAndKeepsAnOldOne) {
  const std::string out = path("keep.mp4");
  std::ofstream(out) << "old";
  {
    VideoWriter writer(out, 64, 64, 30);
    writer.write(Image(64, 64));
    EXPECT_THROW(writer.write(Image(32, 32)), Error);
  }  // destroyed without finish(): abandoned
  EXPECT_EQ(files(), std::vector<std::string>{"keep.mp4"});
  EXPECT_EQ(fs::file_size(out), 3u);
}

TEST_F(RenderOutput, BadCombinationsAreRejectedBeforeRendering) {
  RenderJob sheet_video = job(path("a.mp4"));
  sheet_video.sheet = true;
  EXPECT_THROW(validate(sheet_video), Error);
  EXPECT_THROW(validate(job(path("a.mp4"), 161, 96)), Error);  // odd width for 4:2:0
  EXPECT_THROW(validate(job(path("a.avi"))), Error);
  EXPECT_THROW(validate(job("")), Error);
  EXPECT_NO_THROW(validate(job(path("a.gif"), 161, 97)));
  EXPECT_TRUE(files().empty());
}

TEST_F(RenderOutput, FrameCountIncludesBothEnds) {
  EXPECT_EQ(frame_count(2.0f, 30), 61);
  EXPECT_EQ(frame_count(0.0f, 30), 1);
  EXPECT_EQ(frame_count(1.0f / 3.0f, 30), 11);
}

TEST_F(RenderOutput, CommandLineRejectsBadFlagsWithoutWritingFiles) {
  const std::string out = path("cli.png");
  for (const char* flags : {"--size 0x0", "--size 100000x100000", "--size abc", "--fps 0", "--fps -1",
                                   "--fps 1000", "--camera nowhere", "--background '#12345'", "--color skin=blue",
                                   "--orbit 1,2", "--msaa 3"}) {
    const test::CliRun r = test::run_cli("render --rest -o " + out + " " + flags);
    EXPECT_EQ(r.status, 2) << flags << ": a usage error\n" << r.output;
  }
  const test::CliRun jpg = test::run_cli("render --rest -o " + path("x.jpg"));
  EXPECT_EQ(jpg.status, 2) << jpg.output;
  EXPECT_NE(jpg.output.find(".png, .gif, .mp4 or .webm"), std::string::npos) << "names what it writes: " << jpg.output;
  const test::CliRun unwritable = test::run_cli("render --rest -o " + path("no/such/dir/x.png"));
  EXPECT_EQ(unwritable.status, 1) << unwritable.output;
  EXPECT_NE(unwritable.output.find("no/such/dir/x.png"), std::string::npos) << unwritable.output;
  EXPECT_TRUE(files().empty());
  const test::CliRun both = test::run_cli("render --rest --size 64x64 --camera front,top -o " + out);
  EXPECT_EQ(both.status, 0) << both.output;
  EXPECT_EQ(files(), std::vector<std::string>{"cli.png"});
}

}  // namespace
}  // namespace gestura
