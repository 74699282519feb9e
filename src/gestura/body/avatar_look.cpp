#include "gestura/body/avatar_look.hpp"

#include "gestura/body/mesh.hpp"

namespace gestura {
namespace {

AvatarLook look(std::string_view name, std::string_view description, Sex sex, float height, float build, HairStyle hair,
                AvatarColors colors, float sleeve = 1.0f) {
  AvatarLook l{name, description, {}};
  l.params.sex = sex;
  l.params.height = height;
  l.params.build = build;
  l.params.hair = hair;
  l.params.colors = colors;
  l.params.sleeve = sleeve;
  return l;
}

}  // namespace

const std::vector<AvatarLook>& builtin_looks() {
  // Statures near the means of adult women (1.62 m) and men (1.76 m); skin tones across the range
  // of the Monk scale; tops in one strong colour (teal, navy, steel blue, burgundy, black), light
  // enough on the darkest skin that the hands still stand out against it.
  static const std::vector<AvatarLook> looks{
      {"default", "1.70 m, neutral build, light skin, short dark-brown hair, slate top (--height, --build, --sex apply)",
       AvatarParams{}},
      look("ana", "woman, 1.64 m, medium-light skin, dark-brown hair in a bun, teal top", Sex::Female, 1.64f, 0.95f,
           HairStyle::Bun, {{0.80f, 0.60f, 0.47f}, {0.17f, 0.10f, 0.06f}, {0.30f, 0.20f, 0.12f}, {0.06f, 0.30f, 0.33f}, {0.15f, 0.15f, 0.16f}}),
      look("ben", "man, 1.79 m, fair skin, short light-brown hair, navy top", Sex::Male, 1.79f, 1.05f, HairStyle::Short,
           {{0.93f, 0.76f, 0.66f}, {0.45f, 0.32f, 0.19f}, {0.33f, 0.45f, 0.55f}, {0.11f, 0.15f, 0.27f}, {0.19f, 0.19f, 0.20f}}),
      look("chidi", "man, 1.77 m, dark-brown skin, short curly black hair, steel-blue top", Sex::Male, 1.77f, 1.12f,
           HairStyle::Curly, {{0.40f, 0.26f, 0.18f}, {0.06f, 0.05f, 0.05f}, {0.20f, 0.12f, 0.07f}, {0.35f, 0.47f, 0.60f}, {0.10f, 0.12f, 0.18f}}),
      look("dana", "woman, 1.60 m, light skin, black bob, burgundy top", Sex::Female, 1.60f, 0.88f, HairStyle::Bob,
           {{0.92f, 0.77f, 0.65f}, {0.05f, 0.045f, 0.045f}, {0.18f, 0.11f, 0.07f}, {0.36f, 0.07f, 0.13f}, {0.07f, 0.07f, 0.08f}}),
      look("eli", "1.70 m, olive-brown skin, buzzed black hair, black top with three-quarter sleeves", Sex::Neutral, 1.70f,
           1.0f, HairStyle::Buzz, {{0.66f, 0.47f, 0.33f}, {0.09f, 0.07f, 0.06f}, {0.30f, 0.24f, 0.12f}, {0.09f, 0.09f, 0.10f}, {0.20f, 0.21f, 0.16f}},
           0.72f),
  };
  return looks;
}

const AvatarLook* find_look(std::string_view name) {
  for (const AvatarLook& l : builtin_looks())
    if (l.name == name) return &l;
  return nullptr;
}

std::string look_names() {
  std::string out;
  for (const AvatarLook& l : builtin_looks()) out += (out.empty() ? "" : ", ") + std::string(l.name);
  return out;
}

AvatarParams with_given(const AvatarParams& look, const AvatarParams& given) {
  const AvatarParams d{};
  AvatarParams out = look;
  auto take = [](auto& field, const auto& value, const auto& unset) {
    if (value != unset) field = value;
  };
  take(out.height, given.height, d.height);
  take(out.build, given.build, d.build);
  take(out.shoulder_width, given.shoulder_width, d.shoulder_width);
  take(out.arm_length, given.arm_length, d.arm_length);
  take(out.hand_size, given.hand_size, d.hand_size);
  take(out.finger_length, given.finger_length, d.finger_length);
  take(out.finger_thickness, given.finger_thickness, d.finger_thickness);
  take(out.sex, given.sex, d.sex);
  take(out.hair, given.hair, d.hair);
  take(out.sleeve, given.sleeve, d.sleeve);
  take(out.colors.skin, given.colors.skin, d.colors.skin);
  take(out.colors.hair, given.colors.hair, d.colors.hair);
  take(out.colors.iris, given.colors.iris, d.colors.iris);
  take(out.colors.cloth, given.colors.cloth, d.colors.cloth);
  take(out.colors.trousers, given.colors.trousers, d.colors.trousers);
  take(out.hem, given.hem, d.hem);
  return out;
}

std::vector<vec3> material_colors(const AvatarColors& c) {
  std::vector<vec3> out(kMaterialCount, vec3(0.5f));
  auto set = [&](MaterialId m, vec3 v) { out[static_cast<std::size_t>(m)] = glm::clamp(v, vec3(0.0f), vec3(1.0f)); };
  const float hair_light = glm::dot(c.hair, vec3(0.2126f, 0.7152f, 0.0722f));
  set(MaterialId::Skin, c.skin);
  set(MaterialId::Cloth, c.cloth);
  set(MaterialId::Trousers, c.trousers);
  set(MaterialId::Hair, c.hair);
  set(MaterialId::EyeWhite, {0.90f, 0.88f, 0.85f});
  set(MaterialId::Iris, c.iris);
  // Lips: the skin reddened and a little darker (close to it: saturated lips looked swollen).
  set(MaterialId::Lips, c.skin * vec3(0.89f, 0.72f, 0.74f));
  set(MaterialId::Teeth, {0.94f, 0.92f, 0.86f});
  set(MaterialId::Tongue, {0.78f, 0.38f, 0.40f});
  // Brows and lashes: the hair's colour, darker when the hair is fair.
  set(MaterialId::Brow, c.hair * (hair_light > 0.22f ? 0.55f : 0.92f));
  set(MaterialId::Pupil, {0.02f, 0.02f, 0.02f});
  set(MaterialId::Mouth, {0.22f, 0.07f, 0.07f});
  // Nails: paler and pinker than the skin around them.
  set(MaterialId::Nail, glm::mix(c.skin, vec3(1.0f, 0.87f, 0.84f), 0.45f));
  return out;
}

}  // namespace gestura
