// The interactive viewer runs under a virtual X server and shows the figure: a scripted
// screenshot of its window (after 10 frames) has the figure in the middle and background at the
// corners. Skipped where xvfb-run is not installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/cli.hpp"
#include "support/png_file.hpp"
#include "support/build_paths.hpp"


namespace {

namespace fs = std::filesystem;
using gestura::test::run_command;

TEST(RenderViewer, ScreenshotUnderXvfbShowsTheFigure) {
  if (run_command("command -v xvfb-run").status != 0) GTEST_SKIP() << "xvfb-run not installed";
  const fs::path shot = fs::temp_directory_path() / ("gestura_view_" + std::to_string(::getpid()) + ".png");
  const gestura::test::CliRun view =
      run_command(std::string("timeout 60 xvfb-run -a ") + gestura::test::cli_path() +
                  " view --rest --size 320x240 --background '#808080' --frames 10 --screenshot " + shot.string());
  ASSERT_EQ(view.status, 0) << view.output;
  const gestura::test::PngPixels image = gestura::test::read_png(shot.string(), 3);
  fs::remove(shot);
  ASSERT_TRUE(image.loaded());
  const int w = image.width, h = image.height;
  EXPECT_EQ(w, 320);
  EXPECT_EQ(h, 240);
  auto is_background = [&](int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return std::abs(p[0] - 128) <= 1 && std::abs(p[1] - 128) <= 1 && std::abs(p[2] - 128) <= 1;
  };
  EXPECT_TRUE(is_background(0, 0));
  EXPECT_TRUE(is_background(w - 1, h - 1));
  int figure = 0;
  for (int y = 0; y < h; ++y) figure += !is_background(w / 2, y);
  EXPECT_GT(figure, h / 2) << "the body runs down the middle column";
}

}  // namespace
