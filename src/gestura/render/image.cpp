#include "gestura/render/image.hpp"

#include <algorithm>
#include <cstring>

#include "gestura/core/error.hpp"

namespace gestura {

Image contact_sheet(std::span<const Image> frames, int columns) {
  if (frames.empty() || columns <= 0) throw Error("contact sheet: no frames");
  const int w = frames[0].width, h = frames[0].height;
  const int rows = (static_cast<int>(frames.size()) + columns - 1) / columns;
  Image sheet(w * columns, h * rows);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].width != w || frames[i].height != h) throw Error("contact sheet: frames differ in size");
    const int x0 = static_cast<int>(i) % columns * w, y0 = static_cast<int>(i) / columns * h;
    for (int y = 0; y < h; ++y) std::memcpy(sheet.pixel(x0, y0 + y), frames[i].pixel(0, y), static_cast<std::size_t>(w) * 4);
  }
  return sheet;
}

Image downsample(const Image& image, int factor) {
  if (factor <= 1) return image;
  Image out(std::max(1, image.width / factor), std::max(1, image.height / factor));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      unsigned sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = image.pixel(std::min(x * factor + dx, image.width - 1), std::min(y * factor + dy, image.height - 1));
          for (int c = 0; c < 4; ++c) sum[c] += p[c];
        }
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = static_cast<std::uint8_t>(sum[c] / static_cast<unsigned>(factor * factor));
    }
  return out;
}

}  // namespace gestura
