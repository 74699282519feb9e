// blend_layers / apply_additive / crossfade against a plain per-joint reference of their contract
// (written here, one joint at a time, the way blend.hpp states it), on both SIMD paths, with joint
// counts that leave every kind of remainder after the 4- and 8-joint blocks.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gestura/anim/blend.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

constexpr SimdPath kPaths[] = {SimdPath::Portable, SimdPath::Avx2};
bool available(SimdPath path) { return path != SimdPath::Avx2 || cpu_has_avx2_fma(); }

Pose random_pose(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Pose p;
  p.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    quat q = glm::normalize(quat(u(rng), u(rng), u(rng), u(rng)));
    p.rotations[j] = q;  // either hemisphere: blending must keep them from cancelling
    p.translations[j] = vec3(u(rng), u(rng), u(rng));
    p.scales[j] = vec3(1.0f) + 0.2f * vec3(u(rng), u(rng), u(rng));
  }
  return p;
}

std::vector<float> random_mask(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> m(n);
  for (float& w : m) {
    const float r = u(rng);
    w = r < 0.3f ? 0.0f : r < 0.5f ? 1.0f : u(rng);  // many joints fully off or on
  }
  return m;
}

// The contract of blend.hpp, one joint at a time.
Pose reference_blend(std::span<const BlendLayer> layers, const Pose& rest) {
  const std::size_t n = rest.size();
  Pose out;
  out.resize(n);
  std::vector<const BlendLayer*> order;
  for (const BlendLayer& l : layers)
    if (!l.additive) order.push_back(&l);
  std::stable_sort(order.begin(), order.end(), [](const BlendLayer* a, const BlendLayer* b) { return a->priority > b->priority; });
  for (std::size_t j = 0; j < n; ++j) {
    auto weight = [&](const BlendLayer& l) {
      return std::max(0.0f, l.weight * (l.joint_weights.empty() ? 1.0f : l.joint_weights[j]));
    };
    std::vector<float> w(order.size());
    float claimed = 0.0f;
    for (std::size_t first = 0; first < order.size();) {
      std::size_t last = first;
      float sum = 0.0f;
      while (last < order.size() && order[last]->priority == order[first]->priority) sum += weight(*order[last++]);
      const float room = 1.0f - claimed;
      const float fit = sum > room ? (sum > 0.0f ? room / sum : 0.0f) : 1.0f;
      for (std::size_t k = first; k < last; ++k) w[k] = weight(*order[k]) * fit;
      claimed += sum * fit;
      first = last;
    }
    quat r(0, 0, 0, 0);
    vec3 t(0.0f), s(0.0f);
    if (claimed <= 1e-6f) {
      r = rest.rotations[j], t = rest.translations[j], s = rest.scales[j];
    } else {
      for (std::size_t k = 0; k < order.size(); ++k) {
        const quat& q = order[k]->pose->rotations[j];
        const float sign = glm::dot(r, q) < 0.0f ? -1.0f : 1.0f;
        r = r + (sign * w[k] / claimed) * q;
        t += (w[k] / claimed) * order[k]->pose->translations[j];
        s += (w[k] / claimed) * order[k]->pose->scales[j];
      }
    }
    r = glm::normalize(r);
    for (const BlendLayer& l : layers) {
      if (!l.additive) continue;
      const float a = l.weight * (l.joint_weights.empty() ? 1.0f : l.joint_weights[j]);
      const quat d = a == 1.0f ? l.pose->rotations[j] : nlerp(quat(1, 0, 0, 0), l.pose->rotations[j], a);
      r = glm::normalize(r * d);
      t += a * l.pose->translations[j];
      s *= glm::mix(vec3(1.0f), l.pose->scales[j], a);
    }
    out.rotations[j] = r, out.translations[j] = t, out.scales[j] = s;
  }
  return out;
}

// Rotations up to sign (q and −q are one rotation); translations and scales directly.
void expect_same_pose(const Pose& a, const Pose& b, float tolerance, const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_GT(std::abs(glm::dot(a.rotations[j], b.rotations[j])), 1.0f - tolerance) << what << " joint " << j;
    EXPECT_NEAR(glm::length(a.rotations[j]), 1.0f, 1e-5f) << what << " joint " << j;
    EXPECT_LT(glm::length(a.translations[j] - b.translations[j]), tolerance) << what << " joint " << j;
    EXPECT_LT(glm::length(a.scales[j] - b.scales[j]), tolerance) << what << " joint " << j;
  }
}

}  // namespace

