#include "gestura/anim/blend.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "gestura/anim/blend_kernel.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

namespace blend_detail {

#if defined(__SSE2__)
void run_portable(const BlendJob& job) { run<F4>(job); }
bool plan_portable(const PlanJob& job) { return plan<F4>(job); }
#else
void run_portable(const BlendJob& job) { run<F1>(job); }
bool plan_portable(const PlanJob& job) { return plan<F1>(job); }
#endif

}  // namespace blend_detail

namespace {

using blend_detail::BlendJob;
using blend_detail::BlendSource;

// Per-thread scratch, grown once: blending allocates nothing in steady state.
struct BlendScratch {
  std::vector<float> weights;    // one row of per-joint weights per masked or prioritised layer, + rest
  std::vector<blend_detail::PlanLayer> plan;
  std::vector<std::size_t> order;  // blended layers by priority, highest first (stable)
  std::vector<BlendSource> sources, additive;
};

BlendScratch& scratch() {
  thread_local BlendScratch s;
  return s;
}

BlendSource source_of(const Pose& pose, const float* weights, float weight) {
  return {&pose.rotations[0].x, &pose.translations[0].x, &pose.scales[0].x, weights, weight};
}

[[noreturn, gnu::cold]] void fail_layer(const Pose* pose, std::span<const float> mask, std::size_t n, const char* what,
                                        std::size_t index) {
  const std::string layer = std::string(what) + ": layer " + std::to_string(index);
  if (!pose) throw Error(layer + " has no pose");
  if (!mask.empty() && mask.size() < n)
    throw Error(layer + " has " + std::to_string(mask.size()) + " joint weights for " + std::to_string(n) + " joints");
  throw Error(layer + " has " + std::to_string(pose->size()) + " joints, expected " + std::to_string(n));
}

// Every array of the pose holds n joints, the mask none or at least n.
inline void check_layer(const Pose* pose, std::span<const float> mask, std::size_t n, const char* what, std::size_t index) {
  if (!pose || pose->rotations.size() != n || pose->translations.size() != n || pose->scales.size() != n ||
      (!mask.empty() && mask.size() < n)) [[unlikely]]
    fail_layer(pose, mask, n, what, index);
}

inline void size_output(Pose& out, std::size_t n) {
  if (out.rotations.size() != n || out.translations.size() != n || out.scales.size() != n) out.resize(n);
}

// `path` is resolved (Portable or Avx2).
void run(const BlendJob& job, SimdPath path) {
#ifdef GESTURA_HAS_AVX2_PATH
  if (path == SimdPath::Avx2) return blend_detail::run_avx2(job);
#endif
  blend_detail::run_portable(job);
}

inline SimdPath resolve(SimdPath path, const char* what) {
  if (path == SimdPath::Auto) return cpu_has_avx2_fma() ? SimdPath::Avx2 : SimdPath::Portable;
  return resolve_simd_path(path, what);
}

// The blended (non-additive) layers as sources whose weights sum to 1 on every joint.
// `path` is resolved (Portable or Avx2).
void plan_sources(std::span<const BlendLayer> layers, const Pose& rest, SimdPath path, BlendScratch& s) {
  const std::size_t n = rest.size();
  s.order.clear();
  bool masked = false;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (layers[i].additive) continue;
    s.order.push_back(i);
    masked |= !layers[i].joint_weights.empty();
  }
  // Highest priority first, layer order kept within a priority (the order the sum is taken in):
  // an insertion sort, stable and free of allocations for the few layers there are.
  for (std::size_t i = 1; i < s.order.size(); ++i)
    for (std::size_t k = i; k > 0 && layers[s.order[k - 1]].priority < layers[s.order[k]].priority; --k)
      std::swap(s.order[k - 1], s.order[k]);
  const bool one_level = s.order.empty() || layers[s.order.front()].priority == layers[s.order.back()].priority;

  if (one_level && !masked) {
    // Fast path: one weight per layer, normalised once here.
    float sum = 0.0f;
    for (std::size_t i : s.order) sum += std::max(0.0f, layers[i].weight);
    if (sum <= 1e-6f) {
      s.sources.push_back(source_of(rest, nullptr, 1.0f));
      return;
    }
    for (std::size_t i : s.order)
      if (layers[i].weight > 0.0f) s.sources.push_back(source_of(*layers[i].pose, nullptr, layers[i].weight / sum));
    return;
  }

