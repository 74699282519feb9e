// Headless rendering of the default avatar: works without a display, body pixels land where the
// body is, presets see different things, GPU and CPU skinning agree, morphs and colours apply.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "gestura/core/error.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/renderer.hpp"
#include "support/avatar_subject.hpp"

namespace gestura {
namespace {

constexpr int kW = 320, kH = 180;

class HeadlessRender : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    unsetenv("DISPLAY");  // headless must not need an X server
    unsetenv("WAYLAND_DISPLAY");
    context_ = new HeadlessGlContext();
    figure_ = &default_avatar_subject();
  }
  static void TearDownTestSuite() { delete context_; }
  void SetUp() override {
    renderer_ = std::make_unique<Renderer>(look_);
    renderer_->upload(figure_->mesh);
    renderer_->resize(kW, kH);
    animator_ = std::make_unique<Animator>(*figure_);
    box_ = framing_box(figure_->mesh, figure_->skeleton);
  }
  Image draw(const std::vector<View>& views, SkinningDevice path = SkinningDevice::Gpu, std::vector<float> morphs = {}) {
    renderer_->set_look(look_);
    if (morphs.empty()) morphs.assign(animator_->morph_weights().begin(), animator_->morph_weights().end());
    renderer_->render(views, animator_->skinning(), morphs, path);
    Image image;
    renderer_->read_pixels(image);
    return image;
  }
  Image draw(CameraPreset preset) { return draw({View{preset_camera(preset, box_, float(kW) / kH), {0, 0, kW, kH}}}); }
  bool is_background(const Image& image, int x, int y) const {
    const std::uint8_t* p = image.pixel(x, y);
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(p[c]) - int(std::lround(look_.background[c] * 255.0f))) > 1) return false;
    return true;
  }
  int coverage(const Image& image, Viewport area = {0, 0, kW, kH}) const {
    int n = 0;
    for (int y = area.y; y < area.y + area.height; ++y)
      for (int x = area.x; x < area.x + area.width; ++x) n += !is_background(image, x, y);
    return n;
  }
  // Pixel of a model-space point under a camera (in a full-image view).
  static glm::ivec2 project(const Camera& camera, vec3 p) {
    const vec4 clip = camera.projection * camera.view * vec4(p, 1.0f);
    const vec3 ndc = vec3(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * kW), int((0.5f - ndc.y * 0.5f) * kH)};
  }
  vec3 joint_position(const char* name) const {
    const int j = figure_->skeleton.find(name);
    EXPECT_GE(j, 0) << name;
    return vec3(animator_->model()[static_cast<std::size_t>(std::max(j, 0))][3]);
  }
  std::vector<float> morph_weights(const char* name, float weight) const {
    std::vector<float> w(figure_->mesh.morphs.size(), 0.0f);
    const int m = figure_->mesh.find_morph(name);
    EXPECT_GE(m, 0) << name;
    if (m >= 0) w[static_cast<std::size_t>(m)] = weight;
    return w;
  }

  static HeadlessGlContext* context_;
  static const RenderSubject* figure_;
  Look look_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Animator> animator_;
  FramingBox box_;
};
HeadlessGlContext* HeadlessRender::context_ = nullptr;
const RenderSubject* HeadlessRender::figure_ = nullptr;

TEST_F(HeadlessRender, ContextIsOpenGlWithoutDisplay) {
  EXPECT_EQ(std::getenv("DISPLAY"), nullptr);
  EXPECT_NE(context_->description().find("EGL"), std::string::npos) << context_->description();
}

TEST_F(HeadlessRender, EveryPresetShowsTheHeadAndChestAndLeavesTheCornersEmpty) {
  for (CameraPreset preset : kCameraPresets) {
    SCOPED_TRACE(preset_name(preset));
    const Image image = draw(preset);
    const Camera camera = preset_camera(preset, box_, float(kW) / kH);
    const vec3 head = joint_position("skullbase") + vec3(0.0f, 0.09f, 0.0f);
    const vec3 chest = joint_position("vt6");
    for (vec3 p : {head, chest}) {
      const glm::ivec2 px = project(camera, p);
      ASSERT_TRUE(px.x >= 0 && px.x < kW && px.y >= 0 && px.y < kH) << px.x << "," << px.y;
      EXPECT_FALSE(is_background(image, px.x, px.y)) << "at " << px.x << "," << px.y;
    }
    EXPECT_TRUE(is_background(image, 0, 0));
    EXPECT_TRUE(is_background(image, kW - 1, 0));
    const double fraction = double(coverage(image)) / (kW * kH);
    EXPECT_GT(fraction, 0.03);
    EXPECT_LT(fraction, 0.6);
  }
}

