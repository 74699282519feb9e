// Camera presets, framing and split panes, independent of any GL.
#include <gtest/gtest.h>

#include "gestura/core/error.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/render/look.hpp"
#include "support/test_figure.hpp"

namespace gestura {
namespace {

vec3 to_ndc(const Camera& c, vec3 p) {
  const vec4 clip = c.projection * c.view * vec4(p, 1.0f);
  return vec3(clip) / clip.w;
}

TEST(RenderCamera, PresetNamesRoundTripAndUnknownNamesAreErrors) {
  for (CameraPreset p : kCameraPresets) EXPECT_EQ(parse_camera_preset(preset_name(p)), p);
  EXPECT_THROW(parse_camera_preset("back"), Error);
  EXPECT_EQ(parse_camera_list("front,top").size(), 2u);
  EXPECT_THROW(parse_camera_list("front,,top"), Error);
  EXPECT_THROW(parse_camera_list("front,front,front,front,front,front,front,front,front,front"), Error);
}

TEST(RenderCamera, FramingUsesTheHipsJointAndMeshBounds) {
  const RenderSubject figure = make_test_figure(1);
  const FramingBox box = framing_box(figure.mesh, figure.skeleton);
  EXPECT_NEAR(box.hips_y, 0.98f, 1e-4f);  // the figure's HumanoidRoot
  EXPECT_GT(box.max.y, 1.75f);
  EXPECT_LT(box.min.y, 0.1f);
}

TEST(RenderCamera, FrontPresetFramesHipsToHeadAndLooksAlongMinusZ) {
  FramingBox box{{-0.3f, 0.0f, -0.15f}, {0.3f, 1.8f, 0.15f}, 1.0f};
  const Camera c = preset_camera(CameraPreset::Front, box, 16.0f / 9.0f);
  EXPECT_GT(c.eye.z, 1.0f);
  EXPECT_NEAR(c.eye.x, 0.0f, 1e-4f);
  const vec3 head = to_ndc(c, {0.0f, 1.8f, 0.0f}), hips = to_ndc(c, {0.0f, 1.0f, 0.0f}), feet = to_ndc(c, {0.0f, 0.0f, 0.0f});
  // Interpreter framing: the crown just below the top edge, the cut at the hips.
  EXPECT_LT(head.y, 1.0f);
  EXPECT_GT(head.y, 0.8f);
  EXPECT_NEAR(hips.y, -1.0f, 0.01f);
  EXPECT_LT(feet.y, -1.0f);
  // The avatar's left (+X) is on the image's right when seen from the front.
  EXPECT_GT(to_ndc(c, {0.3f, 1.4f, 0.0f}).x, 0.0f);
}

TEST(RenderCamera, OrthographicPresetsKeepSizeIndependentOfDepth) {
  FramingBox box{{-0.3f, 0.0f, -0.15f}, {0.3f, 1.8f, 0.15f}, 1.0f};
  for (CameraPreset p : {CameraPreset::Top, CameraPreset::SideSection}) {
    const Camera c = preset_camera(p, box, 1.0f);
    EXPECT_TRUE(c.orthographic);
    const vec3 a = to_ndc(c, {0.1f, 1.0f, 0.1f}), b = to_ndc(c, {0.2f, 1.2f, 0.1f});
    const vec3 shift = p == CameraPreset::Top ? vec3(0, 0.5f, 0) : vec3(0.5f, 0, 0);
    const vec3 a2 = to_ndc(c, vec3(0.1f, 1.0f, 0.1f) + shift), b2 = to_ndc(c, vec3(0.2f, 1.2f, 0.1f) + shift);
    EXPECT_NEAR(glm::length(vec2(b - a)), glm::length(vec2(b2 - a2)), 1e-4f);
  }
  // The plan view puts the avatar's front (+Z) towards the image bottom; the section sees the whole body.
  const Camera top = preset_camera(CameraPreset::Top, box, 1.0f);
  EXPECT_LT(to_ndc(top, {0, 1, 0.3f}).y, to_ndc(top, {0, 1, -0.1f}).y);
  const Camera section = preset_camera(CameraPreset::SideSection, box, 1.0f);
  EXPECT_GT(to_ndc(section, {0, 0.01f, 0}).y, -1.0f);
  EXPECT_LT(to_ndc(section, {0, 1.79f, 0}).y, 1.0f);
}

TEST(RenderCamera, OrbitFromPresetSeesTheSameTarget) {
  FramingBox box{{-0.3f, 0.0f, -0.15f}, {0.3f, 1.8f, 0.15f}, 1.0f};
  const Camera preset = preset_camera(CameraPreset::ThreeQuarter, box, 1.5f);
  const Camera orbit = orbit_camera(preset_orbit(CameraPreset::ThreeQuarter, box, 1.5f), 1.5f);
  EXPECT_LT(glm::length(preset.eye - orbit.eye), 1e-3f);
  EXPECT_LT(glm::length(preset.target - orbit.target), 1e-3f);
}

TEST(RenderCamera, SplitPanesTileTheImageWithoutOverlap) {
  for (int count : {1, 2, 3, 4, 5, 9}) {
    const auto panes = split_viewports(count, 641, 359);
    ASSERT_EQ(int(panes.size()), count);
    std::vector<int> covered(641 * 359, 0);
    for (const Viewport& v : panes)
      for (int y = v.y; y < v.y + v.height; ++y)
        for (int x = v.x; x < v.x + v.width; ++x) ++covered[y * 641 + x];
    EXPECT_EQ(*std::max_element(covered.begin(), covered.end()), 1) << count;
  }
}

TEST(RenderLook, HexColoursAndMaterialSettings) {
  const vec3 c = parse_hex_color("#ff8000");
  EXPECT_FLOAT_EQ(c.x, 1.0f);
  EXPECT_NEAR(c.y, 128.0f / 255.0f, 1e-6f);
  EXPECT_FLOAT_EQ(c.z, 0.0f);
  for (const char* bad : {"#ff80", "#gg0000", "", "#ff80000"}) EXPECT_THROW(parse_hex_color(bad), Error) << bad;
  Look look;
  apply_color_setting(look, "cloth=#000000");
  EXPECT_EQ(look.colors[static_cast<std::size_t>(MaterialId::Cloth)], vec3(0.0f));
  EXPECT_THROW(apply_color_setting(look, "shoes=#000000"), Error);
  EXPECT_THROW(apply_color_setting(look, "cloth"), Error);
}

}  // namespace
}  // namespace gestura
