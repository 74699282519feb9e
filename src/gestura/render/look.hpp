#pragma once
// How the avatar looks: colours per MaterialId (sRGB, 0..1), surface response per material and
// the background. Defaults: warm light skin, a dark shirt (so the hands stand out against it),
// a neutral grey background as in interpreter videos.
#include <array>
#include <string>

#include "gestura/body/mesh.hpp"
#include "gestura/core/math.hpp"

namespace gestura {

struct SurfaceResponse {
  float wrap = 0.0f;          // wrap-lighting amount: light reaching past the terminator (skin ~0.5)
  float scatter = 0.0f;       // subsurface tint strength near the terminator
  float specular = 0.0f;      // Blinn-Phong strength
  float shininess = 16.0f;    // Blinn-Phong exponent
};

struct Look {
  vec3 background{0.60f, 0.62f, 0.64f};
  std::array<vec3, kMaterialCount> colors{};
  std::array<SurfaceResponse, kMaterialCount> surfaces{};

  // Colours given by the user (set_color); the others yield to a mesh's own (Mesh::material_colors).
  std::array<bool, kMaterialCount> color_given{};

  Look();  // the defaults described above
  void set_color(MaterialId material, const vec3& srgb) {
    colors[static_cast<std::size_t>(material)] = srgb;
    color_given[static_cast<std::size_t>(material)] = true;
  }
};

// skin, cloth, hair, eye-white, iris, lips, teeth, tongue, brow, pupil, mouth (the oral cavity), nail,
// trousers.
const char* material_name(MaterialId material);
// Throws gestura::Error listing the names when `name` is none of them.
MaterialId parse_material(const std::string& name);
// The highlight strength a material shows in colour `srgb`: its SurfaceResponse::specular, weaker on
// dark skin, lips and hair (to 0.4 of it on the darkest). The same gloss over a dark albedo stands
// out as a wet, plastic sheen against the little diffuse light it returns.
float shown_specular(MaterialId material, const SurfaceResponse& surface, const vec3& srgb);

// "MATERIAL=#rrggbb" (e.g. "cloth=#202830") applied to `look`; throws gestura::Error otherwise.
void apply_color_setting(Look& look, const std::string& setting);
// `look` with the mesh's own colours (Mesh::material_colors) where the user gave none.
Look look_for(const Look& look, const Mesh& mesh);

// "#rrggbb" or "rrggbb" → sRGB 0..1; throws gestura::Error naming the text otherwise.
vec3 parse_hex_color(const std::string& text);

}  // namespace gestura
