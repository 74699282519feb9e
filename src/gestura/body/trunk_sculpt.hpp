#pragma once
// The trunk as a loft of horizontal cross-sections (realtime-virtual-humans.txt §3.2.1: body parts
// as cross-sectional contours around the skeleton): at each height a rounded contour with its own
// half-breadth, its depth in front of and behind its centre line, interpolated by C2 splines up the
// body, so the trunk is smooth everywhere and its breadths and depths at the hips, waist and chest
// are anthropometric measures (docs/avatar.md), scaled with stature, sex and build.
//
// The loft is cut into pieces, one per spine joint, so each piece rides its joint (skin weights);
// cut sharply and joined without blending, the pieces make exactly the loft's surface.
#include <memory>
#include <vector>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/implicit_body.hpp"
#include "gestura/body/natural_spline.hpp"

namespace gestura {

struct TrunkSection {
  float y;             // height (metres)
  float half_breadth;  // x
  float front, back;   // depth in front of / behind centre_z
  float centre_z;
};

class TrunkLoft {
 public:
  // `sections` ascending in y, at least 4; the loft ends (rounded) at the first and last section.
  explicit TrunkLoft(std::vector<TrunkSection> sections);
  float distance(const vec3& p) const;
  TrunkSection at(float y) const;  // the interpolated section
  float bottom() const { return y0_; }
  float top() const { return y1_; }
  float widest() const { return widest_; }  // the largest half-breadth

 private:
  std::vector<TrunkSection> s_;
  NaturalSpline breadth_, front_, back_, centre_;
  float y0_, y1_, widest_;
};

// A slab [y0, y1] of the loft (sharp cuts: neighbouring pieces meet without a seam).
class TrunkPiece final : public Sculpt {
 public:
  TrunkPiece(std::shared_ptr<const TrunkLoft> loft, float y0, float y1) : loft_(std::move(loft)), y0_(y0), y1_(y1) {}
  float distance(const vec3& p) const override;
  void bounds(vec3& lo, vec3& hi) const override;
  float size() const override { return 0.08f; }

 private:
  std::shared_ptr<const TrunkLoft> loft_;
  float y0_, y1_;
};

// The trunk's sections for a body of these params (metres): from the crotch over the hips, waist
// and chest to the base of the neck.
std::vector<TrunkSection> trunk_sections(const AvatarParams& params);

}  // namespace gestura
