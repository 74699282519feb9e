#pragma once
// Internal to blend.cpp / blend.avx2.cpp: the blending kernel over plain arrays, one template for
// every vector width (core/simd.hpp). blend.cpp turns layers, masks and priorities into a BlendJob
// whose per-joint weights already sum to 1; the kernel then makes one pass over the joints, a block
// of V::kLanes joints at a time, with every source accumulated in registers:
//
//   rotation    = Σ w_k · q_k, each q_k negated when it lies in the other hemisphere from the sum so far
//   translation = Σ w_k · t_k,   scale = Σ w_k · s_k
//   then per additive source: rotation ⊗= nlerp(identity, d, w) (unnormalised), translation += w·dt,
//   scale *= 1 + w·(ds − 1); and one normalisation of the rotation at the end (the quaternion
//   product is bilinear, so normalising once equals normalising after every step).
//
// Preconditions (checked by blend.cpp): count ≥ 1; every array holds `count` joints (rotations x y z w,
// translations and scales x y z, weights one float); source_count ≥ 1. The output may be one of the
// inputs (a block reads all its inputs before it writes).
#include <cstddef>

#include "gestura/core/simd.hpp"

namespace gestura::blend_detail {

// Trivial types on purpose (no member initialisers): nothing here may compile to an inline function
// that both the portable and the AVX2 file would emit.
struct BlendSource {
  const float* rotations;
  const float* translations;
  const float* scales;
  const float* weights;  // one per joint, or null: `weight` on every joint
  float weight;
};

struct BlendJob {
  std::size_t count;
  const BlendSource* sources;
  std::size_t source_count;
  const BlendSource* additive;
  std::size_t additive_count;
  float* rotations;
  float* translations;
  float* scales;
};

// The per-joint weights of the blended layers under blend.cpp's priority rules. Layers come highest
// priority first; on each joint a level's summed weight is fitted into what higher levels left, then
// all weights are divided by what was claimed, and joints nobody claims get rest weight 1.
struct PlanLayer {
  const float* mask;  // one per joint, or null: 1 everywhere
  float weight;
  float* row;         // out: the layer's weight per joint
  bool starts_level;  // the first layer of its priority level
};

struct PlanJob {
  std::size_t count;
  const PlanLayer* layers;
  std::size_t layer_count;  // ≥ 1
  float* rest_row;          // out: 1 where no layer claims the joint, else 0
};

void run_portable(const BlendJob& job);
void run_avx2(const BlendJob& job);  // only after cpu_has_avx2_fma()
// Both return whether some joint takes the rest pose.
bool plan_portable(const PlanJob& job);
bool plan_avx2(const PlanJob& job);  // only after cpu_has_avx2_fma()

namespace {

using namespace gestura::simd;

// Scalar: every source of the job has one weight for all joints (known at compile time, so the
// common case carries no per-source test).
template <class V, bool Scalar = false>
inline V weight_at(const BlendSource& s, std::size_t j) {
  if constexpr (Scalar) return set1(s.weight, V{});
  return s.weights ? load(s.weights + j, V{}) : set1(s.weight, V{});
}
// The same weights in the lane order of load_quats.
template <class V, bool Scalar = false>
inline V quat_weight_at(const BlendSource& s, std::size_t j) {
  if constexpr (Scalar) return set1(s.weight, V{});
  return s.weights ? load_in_quat_order(s.weights + j, V{}) : set1(s.weight, V{});
}

// The weights of a block of joints spread over the block's packed vec3 (3 registers).
template <class V, bool Scalar = false>
inline void spread(const BlendSource& s, V w, V& e0, V& e1, V& e2) {
  if (!Scalar && s.weights) expand3(w, e0, e1, e2);
  else e0 = e1 = e2 = w;
}

// Joints [j, j + kLanes): sources from joint j on, output at `rotations`/`translations`/`scales`.
// Rotations first, then translations and scales: fewer values live at once, no register spills.
template <class V, bool Scalar = false>
inline void blend_block(const BlendJob& job, std::size_t j, float* rotations, float* translations, float* scales) {
  constexpr std::size_t L = V::kLanes;
  const V zero = set1(0.0f, V{}), one = set1(1.0f, V{});
  V ax, ay, az, aw;
  {
    const BlendSource& src = job.sources[0];
    const V w = quat_weight_at<V, Scalar>(src, j);
    load_quats(src.rotations + 4 * j, ax, ay, az, aw);
    ax = w * ax, ay = w * ay, az = w * az, aw = w * aw;
  }
  for (std::size_t k = 1; k < job.source_count; ++k) {
    const BlendSource& src = job.sources[k];
    V qx, qy, qz, qw;
    load_quats(src.rotations + 4 * j, qx, qy, qz, qw);
    const V dot = fmadd(ax, qx, ay * qy) + fmadd(az, qz, aw * qw);
    const V w = negate_where(quat_weight_at<V, Scalar>(src, j), less(dot, zero));  // stay on the hemisphere of the sum
    ax = fmadd(w, qx, ax), ay = fmadd(w, qy, ay), az = fmadd(w, qz, az), aw = fmadd(w, qw, aw);
  }
  for (std::size_t k = 0; k < job.additive_count; ++k) {
    const BlendSource& src = job.additive[k];
    const V w = quat_weight_at<V, Scalar>(src, j);
    V dx, dy, dz, dw;
    load_quats(src.rotations + 4 * j, dx, dy, dz, dw);
    // nlerp(identity, d, w) before normalising: d taken onto identity's hemisphere unless w is 1
    // (then d itself), and (w·dx, w·dy, w·dz, 1 − w + w·dw), which is d exactly at w = 1.
    const auto flip = both(less(dw, zero), not_equal(w, one));
    dx = negate_where(dx, flip), dy = negate_where(dy, flip), dz = negate_where(dz, flip), dw = negate_where(dw, flip);
    const V ix = w * dx, iy = w * dy, iz = w * dz, iw = fmadd(w, dw, one - w);
    const V rx = fmadd(aw, ix, fmadd(ax, iw, fnmadd(az, iy, ay * iz)));
    const V ry = fmadd(aw, iy, fmadd(ay, iw, fnmadd(ax, iz, az * ix)));
    const V rz = fmadd(aw, iz, fmadd(az, iw, fnmadd(ay, ix, ax * iy)));
    const V rw = fnmadd(ax, ix, fnmadd(ay, iy, fnmadd(az, iz, aw * iw)));
    ax = rx, ay = ry, az = rz, aw = rw;
  }
  const V inv = rsqrt(fmadd(ax, ax, fmadd(ay, ay, fmadd(az, az, aw * aw))));
  store_quats(rotations, ax * inv, ay * inv, az * inv, aw * inv);

  // Translations and scales: the block's 3·kLanes packed floats as three registers.
  const std::size_t at = 3 * j;
  V t0, t1, t2, s0, s1, s2, e0, e1, e2;
  {
    const BlendSource& src = job.sources[0];
    spread<V, Scalar>(src, weight_at<V, Scalar>(src, j), e0, e1, e2);
    t0 = e0 * load(src.translations + at, V{}), s0 = e0 * load(src.scales + at, V{});
    t1 = e1 * load(src.translations + at + L, V{}), s1 = e1 * load(src.scales + at + L, V{});
    t2 = e2 * load(src.translations + at + 2 * L, V{}), s2 = e2 * load(src.scales + at + 2 * L, V{});
  }
  for (std::size_t k = 1; k < job.source_count; ++k) {
    const BlendSource& src = job.sources[k];
    spread<V, Scalar>(src, weight_at<V, Scalar>(src, j), e0, e1, e2);
    t0 = fmadd(e0, load(src.translations + at, V{}), t0), s0 = fmadd(e0, load(src.scales + at, V{}), s0);
    t1 = fmadd(e1, load(src.translations + at + L, V{}), t1), s1 = fmadd(e1, load(src.scales + at + L, V{}), s1);
    t2 = fmadd(e2, load(src.translations + at + 2 * L, V{}), t2), s2 = fmadd(e2, load(src.scales + at + 2 * L, V{}), s2);
  }
  for (std::size_t k = 0; k < job.additive_count; ++k) {
    const BlendSource& src = job.additive[k];
    spread<V, Scalar>(src, weight_at<V, Scalar>(src, j), e0, e1, e2);
    t0 = fmadd(e0, load(src.translations + at, V{}), t0);
    t1 = fmadd(e1, load(src.translations + at + L, V{}), t1);
    t2 = fmadd(e2, load(src.translations + at + 2 * L, V{}), t2);
    s0 = s0 * fmadd(e0, load(src.scales + at, V{}) - one, one);  // scale · mix(1, ds, w)
    s1 = s1 * fmadd(e1, load(src.scales + at + L, V{}) - one, one);
    s2 = s2 * fmadd(e2, load(src.scales + at + 2 * L, V{}) - one, one);
  }
  store(translations, t0), store(translations + L, t1), store(translations + 2 * L, t2);
  store(scales, s0), store(scales + L, s1), store(scales + 2 * L, s2);
}

// The joints past the last full block: each source's remainder copied into a padded block, blended
// there, and copied out. Jobs with very many sources take the remainder one joint at a time.
template <class V>
inline void blend_remainder(const BlendJob& job, std::size_t j) {
  constexpr std::size_t L = V::kLanes, kMaxSources = 16;
  const std::size_t n = job.count - j, sources = job.source_count + job.additive_count;
  if (sources > kMaxSources) {
    for (; j < job.count; ++j) blend_block<F1>(job, j, job.rotations + 4 * j, job.translations + 3 * j, job.scales + 3 * j);
    return;
  }
  float data[kMaxSources][11 * L];  // rotations 4L, translations 3L, scales 3L, weights L
  BlendSource padded[kMaxSources];
  for (std::size_t k = 0; k < sources; ++k) {
    const BlendSource& src = k < job.source_count ? job.sources[k] : job.additive[k - job.source_count];
    float* r = data[k];
    float* t = r + 4 * L;
    float* s = t + 3 * L;
    float* w = s + 3 * L;
    for (std::size_t i = 0; i < L; ++i) {
      const bool real = i < n;
      for (std::size_t c = 0; c < 4; ++c) r[4 * i + c] = real ? src.rotations[4 * (j + i) + c] : (c == 3 ? 1.0f : 0.0f);
      for (std::size_t c = 0; c < 3; ++c) {
        t[3 * i + c] = real ? src.translations[3 * (j + i) + c] : 0.0f;
        s[3 * i + c] = real ? src.scales[3 * (j + i) + c] : 1.0f;
      }
      w[i] = src.weights ? (real ? src.weights[j + i] : 1.0f) : 0.0f;
    }
    padded[k] = {r, t, s, src.weights ? w : nullptr, src.weight};
  }
  BlendJob block = job;
  block.sources = padded;
  block.additive = padded + job.source_count;
  float out[10 * L];
  blend_block<V>(block, 0, out, out + 4 * L, out + 7 * L);
  for (std::size_t i = 0; i < 4 * n; ++i) job.rotations[4 * j + i] = out[i];
  for (std::size_t i = 0; i < 3 * n; ++i) {
    job.translations[3 * j + i] = out[4 * L + i];
    job.scales[3 * j + i] = out[7 * L + i];
  }
}

// True when the output shares memory with no source: then blocks may overlap.
inline bool output_is_separate(const BlendJob& job) {
  const float* out = job.rotations;
  for (std::size_t k = 0; k < job.source_count; ++k)
    if (job.sources[k].rotations == out) return false;
  for (std::size_t k = 0; k < job.additive_count; ++k)
    if (job.additive[k].rotations == out) return false;
  return true;
}

template <class V, bool Scalar>
inline void run_blocks(const BlendJob& job) {
  constexpr std::size_t L = V::kLanes;
  std::size_t j = 0;
  for (; j + L <= job.count; j += L)
    blend_block<V, Scalar>(job, j, job.rotations + 4 * j, job.translations + 3 * j, job.scales + 3 * j);
  if (j == job.count) return;
  if (job.count >= L && output_is_separate(job)) {
    // The last block again, ending at the last joint: joints it repeats get the same values.
    j = job.count - L;
    blend_block<V, Scalar>(job, j, job.rotations + 4 * j, job.translations + 3 * j, job.scales + 3 * j);
  } else {
    blend_remainder<V>(job, j);
  }
}

template <class V>
inline void run(const BlendJob& job) {
  bool scalar = true;
  for (std::size_t k = 0; k < job.source_count; ++k) scalar &= job.sources[k].weights == nullptr;
  for (std::size_t k = 0; k < job.additive_count; ++k) scalar &= job.additive[k].weights == nullptr;
  if (scalar) run_blocks<V, true>(job);
  else run_blocks<V, false>(job);
}

// Joints [j, j + kLanes) of a plan; returns whether one of them takes the rest pose. Writes only
// those joints, so blocks may overlap.
template <class V>
inline bool plan_block(const PlanJob& job, std::size_t j) {
  const V zero = set1(0.0f, V{}), one = set1(1.0f, V{});
  V claimed = zero;
  for (std::size_t k = 0; k < job.layer_count;) {
    const std::size_t first = k;
    V sum = zero;
    do {
      const PlanLayer& l = job.layers[k];
      V w = set1(l.weight, V{});
      if (l.mask) w = w * load(l.mask + j, V{});
      w = max(w, zero);  // negative (and NaN) weights count as 0
      store(l.row + j, w);
      sum = sum + w;
      ++k;
    } while (k < job.layer_count && !job.layers[k].starts_level);
    const V room = one - claimed;
    const auto over = less(room, sum);
    if (any(over)) {  // the level does not fit everywhere: scale it into the room left
      const V fit = select(over, select(less(zero, sum), room / sum, zero), one);
      claimed = fmadd(sum, fit, claimed);
      for (std::size_t r = first; r < k; ++r) store(job.layers[r].row + j, load(job.layers[r].row + j, V{}) * fit);
    } else {
      claimed = claimed + sum;
    }
  }
  const auto touched = less(set1(1e-6f, V{}), claimed);
  if (any(not_equal(claimed, one))) {  // divide by what was claimed (nothing to do where that is 1)
    const V inv = select(touched, one / claimed, zero);
    for (std::size_t r = 0; r < job.layer_count; ++r) store(job.layers[r].row + j, load(job.layers[r].row + j, V{}) * inv);
  }
  const V rest = select(touched, zero, one);
  store(job.rest_row + j, rest);
  return any(less(zero, rest));
}

template <class V>
inline bool plan(const PlanJob& job) {
  constexpr std::size_t L = V::kLanes;
  bool rest = false;
  if (job.count < L) {
    for (std::size_t j = 0; j < job.count; ++j) rest |= plan_block<F1>(job, j);
    return rest;
  }
  std::size_t j = 0;
  for (; j + L <= job.count; j += L) rest |= plan_block<V>(job, j);
  if (j < job.count) rest |= plan_block<V>(job, job.count - L);  // overlapping the last full block
  return rest;
}

}  // namespace
}  // namespace gestura::blend_detail
