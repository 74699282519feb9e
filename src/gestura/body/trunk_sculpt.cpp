#include "gestura/body/trunk_sculpt.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/natural_spline.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// The contour's roundness: 2 is an ellipse; a trunk is a little boxier.
constexpr float kExponent = 2.4f;

float smax(float a, float b, float k) {
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::max(a, b) + h * h * k * 0.25f;
}

}  // namespace

TrunkLoft::TrunkLoft(std::vector<TrunkSection> sections) : s_(std::move(sections)) {
  if (s_.size() < 4) throw Error("trunk loft: at least four sections are needed");
  for (std::size_t i = 1; i < s_.size(); ++i)
    if (!(s_[i].y > s_[i - 1].y)) throw Error("trunk loft: sections must rise");
  y0_ = s_.front().y;
  y1_ = s_.back().y;
  widest_ = 0.0f;
  for (const TrunkSection& s : s_) widest_ = std::max(widest_, s.half_breadth);
  auto knots = [&](float TrunkSection::*field) {
    std::vector<std::array<float, 2>> k;
    for (const TrunkSection& s : s_) k.push_back({s.y, s.*field});
    return NaturalSpline(std::move(k));
  };
  breadth_ = knots(&TrunkSection::half_breadth);
  front_ = knots(&TrunkSection::front);
  back_ = knots(&TrunkSection::back);
  centre_ = knots(&TrunkSection::centre_z);
}

TrunkSection TrunkLoft::at(float y) const { return {y, breadth_(y), front_(y), back_(y), centre_(y)}; }

float TrunkLoft::distance(const vec3& p) const {
  const float y = std::clamp(p.y, y0_, y1_);
  const TrunkSection s = at(y);
  const float dz = p.z - s.centre_z;
  const float u = std::abs(p.x) / s.half_breadth, v = std::abs(dz) / (dz > 0.0f ? s.front : s.back);
  const float rho = std::pow(std::pow(u, kExponent) + std::pow(v, kExponent), 1.0f / kExponent);
  const float r = std::sqrt(p.x * p.x + dz * dz);
  // Along the ray from the contour's centre (exact there); the contour's own scale inside it.
  const float across = rho > 1e-4f ? r * (rho - 1.0f) / rho : -std::min({s.half_breadth, s.front, s.back});
  // Rounded ends: half a contour's depth above the top and below the bottom section.
  const float below = y0_ - p.y, above = p.y - y1_;
  return smax(across, std::max(below, above), 0.03f);
}

float TrunkPiece::distance(const vec3& p) const {
  return std::max(loft_->distance(p), std::max(y0_ - p.y, p.y - y1_));
}

void TrunkPiece::bounds(vec3& lo, vec3& hi) const {
  const float w = loft_->widest() * 1.05f;
  lo = vec3(-w, y0_, -w);
  hi = vec3(w, y1_, w);
}

std::vector<TrunkSection> trunk_sections(const AvatarParams& p) {
  const float k = p.height / 1.70f, g = p.build;
  using proportions::by_sex;
  // Neutral half-breadths and depths at 1.70 m (means of the men's and women's values of ANSUR
  // scaled to the stature; docs/avatar.md), then the sex's shape: wider hips and a narrower chest
  // and waist for women, the reverse for men.
  const float hips = by_sex(p.sex, 1.06f, 1.0f, 0.96f);
  const float waist = by_sex(p.sex, 0.95f, 1.0f, 1.03f);
  const float chest = by_sex(p.sex, 0.94f, 1.0f, 1.05f);
  // A heavier build carries its girth at the waist and belly more than at the chest.
  const float belly = 1.0f + 1.3f * (g - 1.0f);
  struct Row {
    float y, breadth, front, back, centre, shape, girth;
  };
  const Row rows[] = {
      {0.785f, 0.148f, 0.080f, 0.090f, -0.010f, hips, g},        // crotch
      {0.850f, 0.168f, 0.092f, 0.120f, -0.014f, hips, g},        // buttocks, greatest hip breadth
      {0.930f, 0.160f, 0.098f, 0.106f, -0.006f, hips, g},        // hip joints, iliac crest below
      {1.000f, 0.149f, 0.102f, 0.094f, 0.000f, 0.5f * (hips + waist), belly},
      {1.070f, 0.140f, 0.100f, 0.088f, 0.000f, waist, belly},     // natural waist
      {1.150f, 0.148f, 0.106f, 0.092f, 0.000f, 0.5f * (waist + chest), 0.5f * (belly + g)},
      {1.230f, 0.150f, 0.116f, 0.098f, -0.002f, chest, g},        // chest (0.174 H, Drillis & Contini)
      {1.310f, 0.146f, 0.110f, 0.098f, -0.008f, chest, g},        // armpits
      {1.350f, 0.138f, 0.090f, 0.088f, -0.016f, chest, g},        // under the shoulder girdle
      // The upper chest slopes back to the clavicles and the base of the neck (ending the loft at
      // the armpits left a shelf across the chest under the girdle).
      {1.385f, 0.118f, 0.066f, 0.080f, -0.024f, chest, g},        // the clavicles' front
      {1.415f, 0.082f, 0.050f, 0.062f, -0.030f, 1.0f, 0.5f * (1.0f + g)},  // the base of the neck
  };
  std::vector<TrunkSection> out;
  for (const Row& r : rows)
    out.push_back({r.y * k, r.breadth * r.shape * r.girth * k, r.front * r.girth * k, r.back * r.girth * k, r.centre * k});
  return out;
}

}  // namespace gestura