TEST_F(HeadlessRender, FrontViewIsEmptyBesideTheBody) {
  const Image image = draw(CameraPreset::Front);
  const Camera camera = preset_camera(CameraPreset::Front, box_, float(kW) / kH);
  const glm::ivec2 beside = project(camera, joint_position("skullbase") + vec3(0.45f, 0.0f, 0.0f));
  EXPECT_TRUE(is_background(image, beside.x, beside.y));
}

TEST_F(HeadlessRender, PresetsSeeDifferentSilhouettes) {
  // The follow camera frames like the front one when nothing moves (its box is the front's here).
  const std::vector<CameraPreset> presets{CameraPreset::Front, CameraPreset::Side, CameraPreset::ThreeQuarter,
                                          CameraPreset::Top, CameraPreset::SideSection};
  std::vector<Image> images;
  for (CameraPreset preset : presets) images.push_back(draw(preset));
  for (std::size_t a = 0; a < images.size(); ++a)
    for (std::size_t b = a + 1; b < images.size(); ++b) {
      int differing = 0;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) differing += is_background(images[a], x, y) != is_background(images[b], x, y);
      EXPECT_GT(differing, kW * kH / 50) << preset_name(presets[a]) << " vs " << preset_name(presets[b]);
    }
}

TEST_F(HeadlessRender, RaisedHandAppearsWhereThePalmIs) {
  animator_->pose_at(1.0f);  // the wave: right hand up in the signing space
  const Image image = draw(CameraPreset::Front);
  const Camera camera = preset_camera(CameraPreset::Front, box_, float(kW) / kH);
  const glm::ivec2 palm = project(camera, glm::mix(joint_position("r_wrist"), joint_position("r_middle1"), 0.6f));
  EXPECT_FALSE(is_background(image, palm.x, palm.y));
  const std::uint8_t* p = image.pixel(palm.x, palm.y);
  EXPECT_GT(int(p[0]), int(p[2]) + 20) << "the hand is skin-coloured (red over blue), not shirt";
}

TEST_F(HeadlessRender, GpuAndCpuSkinningDrawTheSameImage) {
  animator_->pose_at(0.8f);
  const Image gpu = draw(CameraPreset::Front);
  const View view{preset_camera(CameraPreset::Front, box_, float(kW) / kH), {0, 0, kW, kH}};
  const Image cpu = draw({view}, SkinningDevice::Cpu);
  long total = 0;
  for (std::size_t i = 0; i < gpu.rgba.size(); ++i) total += std::abs(int(gpu.rgba[i]) - int(cpu.rgba[i]));
  EXPECT_LT(double(total) / gpu.rgba.size(), 0.5);
  EXPECT_GT(coverage(gpu), kW * kH / 30);
}

TEST_F(HeadlessRender, MorphTargetOpensTheMouthOnBothPaths) {
  Orbit face;  // close on the face from the front
  face.target = joint_position("skullbase") + vec3(0.0f, -0.02f, 0.08f);
  face.distance = 0.45f;
  const View view{orbit_camera(face, float(kW) / kH), {0, 0, kW, kH}};
  const Image closed = draw({view}, SkinningDevice::Gpu, morph_weights("mouthOpen", 0.0f));
  const Image open_gpu = draw({view}, SkinningDevice::Gpu, morph_weights("mouthOpen", 1.0f));
  const Image open_cpu = draw({view}, SkinningDevice::Cpu, morph_weights("mouthOpen", 1.0f));
  int changed = 0;
  long gpu_cpu = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      changed += std::abs(int(closed.pixel(x, y)[0]) - int(open_gpu.pixel(x, y)[0])) > 40;
      for (int c = 0; c < 3; ++c) gpu_cpu += std::abs(int(open_gpu.pixel(x, y)[c]) - int(open_cpu.pixel(x, y)[c]));
    }
  EXPECT_GT(changed, 50) << "the open mouth shows";
  EXPECT_LT(double(gpu_cpu) / (kW * kH * 3), 0.5);
}

