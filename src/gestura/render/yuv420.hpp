#pragma once
// RGBA → YUV 4:2:0 (planar, 8 bit), BT.601 "studio" range — what H.264 and VP9 players assume for
// an untagged stream (swscale's default for the same conversion). Y per pixel; U and V per 2×2
// block from the block's mean colour. Done here rather than through swscale: on a 1280×720 frame
// swscale's general scaler pipeline cost about 3 ms, a sixth of the encoder's time (bench R1),
// for what is a fixed linear map plus a 2×2 average.
#include <cstdint>

#include "gestura/render/image.hpp"

namespace gestura {

// The destination planes, each with its own stride in bytes (as AVFrame gives them).
struct Yuv420Planes {
  std::uint8_t* y;
  std::uint8_t* u;
  std::uint8_t* v;
  int y_stride, u_stride, v_stride;
};

// Converts `image` (any size; an odd last row or column is averaged with itself) into `out`,
// whose Y plane holds image.width × image.height and U, V planes ⌈width/2⌉ × ⌈height/2⌉ samples.
void rgba_to_yuv420(const Image& image, const Yuv420Planes& out);

}  // namespace gestura
