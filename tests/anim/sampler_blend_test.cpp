#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gestura/anim/blend.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

Skeleton chain(int n) {
  Skeleton s;
  for (int i = 0; i < n; ++i) s.add_joint("j" + std::to_string(i), i - 1, vec3(0, 0.1f, 0));
  return s;
}

Clip wave_clip(const Skeleton& s, float duration, int keys) {
  Clip c;
  c.name = "wave";
  c.duration = duration;
  c.resize_joints(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    c.rotations[j].interpolation = Interpolation::Slerp;
    for (int k = 0; k < keys; ++k) {
      const float t = duration * static_cast<float>(k) / static_cast<float>(keys - 1);
      c.rotations[j].add(t, glm::angleAxis(std::sin(t * 3 + static_cast<float>(j)), vec3(0, 0, 1)));
    }
  }
  c.translations[0].add(0, vec3(0));
  c.translations[0].add(duration, vec3(1, 0, 0));
  c.channel("smile").add(0, 0.0f);
  c.channel("smile").add(duration, 1.0f);
  return c;
}

}  // namespace

TEST(Sampler, ForwardPlaybackWithCursorsEqualsStatelessSampling) {
  const Skeleton s = chain(5);
  const Clip c = wave_clip(s, 3.0f, 31);
  validate(c, s);
  const Pose rest = rest_pose(s);
  Sampler sampler(c);
  Pose a, b;
  float ch_a[1], ch_b[1];
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> any(-1.0f, 4.0f);
  // Forward at 30 Hz, then random seeks (backwards and far forwards) on the same sampler.
  std::vector<float> times;
  for (int f = 0; f < 90; ++f) times.push_back(static_cast<float>(f) / 30.0f);
  for (int i = 0; i < 200; ++i) times.push_back(any(rng));
  for (float t : times) {
    sampler.sample(t, WrapMode::Clamp, rest, a, ch_a);
    sample_clip(c, t, WrapMode::Clamp, rest, b, ch_b);
    for (std::size_t j = 0; j < s.size(); ++j) {
      EXPECT_GT(std::abs(glm::dot(a.rotations[j], b.rotations[j])), 1 - 1e-6f);
      EXPECT_LT(glm::length(a.translations[j] - b.translations[j]), 1e-6f);
    }
    EXPECT_FLOAT_EQ(ch_a[0], ch_b[0]);
  }
}

TEST(Sampler, UntrackedJointsKeepRestAndChannelsAreSampled) {
  const Skeleton s = chain(3);
  Clip c = wave_clip(s, 2.0f, 5);
  c.rotations[2] = {};
  Pose out;
  float smile = -1;
  sample_clip(c, 1.0f, WrapMode::Clamp, rest_pose(s), out, std::span<float>(&smile, 1));
  EXPECT_FLOAT_EQ(out.rotations[2].w, 1.0f);
  EXPECT_NEAR(out.translations[1].y, 0.1f, 1e-7f);
  EXPECT_NEAR(out.translations[0].x, 0.5f, 1e-6f);
  EXPECT_NEAR(smile, 0.5f, 1e-6f);
}

