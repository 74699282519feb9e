// RGBA → YUV 4:2:0 (render/yuv420.hpp): BT.601 studio-range values for known colours (the
// standard's table: black 16/128/128, white 235/128/128, red 81/90/240, green 145/54/34, blue
// 41/240/110, ±1 for rounding), chroma as the 2×2 block's mean, odd sizes, and strides.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "gestura/render/yuv420.hpp"

namespace gestura {
namespace {

struct Planes {
  int w, h, cw, ch, stride_pad;
  std::vector<std::uint8_t> y, u, v;
  Planes(int width, int height, int pad = 0)
      : w(width), h(height), cw((width + 1) / 2), ch((height + 1) / 2), stride_pad(pad),
        y(static_cast<std::size_t>((w + pad) * h), 0xEE), u(static_cast<std::size_t>((cw + pad) * ch), 0xEE),
        v(static_cast<std::size_t>((cw + pad) * ch), 0xEE) {}
  Yuv420Planes planes() { return {y.data(), u.data(), v.data(), w + stride_pad, cw + stride_pad, cw + stride_pad}; }
  int Y(int x, int yy) const { return y[static_cast<std::size_t>(yy * (w + stride_pad) + x)]; }
  int U(int x, int yy) const { return u[static_cast<std::size_t>(yy * (cw + stride_pad) + x)]; }
  int V(int x, int yy) const { return v[static_cast<std::size_t>(yy * (cw + stride_pad) + x)]; }
};

Image filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    image.rgba[i] = r, image.rgba[i + 1] = g, image.rgba[i + 2] = b, image.rgba[i + 3] = 255;
  return image;
}

TEST(Yuv420, KnownColoursGetBt601StudioRangeValues) {
  struct Case {
    std::uint8_t r, g, b;
    int y, u, v;
  };
  const Case cases[] = {{0, 0, 0, 16, 128, 128},     {255, 255, 255, 235, 128, 128}, {255, 0, 0, 81, 90, 240},
                        {0, 255, 0, 145, 54, 34},    {0, 0, 255, 41, 240, 110},      {128, 128, 128, 126, 128, 128}};
  for (const Case& c : cases) {
    Planes p(8, 4);
    rgba_to_yuv420(filled(8, 4, c.r, c.g, c.b), p.planes());
    for (int yy = 0; yy < 4; ++yy)
      for (int x = 0; x < 8; ++x) EXPECT_NEAR(p.Y(x, yy), c.y, 1) << int(c.r) << "," << int(c.g) << "," << int(c.b);
    for (int yy = 0; yy < 2; ++yy)
      for (int x = 0; x < 4; ++x) {
        EXPECT_NEAR(p.U(x, yy), c.u, 1) << int(c.r) << "," << int(c.g) << "," << int(c.b);
        EXPECT_NEAR(p.V(x, yy), c.v, 1) << int(c.r) << "," << int(c.g) << "," << int(c.b);
      }
  }
}

TEST(Yuv420, ChromaIsTheMeanOfEachTwoByTwoBlockAndLumaStaysPerPixel) {
  // Left column of each 2×2 block blue, right column black: luma alternates, chroma is half blue.
  Image image = filled(6, 2, 0, 0, 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 6; x += 2) image.pixel(x, y)[2] = 255;
  Planes p(6, 2);
  rgba_to_yuv420(image, p.planes());
  for (int x = 0; x < 6; ++x) EXPECT_NEAR(p.Y(x, 0), x % 2 == 0 ? 41 : 16, 1);
  for (int x = 0; x < 3; ++x) {
    EXPECT_NEAR(p.U(x, 0), (240 + 128) / 2, 1);  // the mean colour (0, 0, 127.5)
    EXPECT_NEAR(p.V(x, 0), (110 + 128) / 2, 1);
  }
}

TEST(Yuv420, OddSizesAndPaddedStridesWriteEverySampleAndNothingElse) {
  const Image image = filled(5, 3, 255, 0, 0);
  Planes p(5, 3, 7);
  rgba_to_yuv420(image, p.planes());
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) EXPECT_NEAR(p.Y(x, y), 81, 1);
    for (int x = 5; x < 12; ++x) EXPECT_EQ(p.Y(x, y), 0xEE) << "padding written at " << x;
  }
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      EXPECT_NEAR(p.U(x, y), 90, 1);
      EXPECT_NEAR(p.V(x, y), 240, 1);
    }
    for (int x = 3; x < 10; ++x) {
      EXPECT_EQ(p.U(x, y), 0xEE);
      EXPECT_EQ(p.V(x, y), 0xEE);
    }
  }
}

}  // namespace
}  // namespace gestura
