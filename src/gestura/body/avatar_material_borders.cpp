#include "gestura/body/avatar_material_borders.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "gestura/body/avatar_proportions.hpp"

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

float hair_field(const vec3& p, float k, HairStyle style) {
  // The hairline's height (metres at 1.70 m) by direction around the head's vertical axis, from the
  // front (0°) over the temple and above the ear to the nape (180°).
  struct Knot {
    float degrees, height;
  };
  static constexpr std::array<Knot, 9> cropped{{{0, 1.662f},
                                                {30, 1.658f},
                                                {55, 1.644f},
                                                {68, 1.622f},
                                                {100, 1.622f},
                                                {112, 1.588f},
                                                {135, 1.558f},
                                                {160, 1.533f},
                                                {180, 1.526f}}};
  // A bob: the same line over the forehead and temples, then the hair falls past the ears to the
  // jaw's height all round the back.
  static constexpr std::array<Knot, 9> bob{{{0, 1.662f},
                                            {30, 1.656f},
                                            {52, 1.640f},
                                            {62, 1.610f},
                                            {70, 1.540f},
                                            {80, 1.512f},
                                            {120, 1.506f},
                                            {160, 1.504f},
                                            {180, 1.504f}}};
  const auto& line = style == HairStyle::Bob ? bob : cropped;
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
  const float centre = 1.6235f + 0.0032f * (1.0f - (2.0f * u - 1.3f) * (2.0f * u - 1.3f) / 1.69f);
  const float half_thickness = 0.0055f - 0.0025f * u;
  return std::hypot(ax - x, y - centre) - half_thickness;
}

float lash_field(const vec3& p, const vec3& eye, float k) {
  // The almond of the eye opening (as carved in avatar_volume.cpp), in the eye's frame.
  const vec3 centre = vec3(proportions::kEyeOpeningCentre[0], proportions::kEyeOpeningCentre[1],
                           proportions::kEyeOpeningCentre[2]) * k;
  const vec3 radii = vec3(proportions::kEyeOpeningRadii[0], proportions::kEyeOpeningRadii[1],
                          proportions::kEyeOpeningRadii[2]) * k;
  const vec3 q = p - eye - centre;
  if (q.z < -0.002f * k) return 1.0f;
  const float rho = glm::length(q / radii);
  // A band along the upper margin, thickest over the middle of the eye, thinning to the corners.
  const float across = std::min(std::abs(q.x) / radii.x, 1.0f);
  const float band = 0.18f + 0.30f * (1.0f - across * across);
  return std::max((rho - 1.0f - band) * radii.y, 0.35f * radii.y - q.y);
}

std::vector<MaterialBorder> avatar_material_borders(const ImplicitBody& body, float k, HairStyle style,
                                                   std::array<vec3, 2> eyes) {
  const ImplicitBody* b = &body;
  std::vector<MaterialBorder> borders;
  borders.push_back({MaterialId::Hair, MaterialId::Skin, [k, style](const vec3& p) { return hair_field(p, k, style); }});
  borders.push_back({MaterialId::Cloth, MaterialId::Skin,
                     [b](const vec3& p) { return nearer_material(*b, p, MaterialId::Cloth, MaterialId::Skin); }});
  // Brows and lashes share a material, so one border draws both.
  borders.push_back({MaterialId::Brow, MaterialId::Skin, [k, eyes](const vec3& p) {
                       return std::min({eyebrow_field(p, k), lash_field(p, eyes[0], k), lash_field(p, eyes[1], k)});
                     }});
  return borders;
}

}  // namespace gestura