TEST(BlendKernel, MatchesThePerJointContractOnEveryPathAndJointCount) {
  std::mt19937 rng(7);
  for (std::size_t n : {1u, 3u, 4u, 7u, 8u, 9u, 15u, 67u}) {
    const Pose rest = random_pose(n, rng), a = random_pose(n, rng), b = random_pose(n, rng), c = random_pose(n, rng);
    Pose delta = random_pose(n, rng);
    for (quat& q : delta.rotations) q = glm::normalize(glm::slerp(quat(1, 0, 0, 0), q, 0.3f));  // small additive turns
    const std::vector<float> m1 = random_mask(n, rng), m2 = random_mask(n, rng), m3 = random_mask(n, rng);
    const std::vector<std::vector<BlendLayer>> cases = {
        {{&a, 0.5f}, {&b, 0.3f}, {&c, 0.2f}},                                        // one level, no masks
        {{&a, 2.0f}, {&b, 1.0f}},                                                    // weights above 1 normalised
        {{&a, 1.0f, {}, 0}, {&b, 1.0f, m1, 1}, {&delta, 0.7f, {}, 0, true}},         // W3b's shape
        {{&a, 0.6f, m1, 2}, {&b, 0.8f, m2, 2}, {&c, 1.0f, m3, 0}},                   // levels sharing room
        {{&a, 1.0f, m1, 1}, {&b, 0.5f, m2, 0}, {&delta, 1.0f, m3, 0, true}},         // rest where nobody claims
        {{&a, 0.0f}, {&delta, 0.4f, {}, 0, true}},                                   // nothing blended: rest + additive
        {{&a, 1.0f}, {&delta, 1.0f, {}, 0, true}, {&delta, 0.5f, m2, 0, true}},      // two additive layers
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const Pose expected = reference_blend(cases[k], rest);
      for (SimdPath path : kPaths) {
        if (!available(path)) continue;
        Pose out;
        blend_layers(cases[k], rest, out, path);
        SCOPED_TRACE("joints " + std::to_string(n) + ", case " + std::to_string(k) +
                     (path == SimdPath::Avx2 ? ", AVX2" : ", portable"));
        expect_same_pose(out, expected, 2e-5f, "blend");
      }
    }
  }
}

TEST(BlendKernel, PortableAndAvx2AgreeWithin1e5) {
  if (!cpu_has_avx2_fma()) GTEST_SKIP() << "CPU without AVX2+FMA";
  std::mt19937 rng(11);
  const std::size_t n = 67;
  const Pose rest = random_pose(n, rng), a = random_pose(n, rng), b = random_pose(n, rng), delta = random_pose(n, rng);
  const std::vector<float> m = random_mask(n, rng);
  const BlendLayer layers[] = {{&a, 1.0f, {}, 0}, {&b, 0.8f, m, 1}, {&delta, 0.6f, m, 0, true}};
  Pose p, v;
  blend_layers(layers, rest, p, SimdPath::Portable);
  blend_layers(layers, rest, v, SimdPath::Avx2);
  for (std::size_t j = 0; j < n; ++j) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(p.rotations[j][c], v.rotations[j][c], 1e-5f) << "joint " << j;  // same sign too
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(p.translations[j][c], v.translations[j][c], 1e-5f) << "joint " << j;
      EXPECT_NEAR(p.scales[j][c], v.scales[j][c], 1e-5f) << "joint " << j;
    }
  }
}

TEST(BlendKernel, InPlaceAdditiveAndOutputOverALayerGiveWhatASeparateOutputGets) {
  std::mt19937 rng(3);
  for (std::size_t n : {5u, 13u, 67u}) {
    const Pose rest = random_pose(n, rng), delta = random_pose(n, rng);
    Pose a = random_pose(n, rng), b = random_pose(n, rng);
    const std::vector<float> m = random_mask(n, rng);
    for (SimdPath path : kPaths) {
      if (!available(path)) continue;
      // apply_additive works in place; blend_layers with an additive layer writes elsewhere.
      Pose in_place = a, separate;
      apply_additive(delta, 0.8f, m, in_place, path);
      const BlendLayer with_delta[] = {{&a, 1.0f}, {&delta, 0.8f, m, 0, true}};
      blend_layers(with_delta, rest, separate, path);
      expect_same_pose(in_place, separate, 1e-6f, "in place");
      // The output may be one of the layers.
      Pose expected, over_b = b;
      const BlendLayer two[] = {{&a, 0.25f}, {&b, 0.75f, m, 0}};
      blend_layers(two, rest, expected, path);
      const BlendLayer two_over[] = {{&a, 0.25f}, {&over_b, 0.75f, m, 0}};
      blend_layers(two_over, rest, over_b, path);
      expect_same_pose(over_b, expected, 1e-6f, "over a layer");
    }
  }
}

TEST(BlendKernel, CrossfadeIsNlerpAndMixOnEveryPath) {
  std::mt19937 rng(5);
  const Pose a = random_pose(11, rng), b = random_pose(11, rng);
  for (SimdPath path : kPaths) {
    if (!available(path)) continue;
    Pose out;
    crossfade(a, b, 0.3f, out, path);
    for (std::size_t j = 0; j < 11; ++j) {
      EXPECT_GT(std::abs(glm::dot(out.rotations[j], nlerp(a.rotations[j], b.rotations[j], 0.3f))), 1.0f - 1e-6f);
      EXPECT_LT(glm::length(out.translations[j] - glm::mix(a.translations[j], b.translations[j], 0.3f)), 1e-6f);
    }
  }
}

TEST(BlendKernel, MismatchedInputsAreNamedErrors) {
  std::mt19937 rng(1);
  const Pose rest = random_pose(5, rng), small = random_pose(4, rng);
  Pose out;
  const BlendLayer wrong_size[] = {{&rest, 1.0f}, {&small, 1.0f}};
  EXPECT_THROW(blend_layers(wrong_size, rest, out), Error);
  const float short_mask[] = {1, 1};
  const BlendLayer wrong_mask[] = {{&rest, 1.0f, short_mask}};
  EXPECT_THROW(blend_layers(wrong_mask, rest, out), Error);
  const BlendLayer no_pose[] = {{nullptr, 1.0f}};
  EXPECT_THROW(blend_layers(no_pose, rest, out), Error);
  Pose target = rest;
  EXPECT_THROW(apply_additive(small, 1.0f, {}, target), Error);
}