TEST(Sampler, WrapModes) {
  EXPECT_FLOAT_EQ(wrap_time(2.5f, 2.0f, WrapMode::Clamp), 2.0f);
  EXPECT_FLOAT_EQ(wrap_time(-1.0f, 2.0f, WrapMode::Clamp), 0.0f);
  EXPECT_NEAR(wrap_time(2.5f, 2.0f, WrapMode::Loop), 0.5f, 1e-6f);
  EXPECT_NEAR(wrap_time(-0.5f, 2.0f, WrapMode::Loop), 1.5f, 1e-6f);
  EXPECT_NEAR(wrap_time(2.5f, 2.0f, WrapMode::PingPong), 1.5f, 1e-6f);
  EXPECT_NEAR(wrap_time(4.5f, 2.0f, WrapMode::PingPong), 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(wrap_time(std::nanf(""), 2.0f, WrapMode::Loop), 0.0f);
  EXPECT_FLOAT_EQ(wrap_time(1.0f, 0.0f, WrapMode::Loop), 0.0f);
}

TEST(Sampler, ValidateRejectsAMismatchedClip) {
  const Skeleton s = chain(3);
  Clip c = wave_clip(s, 1.0f, 3);
  c.resize_joints(2);
  EXPECT_THROW(validate(c, s), Error);
}

TEST(Blend, EqualWeightsOfTwoRotationsGiveTheHalfwayRotation) {
  const Skeleton s = chain(2);
  Pose a = rest_pose(s), b = rest_pose(s), out;
  a.rotations[0] = glm::angleAxis(deg(10), vec3(0, 0, 1));
  b.rotations[0] = -glm::angleAxis(deg(50), vec3(0, 0, 1));  // opposite hemisphere on purpose
  const BlendLayer layers[] = {{&a, 1.0f}, {&b, 1.0f}};
  blend_layers(layers, rest_pose(s), out);
  EXPECT_GT(std::abs(glm::dot(out.rotations[0], glm::angleAxis(deg(30), vec3(0, 0, 1)))), 1 - 1e-6f);
}

TEST(Blend, MaskAndPriorityLetOneMotionsArmsOverrideAnothersLegs) {
  const Skeleton s = chain(4);  // pretend joints 0-1 are legs, 2-3 arms
  Pose walk = rest_pose(s), wave = rest_pose(s), out;
  for (auto& q : walk.rotations) q = glm::angleAxis(deg(20), vec3(1, 0, 0));
  for (auto& q : wave.rotations) q = glm::angleAxis(deg(60), vec3(0, 0, 1));
  const float arms[] = {0, 0, 1, 1};
  const BlendLayer layers[] = {{&walk, 1.0f, {}, 0}, {&wave, 1.0f, arms, 1}};
  blend_layers(layers, rest_pose(s), out);
  EXPECT_GT(std::abs(glm::dot(out.rotations[0], walk.rotations[0])), 1 - 1e-6f);
  EXPECT_GT(std::abs(glm::dot(out.rotations[1], walk.rotations[1])), 1 - 1e-6f);
  EXPECT_GT(std::abs(glm::dot(out.rotations[2], wave.rotations[2])), 1 - 1e-6f);
  EXPECT_GT(std::abs(glm::dot(out.rotations[3], wave.rotations[3])), 1 - 1e-6f);
  // A partial mask leaves the remainder to the lower layer.
  const float half[] = {0, 0, 0.5f, 0.5f};
  const BlendLayer mixed[] = {{&walk, 1.0f, {}, 0}, {&wave, 1.0f, half, 1}};
  blend_layers(mixed, rest_pose(s), out);
  const quat expected = nlerp(wave.rotations[2], walk.rotations[2], 0.5f);
  EXPECT_GT(std::abs(glm::dot(out.rotations[2], expected)), 1 - 1e-5f);
}

TEST(Blend, NoLayerOnAJointGivesRest) {
  const Skeleton s = chain(2);
  Pose a = rest_pose(s), out;
  a.rotations[1] = glm::angleAxis(1.0f, vec3(0, 1, 0));
  const float mask[] = {1, 0};
  const BlendLayer layers[] = {{&a, 1.0f, mask}};
  Pose rest = rest_pose(s);
  rest.rotations[1] = glm::angleAxis(0.3f, vec3(1, 0, 0));
  blend_layers(layers, rest, out);
  EXPECT_GT(std::abs(glm::dot(out.rotations[1], rest.rotations[1])), 1 - 1e-6f);
}

TEST(Blend, AdditiveLayerAddsTheDifference) {
  const Skeleton s = chain(2);
  const Pose ref = rest_pose(s);
  Pose nod = ref, base = ref, delta;
  nod.rotations[1] = glm::angleAxis(deg(15), vec3(1, 0, 0));
  nod.translations[0] += vec3(0, 0.05f, 0);
  make_additive(ref, nod, delta);
  base.rotations[1] = glm::angleAxis(deg(30), vec3(1, 0, 0));
  apply_additive(delta, 1.0f, {}, base);
  EXPECT_GT(std::abs(glm::dot(base.rotations[1], glm::angleAxis(deg(45), vec3(1, 0, 0)))), 1 - 1e-6f);
  EXPECT_NEAR(base.translations[0].y, 0.1f + 0.05f, 1e-6f);  // rest offset + the nod's lift
  // Half weight, and a mask that excludes joint 1.
  Pose half = ref;
  apply_additive(delta, 0.5f, {}, half);
  EXPECT_GT(std::abs(glm::dot(half.rotations[1], glm::angleAxis(deg(7.5f), vec3(1, 0, 0)))), 1 - 1e-5f);
  Pose masked = ref;
  const float mask[] = {1, 0};
  apply_additive(delta, 1.0f, mask, masked);
  EXPECT_FLOAT_EQ(masked.rotations[1].w, 1.0f);
}

TEST(Blend, CrossfadeGoesFromOneClipToTheOtherSmoothly) {
  const Skeleton s = chain(1);
  Pose a = rest_pose(s), b = rest_pose(s), out;
  b.translations[0] = vec3(1, 0, 0);
  EXPECT_FLOAT_EQ(crossfade_weight(0.0f, 0.5f), 0.0f);
  EXPECT_FLOAT_EQ(crossfade_weight(0.5f, 0.5f), 1.0f);
  EXPECT_FLOAT_EQ(crossfade_weight(0.25f, 0.5f), 0.5f);
  crossfade(a, b, crossfade_weight(0.25f, 0.5f), out);
  EXPECT_NEAR(out.translations[0].x, 0.5f, 1e-6f);
  // Ease in: slow at the start.
  EXPECT_LT(crossfade_weight(0.05f, 0.5f), 0.1f * 0.5f / 0.5f);
}