TEST_F(HeadlessRender, BackgroundAndClothingColoursAreConfigurable) {
  look_.background = parse_hex_color("#204080");
  look_.set_color(MaterialId::Cloth, parse_hex_color("#ff0000"));
  const Image image = draw(CameraPreset::Front);
  const std::uint8_t* corner = image.pixel(0, 0);
  EXPECT_EQ(int(corner[0]), 0x20);
  EXPECT_EQ(int(corner[1]), 0x40);
  EXPECT_EQ(int(corner[2]), 0x80);
  const Camera camera = preset_camera(CameraPreset::Front, box_, float(kW) / kH);
  const glm::ivec2 chest = project(camera, joint_position("vt6") + vec3(0.0f, 0.0f, 0.08f));
  const std::uint8_t* shirt = image.pixel(chest.x, chest.y);
  EXPECT_GT(int(shirt[0]), 3 * int(shirt[1]) + 10) << "a red shirt";
}

TEST_F(HeadlessRender, SplitViewDrawsEachCameraInItsPane) {
  const std::vector<Viewport> panes = split_viewports(2, kW, kH);
  ASSERT_EQ(panes.size(), 2u);
  std::vector<View> views;
  for (std::size_t i = 0; i < 2; ++i)
    views.push_back({preset_camera(i ? CameraPreset::Top : CameraPreset::Front, box_,
                                   float(panes[i].width) / panes[i].height), panes[i]});
  const Image image = draw(views);
  EXPECT_GT(coverage(image, panes[0]), panes[0].width * panes[0].height / 30);
  EXPECT_GT(coverage(image, panes[1]), panes[1].width * panes[1].height / 30);
}

TEST_F(HeadlessRender, PreviousFramesLeaveNoTrails) {
  const Image fresh = draw(CameraPreset::Front);  // rest pose on a new renderer
  // The whole figure moved 0.6 m to its left: far outside where the rest pose draws.
  std::vector<mat4> shifted(animator_->skinning().begin(), animator_->skinning().end());
  for (mat4& m : shifted) m = glm::translate(mat4(1.0f), vec3(0.6f, 0.0f, 0.0f)) * m;
  const View view{preset_camera(CameraPreset::Front, box_, float(kW) / kH), {0, 0, kW, kH}};
  renderer_->render({&view, 1}, shifted, {});
  Image moved;
  renderer_->read_pixels(moved);
  ASSERT_NE(moved.rgba, fresh.rgba);
  EXPECT_EQ(draw(CameraPreset::Front).rgba, fresh.rgba);
}

// The resolve into the texture waits until something needs it: frames drawn and never read (or read
// straight from a one-sample target) must still leave no trace in what is resolved later.
TEST_F(HeadlessRender, UnresolvedFramesLeaveNoTrails) {
  const Image fresh = draw(CameraPreset::Front);
  const View view{preset_camera(CameraPreset::Front, box_, float(kW) / kH), {0, 0, kW, kH}};
  auto shifted_by = [&](float x) {
    std::vector<mat4> shifted(animator_->skinning().begin(), animator_->skinning().end());
    for (mat4& m : shifted) m = glm::translate(mat4(1.0f), vec3(x, 0.0f, 0.0f)) * m;
    return shifted;
  };
  renderer_->render({&view, 1}, shifted_by(0.6f), {});
  Image moved;
  renderer_->read_pixels(moved);  // resolved: the texture holds the figure on the left
  ASSERT_NE(moved.rgba, fresh.rgba);
  renderer_->render({&view, 1}, animator_->skinning(), animator_->morph_weights());  // never read
  renderer_->render({&view, 1}, shifted_by(-0.6f), {});                                // never read
  EXPECT_EQ(draw(CameraPreset::Front).rgba, fresh.rgba);

  // One sample: read_pixels() reads the drawing target; the texture a UI shows is resolved on demand.
  Renderer single(look_, Antialiasing::None);
  single.upload(figure_->mesh);
  single.resize(kW, kH);
  single.render({&view, 1}, animator_->skinning(), animator_->morph_weights());
  (void)single.resolved_texture();  // resolved once with the rest pose
  single.render({&view, 1}, shifted_by(0.6f), {});
  single.read_pixels(moved);
  single.render({&view, 1}, animator_->skinning(), animator_->morph_weights());
  Image direct;
  single.read_pixels(direct);
  ASSERT_NE(moved.rgba, direct.rgba);
  const GLuint resolved = single.resolved_texture();  // resolves (and binds framebuffers) first
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolved, 0);
  std::vector<std::uint8_t> texture(static_cast<std::size_t>(kW) * kH * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, texture.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int differing = 0;  // the texture's rows run bottom to top
  for (int y = 0; y < kH; ++y)
    differing += !std::equal(direct.pixel(0, y), direct.pixel(0, y) + kW * 4, &texture[static_cast<std::size_t>(kH - 1 - y) * kW * 4]);
  EXPECT_EQ(differing, 0);
}

