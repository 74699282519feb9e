#pragma once
// Reading PNG files the renderer wrote, for tests that look at pixels (stb_image, compiled once).
#include <cstdint>
#include <string>
#include <vector>

namespace gestura::test {

struct PngPixels {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> data;  // rows top to bottom, `channels` bytes per pixel

  bool loaded() const { return !data.empty(); }
  // Contract: 0 <= x < width, 0 <= y < height.
  const std::uint8_t* at(int x, int y) const {
    return data.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                             static_cast<std::size_t>(channels);
  }
};

// The file's pixels converted to `channels` (3 = RGB, 4 = RGBA); empty when it cannot be read.
PngPixels read_png(const std::string& path, int channels);

}  // namespace gestura::test
