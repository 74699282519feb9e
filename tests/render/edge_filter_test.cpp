// The edge filter (render/edge_filter.hpp): smooths stair-stepped edges along their direction,
// leaves flat areas, gentle gradients and straight axis-aligned edges alone, and writes only
// inside the rectangle it is given.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "gestura/render/edge_filter.hpp"

namespace gestura {
namespace {

Image filled(int w, int h, std::uint8_t grey) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = grey, image.rgba[i + 3] = 255;
  return image;
}

void set_grey(Image& image, int x, int y, std::uint8_t grey) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = p[1] = p[2] = grey;
}

// White above a line of slope 1/3 (a staircase of 3-pixel steps), black below.
Image staircase(int w, int h) {
  Image image = filled(w, h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (y < h / 2 - 8 + x / 3) set_grey(image, x, y, 255);
  return image;
}

TEST(EdgeFilter, FlatImagesAndGentleGradientsKeepTheirBytes) {
  EdgeFilterScratch scratch;
  Image flat = filled(40, 30, 120);
  const Image flat_before = flat;
  smooth_edges(flat, {0, 0, 40, 30}, scratch);
  EXPECT_EQ(flat.rgba, flat_before.rgba);

  Image gradient = filled(64, 32, 0);  // one level per pixel across: shading, not an edge
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) set_grey(gradient, x, y, static_cast<std::uint8_t>(60 + x + y / 2));
  const Image gradient_before = gradient;
  smooth_edges(gradient, {0, 0, 64, 32}, scratch);
  EXPECT_EQ(gradient.rgba, gradient_before.rgba);
}

TEST(EdgeFilter, StraightAxisAlignedEdgesStayHard) {
  // Blending is along the edge, never across it: a vertical edge has nothing to smooth.
  Image image = filled(32, 32, 20);
  for (int y = 0; y < 32; ++y)
    for (int x = 16; x < 32; ++x) set_grey(image, x, y, 230);
  EdgeFilterScratch scratch;
  smooth_edges(image, {0, 0, 32, 32}, scratch);
  for (int y = 4; y < 28; ++y) {
    EXPECT_NEAR(image.pixel(15, y)[0], 20, 2) << y;
    EXPECT_NEAR(image.pixel(16, y)[0], 230, 2) << y;
  }
}

TEST(EdgeFilter, StaircaseEdgesGetIntermediateShadesNextToTheEdgeOnly) {
  const int w = 96, h = 64;
  const Image before = staircase(w, h);
  Image image = before;
  EdgeFilterScratch scratch;
  smooth_edges(image, {0, 0, w, h}, scratch);
  std::set<int> shades;
  int changed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      EXPECT_EQ(p[0], p[1]);  // grey stays grey
      EXPECT_EQ(p[3], 255);
      if (p[0] == before.pixel(x, y)[0]) continue;
      ++changed;
      shades.insert(p[0]);
      // Only pixels beside the edge change: the edge row at this column is h/2 - 8 + x/3.
      EXPECT_LE(std::abs(y - (h / 2 - 8 + x / 3)), 2) << x << "," << y;
    }
  EXPECT_GT(changed, w / 2);       // the steps are smoothed along the whole edge
  EXPECT_GE(shades.size(), 4u);    // a ramp of shades, not a second hard step
  for (int s : shades) EXPECT_TRUE(s > 0 && s < 255) << s;
}

TEST(EdgeFilter, WritesOnlyInsideItsRectangle) {
  const int w = 96, h = 64;
  const Image before = staircase(w, h);
  Image image = before;
  EdgeFilterScratch scratch;
  const ImageRect rect{30, 0, 60, h};
  smooth_edges(image, rect, scratch);
  int inside_changed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool changed = image.pixel(x, y)[0] != before.pixel(x, y)[0];
      if (x < rect.x0 || x >= rect.x1) EXPECT_FALSE(changed) << x << "," << y;
      else inside_changed += changed;
    }
  EXPECT_GT(inside_changed, 0);
}

TEST(EdgeFilter, RectanglesBeyondTheImageAreClippedAndEmptyOnesDoNothing) {
  Image image = staircase(20, 12);
  const Image before = image;
  EdgeFilterScratch scratch;
  smooth_edges(image, {5, 5, 5, 9}, scratch);
  smooth_edges(image, {30, 30, 40, 40}, scratch);
  EXPECT_EQ(image.rgba, before.rgba);
  smooth_edges(image, {-10, -10, 100, 100}, scratch);  // the whole image, image borders clamped
  EXPECT_NE(image.rgba, before.rgba);
  Image tiny = filled(1, 1, 7);
  smooth_edges(tiny, {0, 0, 1, 1}, scratch);
  EXPECT_EQ(tiny.pixel(0, 0)[0], 7);
}

}  // namespace
}  // namespace gestura