TEST_F(HeadlessRender, BackgroundChangeRepaintsTheWholeImage) {
  const Image fresh = draw(CameraPreset::Front);
  look_.background = vec3(0.2f, 0.3f, 0.4f);
  const Image blue = draw(CameraPreset::Front);
  EXPECT_EQ(int(blue.pixel(0, kH - 1)[2]), 102);
  look_ = Look{};
  EXPECT_EQ(draw(CameraPreset::Front).rgba, fresh.rgba);
}

// One sample is one sample (asked for a multisampled target of 1, Mesa gives 4); all three draw
// the same figure; the edge filter changes only pixels beside an edge, and some of them.
TEST_F(HeadlessRender, OneSampleAndTheEdgeFilterDrawTheSameFigureAsMultisampling) {
  const View view{preset_camera(CameraPreset::Front, box_, float(kW) / kH), {0, 0, kW, kH}};
  auto draw_with = [&](Antialiasing antialiasing) {
    Renderer renderer(look_, antialiasing);
    renderer.upload(figure_->mesh);
    renderer.resize(kW, kH);
    EXPECT_EQ(renderer.samples(), antialiasing == Antialiasing::Msaa4 ? 4 : 1);
    renderer.render({&view, 1}, animator_->skinning(), animator_->morph_weights());
    Image image;
    renderer.read_pixels(image);
    return image;
  };
  const Image msaa = draw_with(Antialiasing::Msaa4), single = draw_with(Antialiasing::None),
              filtered = draw_with(Antialiasing::EdgeFilter);
  const int covered = coverage(msaa);
  EXPECT_NEAR(coverage(single), covered, covered / 30);
  EXPECT_NEAR(coverage(filtered), covered, covered / 30);
  int changed = 0;
  for (int y = 1; y + 1 < kH; ++y)
    for (int x = 1; x + 1 < kW; ++x) {
      if (std::equal(filtered.pixel(x, y), filtered.pixel(x, y) + 4, single.pixel(x, y))) continue;
      ++changed;
      bool beside_edge = false;  // some neighbour within 2 pixels differs strongly in the unfiltered image
      for (int dy = -2; dy <= 2 && !beside_edge; ++dy)
        for (int dx = -2; dx <= 2 && !beside_edge; ++dx) {
          const int nx = std::clamp(x + dx, 0, kW - 1), ny = std::clamp(y + dy, 0, kH - 1);
          int difference = 0;
          for (int c = 0; c < 3; ++c) difference += std::abs(int(single.pixel(nx, ny)[c]) - int(single.pixel(x, y)[c]));
          beside_edge = difference >= 10;  // the filter's contrast threshold is 1/24 of the luma range
        }
      EXPECT_TRUE(beside_edge) << x << "," << y;
    }
  EXPECT_GT(changed, 50);
}

TEST_F(HeadlessRender, TooFewSkinningMatricesAndTooManyMorphWeightsAreErrors) {
  const View view{preset_camera(CameraPreset::Front, box_, float(kW) / kH), {0, 0, kW, kH}};
  std::vector<mat4> few(3, mat4(1.0f));
  EXPECT_THROW(renderer_->render({&view, 1}, few, {}), Error);
  std::vector<float> many(figure_->mesh.morphs.size() + 1, 0.0f);
  EXPECT_THROW(renderer_->render({&view, 1}, animator_->skinning(), many), Error);
}

TEST_F(HeadlessRender, HugeTargetIsAnError) { EXPECT_THROW(renderer_->resize(100000, 100000), Error); }

}  // namespace
}  // namespace gestura
