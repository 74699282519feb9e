#include <gtest/gtest.h>

#include "gestura/render/look.hpp"

namespace gestura {
namespace {

TEST(Look, HighlightsAreWeakerOnDarkSkinAndHairOnly) {
  const Look look;
  const auto shown = [&](MaterialId m, vec3 srgb) {
    return shown_specular(m, look.surfaces[static_cast<std::size_t>(m)], srgb);
  };
  const float skin = look.surfaces[static_cast<std::size_t>(MaterialId::Skin)].specular;
  // Light skin keeps its gloss; the darkest built-in skin (chidi's) shows well under half of it,
  // the olive-brown between: the same gloss once read as a wet sheen on dark skin.
  EXPECT_FLOAT_EQ(shown(MaterialId::Skin, {0.88f, 0.68f, 0.57f}), skin);
  const float dark = shown(MaterialId::Skin, {0.40f, 0.26f, 0.18f});
  const float olive = shown(MaterialId::Skin, {0.66f, 0.47f, 0.33f});
  EXPECT_LT(dark, 0.5f * skin);
  EXPECT_GE(dark, 0.4f * skin);
  EXPECT_GT(olive, dark);
  EXPECT_LT(olive, skin);
  // Darker is never glossier.
  float last = 0.0f;
  for (float v = 0.0f; v <= 1.0f; v += 0.05f) {
    const float s = shown(MaterialId::Skin, vec3(v, 0.8f * v, 0.7f * v));
    EXPECT_GE(s, last);
    last = s;
  }
  EXPECT_LT(shown(MaterialId::Hair, {0.06f, 0.05f, 0.05f}), look.surfaces[static_cast<std::size_t>(MaterialId::Hair)].specular);
  // The eyes keep their catch-lights, whatever their colour.
  for (MaterialId m : {MaterialId::Pupil, MaterialId::Iris, MaterialId::EyeWhite, MaterialId::Nail})
    EXPECT_FLOAT_EQ(shown(m, {0.02f, 0.02f, 0.02f}), look.surfaces[static_cast<std::size_t>(m)].specular);
}

}  // namespace
}  // namespace gestura
