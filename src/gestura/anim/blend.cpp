#include "gestura/anim/blend.hpp"

#include <algorithm>
#include <vector>

namespace gestura {

namespace {

// Per-thread scratch, grown once: blending allocates nothing in steady state.
struct BlendScratch {
  std::vector<float> claimed, scale;
  void resize(std::size_t n) {
    if (claimed.size() < n) claimed.resize(n), scale.resize(n);
  }
};

float layer_weight(const BlendLayer& l, std::size_t j) {
  return std::max(0.0f, l.weight * (l.joint_weights.empty() ? 1.0f : l.joint_weights[j]));
}

}  // namespace

void blend_layers(std::span<const BlendLayer> layers, const Pose& rest, Pose& out) {
  const std::size_t n = rest.size();
  out.resize(n);
  thread_local BlendScratch scratch;
  scratch.resize(n);
  float* claimed = scratch.claimed.data();
  float* scale = scratch.scale.data();

  // Distinct priorities, highest first (few layers: a tiny local sort).
  int priorities[16];
  int level_count = 0;
  for (const BlendLayer& l : layers)
    if (std::find(priorities, priorities + level_count, l.priority) == priorities + level_count && level_count < 16)
      priorities[level_count++] = l.priority;
  std::sort(priorities, priorities + level_count, std::greater<int>());

  // Accumulate layer-major into `out` (contiguous passes over joints).
  std::fill_n(claimed, n, 0.0f);
  std::fill(out.rotations.begin(), out.rotations.end(), quat(0, 0, 0, 0));
  std::fill(out.translations.begin(), out.translations.end(), vec3(0.0f));
  std::fill(out.scales.begin(), out.scales.end(), vec3(0.0f));
  for (int level = 0; level < level_count; ++level) {
    // scale[j]: how much of this level's summed weight fits in what is left on joint j.
    std::fill_n(scale, n, 0.0f);
    for (const BlendLayer& l : layers)
      if (l.priority == priorities[level])
        for (std::size_t j = 0; j < n; ++j) scale[j] += layer_weight(l, j);
    for (std::size_t j = 0; j < n; ++j) {
      const float sum = scale[j], room = 1.0f - claimed[j];
      const float fit = sum > room ? (sum > 0.0f ? room / sum : 0.0f) : 1.0f;
      claimed[j] += sum * fit;
      scale[j] = fit;
    }
    for (const BlendLayer& l : layers) {
      if (l.priority != priorities[level]) continue;
      const quat* r = l.pose->rotations.data();
      const vec3* t = l.pose->translations.data();
      const vec3* s = l.pose->scales.data();
      for (std::size_t j = 0; j < n; ++j) {
        const float w = layer_weight(l, j) * scale[j];
        quat& acc = out.rotations[j];
        // Keep every contribution on the hemisphere of what is accumulated so far.
        const float signed_w = (acc.w * r[j].w + acc.x * r[j].x + acc.y * r[j].y + acc.z * r[j].z) < 0.0f ? -w : w;
        acc.w += signed_w * r[j].w, acc.x += signed_w * r[j].x, acc.y += signed_w * r[j].y, acc.z += signed_w * r[j].z;
        out.translations[j] += w * t[j];
        out.scales[j] += w * s[j];
      }
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (claimed[j] <= 1e-6f) {  // no layer touches this joint
      out.rotations[j] = rest.rotations[j];
      out.translations[j] = rest.translations[j];
      out.scales[j] = rest.scales[j];
      continue;
    }
    const float inv = 1.0f / claimed[j];  // normalise what the layers claimed
    out.rotations[j] = glm::normalize(out.rotations[j]);
    out.translations[j] *= inv;
    out.scales[j] *= inv;
  }
}

void make_additive(const Pose& reference, const Pose& pose, Pose& delta) {
  const std::size_t n = pose.size();
  delta.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    delta.rotations[j] = glm::normalize(glm::inverse(reference.rotations[j]) * pose.rotations[j]);
    delta.translations[j] = pose.translations[j] - reference.translations[j];
    const vec3& rs = reference.scales[j];
    delta.scales[j] = pose.scales[j] / glm::max(glm::abs(rs), vec3(1e-8f)) * glm::sign(rs + vec3(1e-20f));
  }
}

void apply_additive(const Pose& delta, float weight, std::span<const float> joint_weights, Pose& inout) {
  const std::size_t n = inout.size();
  const quat identity(1, 0, 0, 0);
  for (std::size_t j = 0; j < n; ++j) {
    const float w = weight * (joint_weights.empty() ? 1.0f : joint_weights[j]);
    if (w == 0.0f) continue;
    const quat d = w == 1.0f ? delta.rotations[j] : nlerp(identity, delta.rotations[j], w);
    inout.rotations[j] = glm::normalize(inout.rotations[j] * d);
    inout.translations[j] += w * delta.translations[j];
    inout.scales[j] *= glm::mix(vec3(1.0f), delta.scales[j], w);
  }
}

void crossfade(const Pose& a, const Pose& b, float t, Pose& out) {
  const std::size_t n = a.size();
  out.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    out.rotations[j] = nlerp(a.rotations[j], b.rotations[j], t);
    out.translations[j] = glm::mix(a.translations[j], b.translations[j], t);
    out.scales[j] = glm::mix(a.scales[j], b.scales[j], t);
  }
}

float crossfade_weight(float t, float length) {
  if (!(length > 0.0f)) return 1.0f;
  const float u = std::clamp(t / length, 0.0f, 1.0f);
  return u * u * (3.0f - 2.0f * u);
}

}  // namespace gestura
