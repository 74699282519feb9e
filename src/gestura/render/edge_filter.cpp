#include "gestura/render/edge_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace gestura {
namespace {

// How far the filter reads from a pixel it writes: the longest tap (half of the 8-pixel span)
// plus the bilinear footprint, rounded up.
constexpr int kReach = 6;
constexpr float kSpanMax = 8.0f;              // pixels along the edge, at most
constexpr float kContrastMin = 1.0f / 24.0f;  // luma range below which nothing is an edge
constexpr float kContrastRelative = 0.125f;   // … or below this part of the brightest luma
constexpr float kReduceMul = 1.0f / 8.0f, kReduceMin = 1.0f / 128.0f;
// The pre-test works on an 8-bit luma, (77R + 150G + 29B + 128) >> 8, within 0.96 of 255 × the
// filter's own luma (coefficient error at most 0.45 of a level, rounding 0.5); so a 3×3 range of
// at most 8 levels is, in the filter's luma, below 8 + 2 × 0.96 < 255 × kContrastMin (10.6): no
// edge. Bytes rather than floats: a quarter of the memory traffic, 32 lanes per AVX2 instruction.
constexpr std::uint8_t kMaxRangeWithoutEdge = 8;
constexpr int kRun = 32;  // pixels tested together before any is looked at alone

struct Rgb {
  float r, g, b;
};
Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
Rgb operator*(float s, Rgb a) { return {s * a.r, s * a.g, s * a.b}; }
float luma_of(Rgb c) { return (0.299f * c.r + 0.587f * c.g + 0.114f * c.b) * (1.0f / 255.0f); }

// The copied region: `width`×`height` pixels whose top-left pixel is (x0, y0) in the image.
struct Region {
  const std::uint8_t* pixels;
  int x0, y0, width, height;
  int cx(int x) const { return std::clamp(x - x0, 0, width - 1); }
  int cy(int y) const { return std::clamp(y - y0, 0, height - 1); }
  const std::uint8_t* at(int x, int y) const { return pixels + (static_cast<std::size_t>(cy(y)) * width + cx(x)) * 4; }
  float luma_at(int x, int y) const {
    const std::uint8_t* p = at(x, y);
    return (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) * (1.0f / 255.0f);
  }
  Rgb rgb_at(int x, int y) const {
    const std::uint8_t* p = at(x, y);
    return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
  }
  // Bilinear at (x, y) in pixel-centre coordinates (pixel (i, j)'s centre is (i, j)).
  Rgb sample(float x, float y) const {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const float tx = x - fx, ty = y - fy;
    const Rgb top = (1.0f - tx) * rgb_at(ix, iy) + tx * rgb_at(ix + 1, iy);
    const Rgb bottom = (1.0f - tx) * rgb_at(ix, iy + 1) + tx * rgb_at(ix + 1, iy + 1);
    return (1.0f - ty) * top + ty * bottom;
  }
};

// The filtered colour of pixel (x, y); `changed` is false (and the colour its own) below the
// contrast threshold.
Rgb filter_pixel(const Region& r, int x, int y, bool& changed) {
  const float m = r.luma_at(x, y);
  const float n = r.luma_at(x, y - 1), s = r.luma_at(x, y + 1), w = r.luma_at(x - 1, y), e = r.luma_at(x + 1, y);
  // The four 2×2 blocks' mean luma (what bilinear taps at the pixel's corners read).
  const float nw = 0.25f * (r.luma_at(x - 1, y - 1) + n + w + m), ne = 0.25f * (n + r.luma_at(x + 1, y - 1) + m + e);
  const float sw = 0.25f * (w + m + r.luma_at(x - 1, y + 1) + s), se = 0.25f * (m + e + s + r.luma_at(x + 1, y + 1));
  const float lo = std::min({m, nw, ne, sw, se}), hi = std::max({m, nw, ne, sw, se});
  changed = hi - lo >= std::max(kContrastMin, hi * kContrastRelative);
  if (!changed) return r.rgb_at(x, y);
  // Along the edge: perpendicular to the gradient ((ne + se) - (nw + sw), (sw + se) - (nw + ne)).
  float ax = (nw + ne) - (sw + se), ay = (ne + se) - (nw + sw);
  const float reduce = std::max((nw + ne + sw + se) * 0.25f * kReduceMul, kReduceMin);
  const float scale = 1.0f / (std::min(std::abs(ax), std::abs(ay)) + reduce);
  ax = std::clamp(ax * scale, -kSpanMax, kSpanMax), ay = std::clamp(ay * scale, -kSpanMax, kSpanMax);
  const float fx = static_cast<float>(x), fy = static_cast<float>(y);
  const Rgb two = 0.5f * (r.sample(fx - ax / 6.0f, fy - ay / 6.0f) + r.sample(fx + ax / 6.0f, fy + ay / 6.0f));
  const Rgb four = 0.5f * two + 0.25f * (r.sample(fx - ax * 0.5f, fy - ay * 0.5f) + r.sample(fx + ax * 0.5f, fy + ay * 0.5f));
  const float l = luma_of(four);
  return l < lo || l > hi ? two : four;
}

std::uint8_t to_byte(float v) { return static_cast<std::uint8_t>(std::clamp(v + 0.5f, 0.0f, 255.0f)); }

}  // namespace

