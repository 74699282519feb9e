#include "gestura/body/avatar_material_borders.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace gestura {
namespace {

// Distance from p to the nearest union primitive of material `a`, minus that to material `b`:
// negative where `a`'s surface is the nearer, as the per-vertex labelling decides.
float nearer_material(const ImplicitBody& body, const vec3& p, MaterialId a, MaterialId b) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  float da = inf, db = inf;
  for (const Primitive& s : body.primitives) {
    if (s.op != BlendOp::Union) continue;
    const auto m = static_cast<MaterialId>(s.material);
    if (m != a && m != b) continue;
    const float d = primitive_distance(s, p);
    (m == a ? da : db) = std::min(m == a ? da : db, d);
  }
  return da - db;
}

}  // namespace

float hair_field(const vec3& p, float k) {
  // The hairline's height (metres at 1.70 m) by direction around the head's vertical axis, from the
  // front (0°) over the temple and above the ear to the nape (180°).
  struct Knot {
    float degrees, height;
  };
  static constexpr std::array<Knot, 9> line{{{0, 1.664f},
                                             {30, 1.660f},
                                             {55, 1.646f},
                                             {68, 1.624f},
                                             {100, 1.624f},
                                             {112, 1.590f},
                                             {135, 1.560f},
                                             {160, 1.535f},
                                             {180, 1.528f}}};
  const float around =
      std::atan2(std::abs(p.x), p.z + 0.010f * k) * (180.0f / std::numbers::pi_v<float>);  // 0 .. 180
  std::size_t i = 1;
  while (i + 1 < line.size() && line[i].degrees < around) ++i;
  const float t = std::clamp((around - line[i - 1].degrees) / (line[i].degrees - line[i - 1].degrees), 0.0f, 1.0f);
  const float eased = t * t * (3.0f - 2.0f * t);  // smooth through every knot
  return (line[i - 1].height + (line[i].height - line[i - 1].height) * eased) * k - p.y;
}

float eyebrow_field(const vec3& p, float k) {
  const float ax = std::abs(p.x) / k, y = p.y / k;
  if (p.z / k < 0.04f) return 1.0f;  // the brows are on the front of the head only
  // Seen from the front, a brow is a thick stroke along a gentle arch from its head near the nose
  // (inner, 5.5 mm half thickness) to its thin tail: a distance to the stroke's centre line minus
  // the stroke's half thickness (so the field is close to metres everywhere, as the cutting wants).
  constexpr float inner = 0.0140f, outer = 0.0490f;
  const float x = std::clamp(ax, inner, outer);
  const float u = (x - inner) / (outer - inner);  // 0 at the head, 1 at the tail
  const float centre = 1.6300f + 0.0032f * (1.0f - (2.0f * u - 1.3f) * (2.0f * u - 1.3f) / 1.69f);
  const float half_thickness = 0.0055f - 0.0025f * u;
  return std::hypot(ax - x, y - centre) - half_thickness;
}

std::vector<MaterialBorder> avatar_material_borders(const ImplicitBody& body, float k) {
  const ImplicitBody* b = &body;
  std::vector<MaterialBorder> borders;
  borders.push_back({MaterialId::Hair, MaterialId::Skin, [k](const vec3& p) { return hair_field(p, k); }});
  borders.push_back({MaterialId::Cloth, MaterialId::Skin,
                     [b](const vec3& p) { return nearer_material(*b, p, MaterialId::Cloth, MaterialId::Skin); }});
  borders.push_back({MaterialId::Brow, MaterialId::Skin, [k](const vec3& p) { return eyebrow_field(p, k); }});
  return borders;
}

}  // namespace gestura
