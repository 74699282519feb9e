#include "gestura/render/yuv420.hpp"

#include <algorithm>

namespace gestura {
namespace {

// BT.601 with 8 fractional bits (the usual integer form: Y = 16 + (66R + 129G + 25B) / 256, …).
inline std::uint8_t luma(int r, int g, int b) { return static_cast<std::uint8_t>(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16); }

// From the sums of four pixels' channels: the mean colour's chroma, rounded.
inline std::uint8_t chroma_u(int r4, int g4, int b4) {
  return static_cast<std::uint8_t>(((-38 * r4 - 74 * g4 + 112 * b4 + 512) >> 10) + 128);
}
inline std::uint8_t chroma_v(int r4, int g4, int b4) {
  return static_cast<std::uint8_t>(((112 * r4 - 94 * g4 - 18 * b4 + 512) >> 10) + 128);
}

// One row of Y. Plain loops over bytes with no branches: the compiler vectorises them.
void luma_row(const std::uint8_t* __restrict rgba, std::uint8_t* __restrict y, int width) {
  for (int x = 0; x < width; ++x) y[x] = luma(rgba[4 * x], rgba[4 * x + 1], rgba[4 * x + 2]);
}

// One row of U and V from two image rows (`below` may be `above` for an odd last row), pairs of
// pixels; an odd last column pairs with itself.
void chroma_row(const std::uint8_t* __restrict above, const std::uint8_t* __restrict below, std::uint8_t* __restrict u,
                std::uint8_t* __restrict v, int width) {
  const int pairs = width / 2;
  for (int i = 0; i < pairs; ++i) {
    const std::uint8_t* a = above + 8 * i;
    const std::uint8_t* b = below + 8 * i;
    const int r = a[0] + a[4] + b[0] + b[4], g = a[1] + a[5] + b[1] + b[5], bl = a[2] + a[6] + b[2] + b[6];
    u[i] = chroma_u(r, g, bl);
    v[i] = chroma_v(r, g, bl);
  }
  if (width % 2 != 0) {
    const std::uint8_t* a = above + 4 * (width - 1);
    const std::uint8_t* b = below + 4 * (width - 1);
    const int r = 2 * (a[0] + b[0]), g = 2 * (a[1] + b[1]), bl = 2 * (a[2] + b[2]);
    u[pairs] = chroma_u(r, g, bl);
    v[pairs] = chroma_v(r, g, bl);
  }
}

}  // namespace

void rgba_to_yuv420(const Image& image, const Yuv420Planes& out) {
  const int w = image.width, h = image.height;
  for (int y = 0; y < h; ++y) luma_row(image.pixel(0, y), out.y + static_cast<std::ptrdiff_t>(y) * out.y_stride, w);
  for (int cy = 0; cy < (h + 1) / 2; ++cy) {
    const std::uint8_t* above = image.pixel(0, 2 * cy);
    const std::uint8_t* below = image.pixel(0, std::min(2 * cy + 1, h - 1));
    chroma_row(above, below, out.u + static_cast<std::ptrdiff_t>(cy) * out.u_stride,
               out.v + static_cast<std::ptrdiff_t>(cy) * out.v_stride, w);
  }
}

}  // namespace gestura
