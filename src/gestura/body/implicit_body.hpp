#pragma once
// The body as an implicit volume (realtime-virtual-humans.txt §2.2): simple primitives attached to
// bones, folded in order into one signed field — negative inside, positive outside, roughly a
// distance in metres — by smooth union, smooth subtraction or intersection with the field so far.
// One field means one surface: whatever polygonises it gets a single seamless skin.
//
// Every primitive carries the joint it rides on and the material of the surface it makes; the
// skin-weight and material passes ask which primitives are near a surface point.
#include <cstdint>
#include <span>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

enum class PrimitiveShape : std::uint8_t {
  Capsule,    // segment a–b, radius tapering from radius_a to radius_b
  Ellipsoid,  // centre a, semi-axes `radii` in the frame `axes` (columns = local x, y, z)
  RoundBox,   // centre a, half extents `radii` (before rounding) in `axes`, corner radius radius_a
  HalfSpace,  // points with dot(p − a, axes[1]) < 0 are inside ("below the plane")
};

enum class BlendOp : std::uint8_t { Union, Subtract, Intersect };

struct Primitive {
  PrimitiveShape shape = PrimitiveShape::Capsule;
  BlendOp op = BlendOp::Union;
  float blend = 0.0f;           // smooth-blend width in metres (0 = sharp)
  vec3 a{0.0f}, b{0.0f};
  float radius_a = 0.0f, radius_b = 0.0f;
  vec3 radii{0.0f};
  mat3 axes{1.0f};
  std::int16_t joint = 0;       // bone the primitive rides on
  std::uint8_t material = 0;    // MaterialId of the surface it makes
  bool skinned = true;          // takes part in skin weights (false for carved cavities, planes)
  vec3 lo{0.0f}, hi{0.0f};      // bounding box of the primitive itself; filled by finish()
};

// Signed distance (approximate for ellipsoids) from p to one primitive, ignoring its op.
float primitive_distance(const Primitive& primitive, const vec3& p);

struct ImplicitBody {
  std::vector<Primitive> primitives;
  vec3 lo{0.0f}, hi{0.0f};  // bounds of the union primitives; filled by finish()

  // Computes bounding boxes; call after the last primitive is added.
  void finish();

  // The field at p. `band` > 0 allows skipping primitives farther than band: the result is then
  // exact where |f| < band and only its sign is exact elsewhere (clamped to ±band).
  float field(const vec3& p, float band = 1e9f) const;
  vec3 gradient(const vec3& p, float step = 1e-4f) const;

  // Distances from p to every union primitive (others: +inf), for weights and materials.
  void distances(const vec3& p, std::span<float> out) const;
};

}  // namespace gestura