  // General path: the weights per joint (blend_kernel.hpp's plan), then one source per layer.
  const std::size_t rows = s.order.size();  // s.weights holds at least rows + 1 rows
  s.plan.clear();
  for (std::size_t r = 0; r < rows; ++r) {
    const BlendLayer& l = layers[s.order[r]];
    s.plan.push_back({l.joint_weights.empty() ? nullptr : l.joint_weights.data(), l.weight, s.weights.data() + r * n,
                      r == 0 || l.priority != layers[s.order[r - 1]].priority});
  }
  float* rest_weights = s.weights.data() + rows * n;
  const blend_detail::PlanJob job{n, s.plan.data(), rows, rest_weights};
  bool rest_needed;
#ifdef GESTURA_HAS_AVX2_PATH
  if (path == SimdPath::Avx2) rest_needed = blend_detail::plan_avx2(job);
  else rest_needed = blend_detail::plan_portable(job);
#else
  rest_needed = blend_detail::plan_portable(job);
#endif
  for (std::size_t r = 0; r < rows; ++r) s.sources.push_back(source_of(*layers[s.order[r]].pose, s.weights.data() + r * n, 0.0f));
  if (rest_needed) s.sources.push_back(source_of(rest, rest_weights, 0.0f));
}

}  // namespace

void blend_layers(std::span<const BlendLayer> layers, const Pose& rest, Pose& out, SimdPath path) {
  const std::size_t n = rest.size();
  check_layer(&rest, {}, n, "blend_layers (rest pose)", 0);
  // The common case — no masks, one priority, a few layers — is planned on the stack, weights
  // normalised once here; everything else goes through plan_sources.
  constexpr std::size_t kFew = 8;
  bool simple = layers.size() <= kFew;
  float sum = 0.0f;
  const int priority = layers.empty() ? 0 : layers[0].priority;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const BlendLayer& l = layers[i];
    check_layer(l.pose, l.joint_weights, n, "blend_layers", i);
    simple &= l.joint_weights.empty() && (l.additive || l.priority == priority);
    if (!l.additive) sum += std::max(0.0f, l.weight);
  }
  path = resolve(path, "blend_layers");
  size_output(out, n);
  if (n == 0) return;
  if (simple) {
    BlendSource sources[kFew + 1], additive[kFew];
    std::size_t source_count = 0, additive_count = 0;
    for (const BlendLayer& l : layers) {
      if (l.additive) additive[additive_count++] = source_of(*l.pose, nullptr, l.weight);
      else if (l.weight > 0.0f && sum > 1e-6f) sources[source_count++] = source_of(*l.pose, nullptr, l.weight / sum);
    }
    if (source_count == 0) sources[source_count++] = source_of(rest, nullptr, 1.0f);
    run({n, sources, source_count, additive, additive_count, &out.rotations[0].x, &out.translations[0].x, &out.scales[0].x},
        path);
    return;
  }
  BlendScratch& s = scratch();
  s.sources.clear();
  s.additive.clear();
  // Weight rows (their pointers go into the sources, so sized once before any is taken): one per
  // blended layer and one for the rest pose, then one per masked additive layer.
  std::size_t blended = 0, masked_additive = 0;
  for (const BlendLayer& l : layers) {
    if (!l.additive) ++blended;
    else if (!l.joint_weights.empty()) ++masked_additive;
  }
  s.weights.resize((blended + 1 + masked_additive) * n);
  plan_sources(layers, rest, path, s);
  float* row = s.weights.data() + (blended + 1) * n;
  for (const BlendLayer& l : layers) {
    if (!l.additive) continue;
    if (l.joint_weights.empty()) {
      s.additive.push_back(source_of(*l.pose, nullptr, l.weight));
      continue;
    }
    for (std::size_t j = 0; j < n; ++j) row[j] = l.weight * l.joint_weights[j];
    s.additive.push_back(source_of(*l.pose, row, 0.0f));
    row += n;
  }
  run({n, s.sources.data(), s.sources.size(), s.additive.data(), s.additive.size(), &out.rotations[0].x,
       &out.translations[0].x, &out.scales[0].x},
      path);
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

void apply_additive(const Pose& delta, float weight, std::span<const float> joint_weights, Pose& inout,
                    SimdPath path) {
  const std::size_t n = inout.size();
  check_layer(&delta, joint_weights, n, "apply_additive", 0);
  if (n == 0) return;
  const BlendLayer layers[] = {{&inout, 1.0f}, {&delta, weight, joint_weights, 0, true}};
  blend_layers(layers, inout, inout, path);
}

void crossfade(const Pose& a, const Pose& b, float t, Pose& out, SimdPath path) {
  const std::size_t n = a.size();
  check_layer(&a, {}, n, "crossfade", 0);
  check_layer(&b, {}, n, "crossfade", 1);
  path = resolve(path, "crossfade");
  size_output(out, n);
  if (n == 0) return;
  const BlendSource sources[] = {source_of(a, nullptr, 1.0f - t), source_of(b, nullptr, t)};
  run({n, sources, 2, nullptr, 0, &out.rotations[0].x, &out.translations[0].x, &out.scales[0].x}, path);
}

float crossfade_weight(float t, float length) {
  if (!(length > 0.0f)) return 1.0f;
  const float u = std::clamp(t / length, 0.0f, 1.0f);
  return u * u * (3.0f - 2.0f * u);
}

}  // namespace gestura
