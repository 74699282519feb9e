#pragma once
// Internal to playback_context.cpp / playback.avx2.cpp: sampling a compressed clip through a
// PlaybackContext, one kernel template for every vector width (core/simd.hpp).
//
// The context keeps the clip's animated tracks in three groups (rotations, translations, scales),
// each as structure-of-arrays over its tracks, padded to a multiple of 8 with tracks that never go
// stale and are never written out. For each track it caches the key pair the playhead sits between:
// their frames, and their decoded values (quaternions rebuilt). A sample makes three passes over a
// group:
//   1. find the tracks whose pair does not hold the frame (a block of kLanes at a time); for those,
//      the new pair from the keysets and the keys' raw codes (scalar bit reads);
//   2. decode the codes of those blocks, kLanes tracks at a time (a track that moved on by one key
//      keeps its old second key as first); a separate pass, so the scalar stores of pass 1 have
//      reached the cache before vector loads read them;
//   3. interpolate every track (rotations by nlerp) and store it at its joint.
// Decoded values and interpolation follow CompressedClip::sample operation for operation (no FMA,
// exact square root and division), so both give bit-identical poses.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "gestura/core/simd.hpp"

namespace gestura::playback_detail {

// Trivial on purpose: nothing here may compile to an inline function both files would emit.
struct Group {
  std::size_t count;    // tracks; arrays hold count rounded up to a multiple of 8
  bool rotation;        // 4 components rebuilt from 3, or 3 components
  std::uint32_t frame_count;
  // Per track, fixed while bound:
  const std::uint8_t* const* data;     // packed keys
  const std::uint64_t* const* keyset;  // null: every frame is a key
  const std::uint16_t* const* rank;
  const int* bits;
  const float* dropped;                // rotations: the component rebuilt (0..3 = x, y, z, w)
  const float* min[3];
  const float* scale[3];
  const std::uint32_t* joint;          // where the value goes
  // Per track, the cached pair:
  float* f0;        // frames of the two keys (the pair holds frames f0 ≤ f < f1)
  float* f1;
  std::uint32_t* k0;  // key index of the first (the second is k0 + 1)
  float* a[4];      // decoded first key
  float* b[4];      // decoded second key
  // Per track, between passes 1 and 2:
  int* code_a[3];   // raw codes of the keys to decode
  int* code_b[3];
  int* need_a;      // -1: decode code_a into a; 0: keep a, or
  int* shift;       // -1: a takes b (the pair moved on by one key)
  int* need_b;      // -1: decode code_b into b
  std::uint32_t* dirty;  // scratch: first track of each block pass 1 touched
};

void sample_portable(const Group& group, std::uint32_t frame, float x, float* out);
void sample_avx2(const Group& group, std::uint32_t frame, float x, float* out);  // only after cpu_has_avx2_fma()

namespace {

using namespace gestura::simd;

inline std::uint32_t read_key_bits(const std::uint8_t* data, std::uint64_t bit, unsigned bits) {
  std::uint64_t word;
  std::memcpy(&word, data + (bit >> 3), 8);  // the clip's data ends with 8 bytes of padding
  return static_cast<std::uint32_t>((word >> (bit & 7)) & ((1ull << bits) - 1));
}

// The keys around `frame` (frame ≤ f < frame + 1): first key index and the frames of both keys.
// The same search as CompressedClip::sample.
inline void find_pair(const Group& g, std::size_t t, std::uint32_t frame, std::uint32_t& k0, std::uint32_t& f0,
                      std::uint32_t& f1) {
  const std::uint64_t* keyset = g.keyset[t];
  if (!keyset) {
    k0 = frame, f0 = frame, f1 = frame + 1;
    return;
  }
  const std::uint32_t word = frame >> 6, bit = frame & 63;
  const std::uint64_t upto = ~0ull >> (63 - bit);
  const std::uint64_t before = keyset[word] & upto;  // never 0 in word 0 (frame 0 is a key)
  k0 = g.rank[t][word] + static_cast<std::uint32_t>(__builtin_popcountll(before)) - 1u;
  std::uint32_t w0 = word;
  std::uint64_t m0 = before;
  while (m0 == 0) m0 = keyset[--w0];
  f0 = 64u * w0 + 63u - static_cast<std::uint32_t>(__builtin_clzll(m0));
  std::uint32_t w1 = word;
  std::uint64_t m1 = keyset[word] & ~upto;
  while (m1 == 0) m1 = keyset[++w1];  // the last frame is a key, so this ends
  f1 = 64u * w1 + static_cast<std::uint32_t>(__builtin_ctzll(m1));
}

// Pass 1 for one stale track: its new pair and the codes still to decode.
inline void find_and_read(const Group& g, std::size_t t, std::uint32_t frame) {
  std::uint32_t k0, f0, f1;
  find_pair(g, t, frame, k0, f0, f1);
  const bool one_on = k0 == g.k0[t] + 1 && static_cast<float>(f0) == g.f1[t];
  const unsigned bits = static_cast<unsigned>(g.bits[t]);
  const std::uint64_t first = std::uint64_t{k0} * 3u * bits, second = first + 3u * bits;
  for (unsigned c = 0; c < 3; ++c) {
    if (!one_on) g.code_a[c][t] = static_cast<int>(read_key_bits(g.data[t], first + c * bits, bits));
    g.code_b[c][t] = static_cast<int>(read_key_bits(g.data[t], second + c * bits, bits));
  }
  g.shift[t] = one_on ? -1 : 0;
  g.need_a[t] = one_on ? 0 : -1;
  g.need_b[t] = -1;
  g.k0[t] = k0, g.f0[t] = static_cast<float>(f0), g.f1[t] = static_cast<float>(f1);
}

// Dequantises the codes of tracks [i, i + kLanes) (and rebuilds rotations) as CompressedClip does.
template <class V>
inline void dequantise(const Group& g, std::size_t i, int* const* code, V out[4]) {
  for (std::size_t k = 0; k < 3; ++k) out[k] = load(g.min[k] + i, V{}) + load_int(code[k] + i, V{}) * load(g.scale[k] + i, V{});
  if (!g.rotation) return;
  // rebuild_quat: the dropped component is +√(1 − |kept|²), the kept ones fill the others in order.
  const V zero = set1(0.0f, V{}), one = set1(1.0f, V{});
  const V c0 = out[0], c1 = out[1], c2 = out[2];
  const V m = sqrt(max(one - ((c0 * c0 + c1 * c1) + c2 * c2), zero));
  const V d = load(g.dropped + i, V{});
  const auto d0 = equal(d, zero), d1 = equal(d, one), d2 = equal(d, set1(2.0f, V{})), d3 = equal(d, set1(3.0f, V{}));
  out[0] = select(d0, m, c0);
  out[1] = select(d0, c0, select(d1, m, c1));
  out[2] = select(either(d0, d1), c1, select(d2, m, c2));
  out[3] = select(d3, m, c2);
}

// Pass 2 for tracks [i, i + kLanes).
template <class V>
inline void decode_block(const Group& g, std::size_t i) {
  const std::size_t components = g.rotation ? 4 : 3;
  const V need_a = load_mask(g.need_a + i, V{}), shift = load_mask(g.shift + i, V{}), need_b = load_mask(g.need_b + i, V{});
  V a[4], b[4];
  dequantise<V>(g, i, g.code_a, a);
  dequantise<V>(g, i, g.code_b, b);
  for (std::size_t c = 0; c < components; ++c) {
    const V old_b = load(g.b[c] + i, V{});
    store(g.a[c] + i, select(need_a, a[c], select(shift, old_b, load(g.a[c] + i, V{}))));
    store(g.b[c] + i, select(need_b, b[c], old_b));
  }
}

// Pass 3 for tracks [i, i + kLanes): interpolate at frame position x, store those below g.count.
template <class V>
inline void interpolate_block(const Group& g, std::size_t i, float x, float* out) {
  constexpr std::size_t L = V::kLanes;
  const std::size_t n = g.count - i < L ? g.count - i : L;
  const V f0 = load(g.f0 + i, V{}), f1 = load(g.f1 + i, V{});
  const V alpha = (set1(x, V{}) - f0) / (f1 - f0);
  if (g.rotation) {
    // nlerp(a, b, alpha) as math.hpp computes it: b onto a's hemisphere, lerp, glm::normalize.
    const V ax = load(g.a[0] + i, V{}), ay = load(g.a[1] + i, V{}), az = load(g.a[2] + i, V{}), aw = load(g.a[3] + i, V{});
    V bx = load(g.b[0] + i, V{}), by = load(g.b[1] + i, V{}), bz = load(g.b[2] + i, V{}), bw = load(g.b[3] + i, V{});
    const auto flip = less((aw * bw + ax * bx) + (ay * by + az * bz), set1(0.0f, V{}));
    bx = negate_where(bx, flip), by = negate_where(by, flip), bz = negate_where(bz, flip), bw = negate_where(bw, flip);
    const V qx = ax + (bx - ax) * alpha, qy = ay + (by - ay) * alpha, qz = az + (bz - az) * alpha, qw = aw + (bw - aw) * alpha;
    const V inv = set1(1.0f, V{}) / sqrt((qw * qw + qx * qx) + (qy * qy + qz * qz));
    float* dst[L] = {};
    for (std::size_t l = 0; l < n; ++l) dst[l] = out + 4 * std::size_t{g.joint[i + l]};
    scatter_quats(qx * inv, qy * inv, qz * inv, qw * inv, dst, n);
    return;
  }
  // glm::mix(a, b, alpha) = a·(1 − alpha) + b·alpha
  const V keep = set1(1.0f, V{}) - alpha;
  alignas(32) float v[3][L];
  for (std::size_t c = 0; c < 3; ++c) store(v[c], load(g.a[c] + i, V{}) * keep + load(g.b[c] + i, V{}) * alpha);
  for (std::size_t l = 0; l < n; ++l) {
    float* o = out + 3 * std::size_t{g.joint[i + l]};
    o[0] = v[0][l], o[1] = v[1][l], o[2] = v[2][l];
  }
}

template <class V>
inline void sample_group(const Group& group, std::uint32_t frame, float x, float* out) {
  constexpr std::size_t L = V::kLanes;
  const Group g = group;  // a local copy: stores through its pointers cannot change it, so it stays in registers
  const V here = set1(static_cast<float>(frame), V{});
  std::size_t dirty = 0;
  for (std::size_t i = 0; i < g.count; i += L) {
    const unsigned stale = bits(either(less(here, load(g.f0 + i, V{})), less_equal(load(g.f1 + i, V{}), here)));
    if (!stale) continue;
    g.dirty[dirty++] = static_cast<std::uint32_t>(i);
    for (std::size_t l = 0; l < L; ++l) {
      if ((stale >> l) & 1u) find_and_read(g, i + l, frame);
      else g.need_a[i + l] = g.shift[i + l] = g.need_b[i + l] = 0;
    }
  }
  for (std::size_t d = 0; d < dirty; ++d) decode_block<V>(g, g.dirty[d]);
  for (std::size_t i = 0; i < g.count; i += L) interpolate_block<V>(g, i, x, out);
}

}  // namespace
}  // namespace gestura::playback_detail
