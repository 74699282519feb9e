#pragma once
// The body as an implicit volume (realtime-virtual-humans.txt §2.2): simple primitives attached to
// bones, folded in order into one signed field — negative inside, positive outside, roughly a
// distance in metres — by smooth union, smooth subtraction or intersection with the field so far.
// One field means one surface: whatever polygonises it gets a single seamless skin.
//
// Every primitive carries the joint it rides on and the material of the surface it makes; the
// skin-weight and material passes ask which primitives are near a surface point.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

enum class PrimitiveShape : std::uint8_t {
  Capsule,    // segment a–b, radius tapering from radius_a to radius_b
  Ellipsoid,  // centre a, semi-axes `radii` in the frame `axes` (columns = local x, y, z)
  RoundBox,   // centre a, half extents `radii` (before rounding) in `axes`, corner radius radius_a
  HalfSpace,  // points with dot(p − a, axes[1]) < 0 are inside ("below the plane")
  Sculpt,     // a shape written as code (`sculpt`), in the frame at a with axes `axes`
};

// A shape too rich for the simple primitives (a head from its profile and contours, a lofted
// trunk): a signed, roughly metric distance in its own frame, and the box that holds it there.
// Immutable and shared, so bodies holding it copy cheaply.
class Sculpt {
 public:
  virtual ~Sculpt() = default;
  virtual float distance(const vec3& local) const = 0;
  virtual void bounds(vec3& lo, vec3& hi) const = 0;  // local frame
  // The material of the surface near `local` (its own regions: lips on a face); by default the
  // primitive's.
  virtual int material(const vec3& local) const { (void)local; return -1; }
  // Size of the shape where its influence on skin weights blends (cf. a capsule's radius).
  virtual float size() const = 0;
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
  std::shared_ptr<const Sculpt> sculpt;  // the shape of a Sculpt primitive
  vec3 lo{0.0f}, hi{0.0f};      // bounding box of the primitive itself; filled by finish()
};

// Signed distance (approximate for ellipsoids) from p to one primitive, ignoring its op.
float primitive_distance(const Primitive& primitive, const vec3& p);
// The material of a primitive's surface near p (a sculpt's own regions, else the primitive's).
std::uint8_t primitive_material(const Primitive& primitive, const vec3& p);

struct ImplicitBody {
  std::vector<Primitive> primitives;
  vec3 lo{0.0f}, hi{0.0f};  // bounds of the union primitives; filled by finish()

  // Computes bounding boxes and the index below; call after the last primitive is added.
  void finish();

  // The field at p. `band` > 0 allows skipping primitives farther than band: the result is then
  // exact where |f| < band and only its sign is exact elsewhere (clamped to ±band).
  float field(const vec3& p, float band = 1e9f) const;
  vec3 gradient(const vec3& p, float step = 1e-4f) const;

  // Distances from p to every union primitive (others: +inf), for weights and materials.
  void distances(const vec3& p, std::span<float> out) const;

  // Uniform grids over the bounds: for each cell, in order, the primitives that can change the
  // field within `band` of it (the rest are too far to matter: a blend reaches only so far), so
  // field() looks at a few instead of all of them. A coarse grid for the polygoniser's coarse
  // lattice, a fine one for everything near the surface (fine lattices, gradients). Built by finish().
  struct Index {
    float band = 0.0f;
    vec3 origin{0.0f};
    float cell = 0.0f;
    glm::ivec3 cells{0};
    std::vector<std::uint32_t> start;  // per cell, into items; one extra at the end
    std::vector<std::uint16_t> items;
    void build(const ImplicitBody& body, float band, float cell);
    // The primitives for p, or false when p lies outside the grid or band exceeds its own.
    bool find(const vec3& p, float band, std::uint32_t& first, std::uint32_t& last) const;
  };
  Index coarse_index, fine_index;
};

}  // namespace gestura
