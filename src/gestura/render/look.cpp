#include "gestura/render/look.hpp"

#include <algorithm>
#include <cctype>

#include "gestura/core/error.hpp"

namespace gestura {

Look::Look() {
  auto set = [this](MaterialId m, vec3 color, SurfaceResponse surface) {
    colors[static_cast<std::size_t>(m)] = color;
    surfaces[static_cast<std::size_t>(m)] = surface;
  };
  set(MaterialId::Skin, {0.88f, 0.68f, 0.57f}, {0.5f, 0.35f, 0.10f, 24.0f});
  // A dark slate shirt: dark enough for skin-coloured hands to stand out, light enough to show
  // the body's form (near-black read as one flat blob on the real avatar).
  set(MaterialId::Cloth, {0.17f, 0.20f, 0.26f}, {0.2f, 0.0f, 0.04f, 8.0f});
  set(MaterialId::Hair, {0.20f, 0.13f, 0.08f}, {0.3f, 0.0f, 0.15f, 30.0f});
  set(MaterialId::EyeWhite, {0.90f, 0.88f, 0.85f}, {0.3f, 0.1f, 0.9f, 200.0f});
  set(MaterialId::Iris, {0.28f, 0.40f, 0.52f}, {0.2f, 0.0f, 1.2f, 300.0f});
  // Lips close to the skin tone with a soft sheen: saturated, glossy lips looked swollen.
  set(MaterialId::Lips, {0.76f, 0.50f, 0.47f}, {0.5f, 0.35f, 0.10f, 30.0f});
  set(MaterialId::Teeth, {0.94f, 0.92f, 0.86f}, {0.3f, 0.1f, 0.3f, 60.0f});
  set(MaterialId::Tongue, {0.78f, 0.38f, 0.40f}, {0.5f, 0.4f, 0.3f, 40.0f});
  set(MaterialId::Brow, {0.18f, 0.12f, 0.08f}, {0.3f, 0.0f, 0.05f, 10.0f});
  set(MaterialId::Pupil, {0.02f, 0.02f, 0.02f}, {0.0f, 0.0f, 1.5f, 300.0f});
  // The oral cavity: a dark red that reads as the shadowed inside of the mouth (no shadows are cast).
  set(MaterialId::Mouth, {0.22f, 0.07f, 0.07f}, {0.3f, 0.2f, 0.05f, 20.0f});
  // Nails: paler and pinker than the skin, with a sheen.
  set(MaterialId::Nail, {0.93f, 0.76f, 0.70f}, {0.4f, 0.2f, 0.35f, 60.0f});
  set(MaterialId::Trousers, {0.14f, 0.14f, 0.16f}, {0.2f, 0.0f, 0.04f, 8.0f});
}

namespace {
constexpr const char* kMaterialNames[kMaterialCount] = {"skin", "cloth", "hair", "eye-white", "iris", "lips",
                                                         "teeth", "tongue", "brow", "pupil", "mouth", "nail", "trousers"};
}

const char* material_name(MaterialId material) { return kMaterialNames[static_cast<std::size_t>(material)]; }

MaterialId parse_material(const std::string& name) {
  std::string all;
  for (int m = 0; m < kMaterialCount; ++m) {
    if (name == kMaterialNames[m]) return static_cast<MaterialId>(m);
    all += (m ? ", " : "") + std::string(kMaterialNames[m]);
  }
  throw Error("unknown material '" + name + "' (" + all + ")");
}

void apply_color_setting(Look& look, const std::string& setting) {
  const auto eq = setting.find('=');
  if (eq == std::string::npos) throw Error("bad --color '" + setting + "' (expected MATERIAL=#rrggbb)");
  look.set_color(parse_material(setting.substr(0, eq)), parse_hex_color(setting.substr(eq + 1)));
}

Look look_for(const Look& look, const Mesh& mesh) {
  Look out = look;
  if (mesh.material_colors.size() != static_cast<std::size_t>(kMaterialCount)) return out;
  for (std::size_t m = 0; m < out.colors.size(); ++m)
    if (!look.color_given[m]) out.colors[m] = mesh.material_colors[m];
  return out;
}

float shown_specular(MaterialId material, const SurfaceResponse& surface, const vec3& srgb) {
  if (material != MaterialId::Skin && material != MaterialId::Lips && material != MaterialId::Hair) return surface.specular;
  const vec3 linear = glm::pow(glm::clamp(srgb, vec3(0.0f), vec3(1.0f)), vec3(2.2f));
  const float luminance = glm::dot(linear, vec3(0.2126f, 0.7152f, 0.0722f));
  const float t = std::clamp((luminance - 0.02f) / (0.35f - 0.02f), 0.0f, 1.0f);
  return surface.specular * (0.4f + 0.6f * t * t * (3.0f - 2.0f * t));
}

vec3 parse_hex_color(const std::string& text) {
  std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  bool ok = hex.size() == 6;
  for (char c : hex) ok = ok && std::isxdigit(static_cast<unsigned char>(c));
  if (!ok) throw Error("bad colour '" + text + "' (expected #rrggbb)");
  const unsigned long value = std::stoul(hex, nullptr, 16);
  return vec3((value >> 16) & 0xff, (value >> 8) & 0xff, value & 0xff) / 255.0f;
}

}  // namespace gestura
