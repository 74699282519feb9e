#include "gestura/anim/blend.hpp"

#include <algorithm>
#include <vector>

namespace gestura {

void blend_layers(std::span<const BlendLayer> layers, const Pose& rest, Pose& out) {
  const std::size_t n = rest.size();
  out.resize(n);
  // Distinct priorities, highest first (few layers: a tiny local sort).
  int priorities[16];
  int level_count = 0;
  for (const BlendLayer& l : layers) {
    if (std::find(priorities, priorities + level_count, l.priority) == priorities + level_count && level_count < 16)
      priorities[level_count++] = l.priority;
  }
  std::sort(priorities, priorities + level_count, std::greater<int>());

  for (std::size_t j = 0; j < n; ++j) {
    vec3 t(0.0f), s(0.0f);
    quat r(0, 0, 0, 0);
    float claimed = 0.0f;
    const quat* reference = nullptr;  // hemisphere of the first contributor
    for (int level = 0; level < level_count && claimed < 1.0f; ++level) {
      float level_sum = 0.0f;
      for (const BlendLayer& l : layers)
        if (l.priority == priorities[level])
          level_sum += std::max(0.0f, l.weight * (l.joint_weights.empty() ? 1.0f : l.joint_weights[j]));
      if (level_sum <= 0.0f) continue;
      const float room = 1.0f - claimed;
      const float scale = level_sum > room ? room / level_sum : 1.0f;
      for (const BlendLayer& l : layers) {
        if (l.priority != priorities[level]) continue;
        const float w = scale * std::max(0.0f, l.weight * (l.joint_weights.empty() ? 1.0f : l.joint_weights[j]));
        if (w <= 0.0f) continue;
        const quat& q = l.pose->rotations[j];
        if (!reference) reference = &q;
        const float sign = glm::dot(*reference, q) < 0.0f ? -w : w;
        r.w += sign * q.w, r.x += sign * q.x, r.y += sign * q.y, r.z += sign * q.z;
        t += w * l.pose->translations[j];
        s += w * l.pose->scales[j];
      }
      claimed += std::min(level_sum, room);
    }
    if (claimed <= 1e-6f) {
      out.rotations[j] = rest.rotations[j];
      out.translations[j] = rest.translations[j];
      out.scales[j] = rest.scales[j];
      continue;
    }
    const float inv = 1.0f / claimed;  // normalise what the layers claimed
    out.rotations[j] = glm::normalize(r);
    out.translations[j] = t * inv;
    out.scales[j] = s * inv;
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
