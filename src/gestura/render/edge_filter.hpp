#pragma once
// Edge smoothing for frames drawn with one sample per pixel, after the console variant of FXAA
// (Lottes 2009/2011): the luma of the four 2×2 blocks around a pixel gives the local gradient;
// where the contrast passes a threshold the pixel becomes the average of the image sampled along
// the edge (perpendicular to the gradient) — two taps, or four when their mean stays inside the
// neighbourhood's luma range (otherwise a thin feature would be washed out). Pixels without an
// edge keep their bytes exactly, so smooth shading is untouched.
//
// Done on the CPU over the read-back image: on llvmpipe the same filter as a GL pass cost as much
// as 4× multisampling, and here it only visits the rectangle where the figure is (bench R1).
#include <cstdint>
#include <vector>

#include "gestura/render/image.hpp"

namespace gestura {

// A rectangle of image pixels, origin top-left, half-open [x0, x1) × [y0, y1).
struct ImageRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Buffers reused from frame to frame (no allocation per frame once grown).
struct EdgeFilterScratch {
  std::vector<std::uint8_t> source;  // the pixels read: the rectangle grown by the filter's reach
  std::vector<std::uint8_t> luma;    // their luma, 8 bit (for the pre-test only)
  std::vector<std::uint8_t> row_min, row_max;  // per pixel: the smallest / largest luma of it and its row neighbours
  std::vector<std::uint8_t> range;             // one row: the luma range of each pixel's 3×3 neighbourhood
};

// Smooths the edges of `image` inside `rect` (clipped to the image); reads up to 6 pixels beyond it.
void smooth_edges(Image& image, ImageRect rect, EdgeFilterScratch& scratch);

}  // namespace gestura
