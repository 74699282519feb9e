#pragma once
// An 8-bit RGBA image, rows top to bottom: what the renderer reads back and the writers consume.
#include <cstdint>
#include <span>
#include <vector>

namespace gestura {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0) {}
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// A contact sheet: `frames` (all the same size) tiled row by row into `columns` columns.
Image contact_sheet(std::span<const Image> frames, int columns);
// Box-filters `image` down by an integer factor (>= 1) — thumbnails for contact sheets.
Image downsample(const Image& image, int factor);

}  // namespace gestura