void smooth_edges(Image& image, ImageRect rect, EdgeFilterScratch& scratch) {
  rect = {std::max(rect.x0, 0), std::max(rect.y0, 0), std::min(rect.x1, image.width), std::min(rect.y1, image.height)};
  if (rect.x1 <= rect.x0 || rect.y1 <= rect.y0) return;
  const int gx0 = std::max(0, rect.x0 - kReach), gy0 = std::max(0, rect.y0 - kReach);
  const int gx1 = std::min(image.width, rect.x1 + kReach), gy1 = std::min(image.height, rect.y1 + kReach);
  const int w = gx1 - gx0, h = gy1 - gy0;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  scratch.source.resize(count * 4);
  scratch.luma.resize(count);
  scratch.row_min.resize(count);
  scratch.row_max.resize(count);
  for (int y = 0; y < h; ++y) {
    std::memcpy(&scratch.source[static_cast<std::size_t>(y) * w * 4], image.pixel(gx0, gy0 + y), static_cast<std::size_t>(w) * 4);
    const std::uint8_t* p = &scratch.source[static_cast<std::size_t>(y) * w * 4];
    std::uint8_t* l = &scratch.luma[static_cast<std::size_t>(y) * w];
    for (int x = 0; x < w; ++x)
      l[x] = static_cast<std::uint8_t>((77 * p[4 * x] + 150 * p[4 * x + 1] + 29 * p[4 * x + 2] + 128) >> 8);
    std::uint8_t* lo = &scratch.row_min[static_cast<std::size_t>(y) * w];
    std::uint8_t* hi = &scratch.row_max[static_cast<std::size_t>(y) * w];
    lo[0] = std::min(l[0], l[std::min(1, w - 1)]), hi[0] = std::max(l[0], l[std::min(1, w - 1)]);
    for (int x = 1; x + 1 < w; ++x) {  // no clamping inside: the compiler vectorises this
      lo[x] = std::min(std::min(l[x - 1], l[x]), l[x + 1]);
      hi[x] = std::max(std::max(l[x - 1], l[x]), l[x + 1]);
    }
    if (w > 1) lo[w - 1] = std::min(l[w - 2], l[w - 1]), hi[w - 1] = std::max(l[w - 2], l[w - 1]);
  }
  const Region region{scratch.source.data(), gx0, gy0, w, h};
  scratch.range.assign(static_cast<std::size_t>(w + kRun), 0);  // padded for the runs' reads
  std::uint8_t* range = scratch.range.data();
  for (int y = rect.y0; y < rect.y1; ++y) {
    const int ry = y - gy0;
    const std::uint8_t* lo_above = &scratch.row_min[static_cast<std::size_t>(std::max(ry - 1, 0)) * w];
    const std::uint8_t* lo_here = &scratch.row_min[static_cast<std::size_t>(ry) * w];
    const std::uint8_t* lo_below = &scratch.row_min[static_cast<std::size_t>(std::min(ry + 1, h - 1)) * w];
    const std::uint8_t* hi_above = &scratch.row_max[static_cast<std::size_t>(std::max(ry - 1, 0)) * w];
    const std::uint8_t* hi_here = &scratch.row_max[static_cast<std::size_t>(ry) * w];
    const std::uint8_t* hi_below = &scratch.row_max[static_cast<std::size_t>(std::min(ry + 1, h - 1)) * w];
    // The 3×3 luma range bounds that of the centre and the four block means: below the threshold
    // nothing can be an edge (most pixels stop here). A whole row at a time, vectorised.
    for (int x = 0; x < w; ++x)
      range[x] = static_cast<std::uint8_t>(std::max(std::max(hi_above[x], hi_here[x]), hi_below[x]) -
                                           std::min(std::min(lo_above[x], lo_here[x]), lo_below[x]));
    // Runs of 32 pixels without an edge candidate are skipped whole (one vectorised maximum).
    for (int run = rect.x0; run < rect.x1; run += kRun) {
      const int end = std::min(run + kRun, rect.x1);
      std::uint8_t most = 0;
      const std::uint8_t* block = range + (run - gx0);  // may read past `end` into the padding: harmless, only conservative
      for (int k = 0; k < kRun; ++k) most = std::max(most, block[k]);
      if (most <= kMaxRangeWithoutEdge) continue;
      for (int x = run; x < end; ++x) {
        if (range[x - gx0] <= kMaxRangeWithoutEdge) continue;
        bool changed = false;
        const Rgb c = filter_pixel(region, x, y, changed);
        if (!changed) continue;
        std::uint8_t* out = image.pixel(x, y);
        out[0] = to_byte(c.r), out[1] = to_byte(c.g), out[2] = to_byte(c.b);
      }
    }
  }
}

}  // namespace gestura
