// The Colour Editor's palette (ALIAS §7.1): six ramps of nearby colours, three adding and three
// taking away red, green or blue, stopping at the gamut's edge; clicking a ramp moves the palette;
// seven slots; the colour applied to one object only.
#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/world/color_palette.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/scene_json.hpp"

namespace {

using namespace gestura;

TEST(ColorPalette, RampsAddAndTakeAwayOneChannelEach) {
  const vec3 c(0.5f, 0.25f, 0.9375f);
  const auto ramps = nearby_colors(c, 4, 0.125f);
  for (int r = 0; r < 6; ++r) {
    const ColorRamp& ramp = ramps[static_cast<std::size_t>(r)];
    const int ch = r % 3;
    EXPECT_EQ(static_cast<int>(ramp.channel), ch);
    EXPECT_EQ(ramp.up, r < 3);
    ASSERT_FALSE(ramp.colors.empty()) << r;
    float last = c[ch];
    for (const vec3& k : ramp.colors) {
      for (int other = 0; other < 3; ++other) {
        if (other != ch) {
          EXPECT_EQ(k[other], c[other]) << "only one channel changes";
        }
      }
      EXPECT_EQ(k[ch] > last, ramp.up) << "ramp " << r << " goes the wrong way";
      EXPECT_GE(k[ch], 0.0f);
      EXPECT_LE(k[ch], 1.0f);
      last = k[ch];
    }
  }
  // Red 0.5 up in steps of 0.125: 0.625 0.75 0.875 1.0 (four); blue 0.9375 up: one step reaches 1.
  EXPECT_EQ(ramps[0].colors.size(), 4u);
  EXPECT_FLOAT_EQ(ramps[0].colors[1].x, 0.75f);
  ASSERT_EQ(ramps[2].colors.size(), 1u);
  EXPECT_FLOAT_EQ(ramps[2].colors[0].z, 1.0f);
  // Green 0.25 down: 0.125, 0.0, then the edge.
  ASSERT_EQ(ramps[4].colors.size(), 2u);
  EXPECT_FLOAT_EQ(ramps[4].colors[1].y, 0.0f);
  // Pure white has nothing above it.
  const auto white = nearby_colors(vec3(1.0f));
  for (int r = 0; r < 3; ++r) EXPECT_TRUE(white[static_cast<std::size_t>(r)].colors.empty());
  EXPECT_EQ(white[3].colors.size(), 8u);
}

TEST(ColorPalette, ClickingARampMovesThePaletteAndSlotsKeepColours) {
  ColorPalette palette(vec3(0.5f), 8, 1.0f / 16.0f);
  palette.choose_from_ramp(0, 3);  // red up, fourth step
  EXPECT_FLOAT_EQ(palette.color().x, 0.75f);
  EXPECT_FLOAT_EQ(palette.color().y, 0.5f);
  EXPECT_FLOAT_EQ(palette.ramps()[3].colors[0].x, 0.6875f) << "the ramps follow the new colour";
  palette.store(6);
  palette.choose(vec3(2.0f, -1.0f, 0.2f));
  EXPECT_EQ(palette.color(), vec3(1.0f, 0.0f, 0.2f)) << "clamped into the gamut";
  palette.choose_slot(6);
  EXPECT_FLOAT_EQ(palette.color().x, 0.75f);
  EXPECT_THROW(palette.choose_slot(0), Error);
  EXPECT_THROW(palette.store(7), Error);
  EXPECT_THROW(palette.choose_from_ramp(6, 0), Error);
  EXPECT_THROW(palette.choose_from_ramp(0, 99), Error);
}

TEST(ColorPalette, AppliedColourChangesOnlyThatObject) {
  Scene scene = parse_scene(R"({
    "materials": {"wood": {"color": "#8a5a36", "specular": 0.3}, "metal": "#c0c0c0"},
    "objects": [
      {"name": "table", "shape": "box", "size": [1, 0.05, 1], "position": [0, 0.7, 0], "material": "wood"},
      {"name": "shelf", "material": "wood", "parts": [
        {"shape": "box", "size": [1, 0.02, 0.3]},
        {"shape": "box", "size": [0.1, 0.02, 0.02], "position": [0, 0.05, 0], "material": "metal"}]}
    ]})", "palette.json");
  const vec3 blue(0.1f, 0.2f, 0.8f);
  EXPECT_EQ(apply_color(scene, 1, blue), "shelf");
  EXPECT_FLOAT_EQ(scene.materials.at("shelf").specular, 0.3f) << "the material's other qualities are kept";
  validate(scene);
  const SceneGeometry g = build_scene_geometry(scene);
  const auto colour_of = [&](int object, std::uint32_t k) { return g.colors[g.indices[g.object_first[static_cast<std::size_t>(object)] + k]]; };
  EXPECT_NEAR(colour_of(0, 0).z, scene.materials.at("wood").color.z, 1e-6f) << "the table keeps the wood";
  bool blue_seen = false, metal_seen = false;
  for (std::uint32_t k = 0; k < g.object_count[1]; ++k) {
    blue_seen |= glm::length(colour_of(1, k) - blue) < 1e-6f;
    metal_seen |= glm::length(colour_of(1, k) - scene.materials.at("metal").color) < 1e-6f;
  }
  EXPECT_TRUE(blue_seen);
  EXPECT_TRUE(metal_seen) << "a part with its own material keeps it";
  EXPECT_THROW(apply_color(scene, 2, blue), Error);
}

}  // namespace
