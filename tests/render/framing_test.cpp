// The interpreter framing on real signing (elbows and raised hands in view at every moment, crown
// near the top, hips at the bottom), the follow camera, and the occluder capsules' shading: a hand
// in front of the chest darkens the chest beside it.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/occluders.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/sentence/signer.hpp"
#include "support/signing_avatar.hpp"

namespace gestura {
namespace {

const Avatar& avatar() { return test::signing_avatar().avatar; }

Clip said(const std::string& text, float speed = 1.0f) {
  DefaultLexicon lexicon;
  const Signer signer(avatar(), lexicon.layers());
  SayOptions options;
  options.speed = speed;
  return signer.say(text, options).clip;
}

vec3 ndc(const Camera& c, const vec3& p) {
  const vec4 clip = c.projection * c.view * vec4(p, 1.0f);
  return vec3(clip) / clip.w;
}

std::vector<std::vector<vec3>> positions(const Clip& clip, float fps) {
  const Skeleton& s = avatar().skeleton;
  std::vector<std::vector<vec3>> out;
  Pose pose;
  std::vector<mat4> model(s.size());
  for (float t = 0.0f; t <= clip.duration + 1e-4f; t += 1.0f / fps) {
    sample_clip(clip, t, WrapMode::Clamp, rest_pose(s), pose);
    local_to_model(s, pose, model);
    std::vector<vec3> p(s.size());
    model_positions(model, p);
    out.push_back(std::move(p));
  }
  return out;
}

int joint(const char* name) {
  const int j = avatar().skeleton.find(name);
  EXPECT_GE(j, 0) << name;
  return j;
}

class Framing : public ::testing::TestWithParam<const char*> {};

TEST_P(Framing, FrontKeepsElbowsAndRaisedHandsInViewAtEveryMoment) {
  const Clip clip = said(GetParam());
  const FramingBox box = framing_box(avatar().mesh, avatar().skeleton, &clip);
  ASSERT_TRUE(box.has_limbs);
  const Camera camera = preset_camera(CameraPreset::Front, box, 16.0f / 9.0f);
  int raised = 0;
  for (const std::vector<vec3>& p : positions(clip, 30.0f)) {
    for (const char* elbow : {"l_elbow", "r_elbow"}) {
      const vec3 q = ndc(camera, p[static_cast<std::size_t>(joint(elbow))]);
      EXPECT_LT(std::abs(q.x), 1.0f) << GetParam() << " " << elbow;
      EXPECT_LT(std::abs(q.y), 1.0f) << GetParam() << " " << elbow;
    }
    for (const char* hand : {"l_wrist", "r_wrist", "l_middle_tip", "r_middle_tip"}) {
      const vec3 world = p[static_cast<std::size_t>(joint(hand))];
      if (world.y <= box.hips_y) continue;
      ++raised;
      const vec3 q = ndc(camera, world);
      EXPECT_LT(std::abs(q.x), 1.0f) << GetParam() << " " << hand;
      EXPECT_LT(std::abs(q.y), 1.0f) << GetParam() << " " << hand;
    }
  }
  EXPECT_GT(raised, 10) << "the hands sign above the hips";
  // The crown under the top edge (lower when the hands rise above the head); the signer on the
  // image's centre line.
  std::vector<mat4> model(avatar().skeleton.size());
  local_to_model(avatar().skeleton, rest_pose(avatar().skeleton), model);
  const vec3 crown(0.0f, box.max.y, 0.0f);
  EXPECT_GT(ndc(camera, crown).y, 0.6f);
  EXPECT_LT(ndc(camera, crown).y, 1.0f);
  EXPECT_NEAR(ndc(camera, vec3(model[static_cast<std::size_t>(joint("skullbase"))][3])).x, 0.0f, 0.02f);
  // The hips near the bottom edge (a little above it when wide or raised signs need the camera
  // further back: HOUSE's roof above the head puts them at -0.74); the knees are not in the picture.
  EXPECT_LE(ndc(camera, vec3(model[static_cast<std::size_t>(joint("l_hip"))][3])).y, -0.70f);
  EXPECT_LT(ndc(camera, vec3(model[static_cast<std::size_t>(joint("l_knee"))][3])).y, -1.0f);
}

INSTANTIATE_TEST_SUITE_P(Signs, Framing, ::testing::Values("house", "sad", "library", "my mother lives in a big house"));

TEST(FollowFraming, TightensOnHandsAtTheFaceAndGlides) {
  // The thumb at the chin. With the citation-timing model the hold there is 0.51 s (was 0.59 s), too
  // short for the gliding camera to settle fully: it comes at least 5 % closer.
  const Clip clip = said("mother");
  const FramingBox box = framing_box(avatar().mesh, avatar().skeleton, &clip);
  const int frames = static_cast<int>(clip.duration * 30.0f) + 1;
  const std::vector<FramingBox> follow = follow_framing(box, avatar().skeleton, clip, 30.0f, frames);
  ASSERT_EQ(static_cast<int>(follow.size()), frames);
  const Camera front = preset_camera(CameraPreset::Front, box, 16.0f / 9.0f);
  float tightest = 1e9f, largest_step = 0.0f;
  vec3 previous = preset_camera(CameraPreset::Follow, follow[0], 16.0f / 9.0f).eye;
  for (const FramingBox& b : follow) {
    const Camera c = preset_camera(CameraPreset::Follow, b, 16.0f / 9.0f);
    tightest = std::min(tightest, glm::distance(c.eye, c.target));
    largest_step = std::max(largest_step, glm::distance(c.eye, previous));
    previous = c.eye;
    EXPECT_GE(b.hips_y, box.hips_y - 1e-5f);
  }
  EXPECT_LT(tightest, 0.95f * glm::distance(front.eye, front.target)) << "the follow camera moves in on the face";
  EXPECT_LT(largest_step, 0.03f) << "metres per frame: no jumps";
}

// The follow camera glides at every tempo and on signs that move far: a camera that steps more than
// 3 cm in one frame at 30 fps (0.9 m/s) reads as a cut, not a glide. Slow tempos hold longest, so
// there the camera has time to zoom all the way in, and it used to do it in half a second (5 cm a frame).
TEST(FollowFraming, NeverJumpsAtAnyTempo) {
  for (const char* text : {"mother", "my mother lives in a big house"})
    for (float speed : {0.5f, 0.7f, 2.0f}) {
      const Clip clip = said(text, speed);
      const FramingBox box = framing_box(avatar().mesh, avatar().skeleton, &clip);
      const int frames = static_cast<int>(clip.duration * 30.0f) + 1;
      const std::vector<FramingBox> follow = follow_framing(box, avatar().skeleton, clip, 30.0f, frames);
      float largest_step = 0.0f;
      vec3 previous = preset_camera(CameraPreset::Follow, follow[0], 16.0f / 9.0f).eye;
      for (const FramingBox& b : follow) {
        const vec3 eye = preset_camera(CameraPreset::Follow, b, 16.0f / 9.0f).eye;
        largest_step = std::max(largest_step, glm::distance(eye, previous));
        previous = eye;
      }
      EXPECT_LT(largest_step, 0.03f) << text << " at speed " << speed << ": metres per frame";
    }
}

TEST(Occluders, ArmsAndHandsGetCapsulesOfTheirThickness) {
  const OccluderSet set = find_occluders(avatar().skeleton, avatar().mesh);
  ASSERT_EQ(set.capsules.size(), 10u);
  for (const Occluder& o : set.capsules) {
    EXPECT_GT(o.radius, 0.008f);
    EXPECT_LT(o.radius, 0.07f);
    EXPECT_TRUE(o.part == BodyPart::LeftArm || o.part == BodyPart::RightArm);
  }
  EXPECT_EQ(set.joint_part[static_cast<std::size_t>(joint("r_index2"))], BodyPart::RightArm);
  EXPECT_EQ(set.joint_part[static_cast<std::size_t>(joint("skullbase"))], BodyPart::Head);
  EXPECT_EQ(set.joint_part[static_cast<std::size_t>(joint("vt6"))], BodyPart::Trunk);
  Skeleton bare;
  bare.add_joint("root", -1, vec3(0.0f));
  EXPECT_TRUE(find_occluders(bare, avatar().mesh).capsules.empty());
}

// Rendering the same pose with and without the capsules: the chest beside and below the raised
// right hand (where the key light's shadow falls) is darker with them, the far side of the image
// (background) and the top of the head are unchanged.
TEST(Occluders, AHandInFrontOfTheChestShadowsIt) {
  unsetenv("DISPLAY");
  HeadlessGlContext context;
  const Clip clip = said("coffee");  // both hands held in front of the chest (COFFEE grinds one fist on the other)
  RenderSubject subject{avatar().skeleton, avatar().mesh, clip};
  Animator animator(subject);
  animator.pose_at(0.5f * clip.duration);
  constexpr int kW = 320, kH = 180;
  const FramingBox box = framing_box(subject.mesh, subject.skeleton, &clip);
  const std::vector<View> views{{preset_camera(CameraPreset::Front, box, float(kW) / kH), {0, 0, kW, kH}}};
  const auto draw = [&](bool shade) {
    Renderer renderer;
    renderer.upload(subject.mesh);
    if (shade) renderer.set_occluders(find_occluders(subject.skeleton, subject.mesh));
    renderer.resize(kW, kH);
    renderer.render(views, animator.skinning(), animator.morph_weights());
    Image image;
    renderer.read_pixels(image);
    return image;
  };
  const Image plain = draw(false), shaded = draw(true);
  const auto luminance = [](const Image& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      }
    return sum / ((x1 - x0) * (y1 - y0));
  };
  // Where the hand is on screen: its palm projected.
  const vec3 palm = vec3(animator.model()[static_cast<std::size_t>(joint("r_middle1"))][3]);
  const vec3 q = ndc(views[0].camera, palm);
  const int hx = static_cast<int>((q.x * 0.5f + 0.5f) * kW), hy = static_cast<int>((0.5f - q.y * 0.5f) * kH);
  ASSERT_TRUE(hx > 20 && hx < kW - 20 && hy > 20 && hy < kH - 20) << hx << "," << hy;
  // Chest region around the hand (the hand itself is lit the same either way, the chest is not).
  double darker = 0.0;
  int pixels = 0;
  for (int y = std::max(0, hy - 25); y < std::min(kH, hy + 25); ++y)
    for (int x = std::max(0, hx - 25); x < std::min(kW, hx + 25); ++x) {
      const std::uint8_t *a = plain.pixel(x, y), *b = shaded.pixel(x, y);
      darker += (a[0] + a[1] + a[2]) - (b[0] + b[1] + b[2]);
      ++pixels;
    }
  EXPECT_GT(darker / pixels, 3.0) << "mean RGB sum lost around the hand";
  EXPECT_NEAR(luminance(plain, 0, 0, 40, 40), luminance(shaded, 0, 0, 40, 40), 0.01) << "background untouched";
}

}  // namespace
}  // namespace gestura
