#pragma once
// Internal to the hot kernels: fixed-width float vectors, so that one kernel template compiles to
//   F4 — SSE2, 4 lanes (every x86-64: the portable path),
//   F8 — AVX2 + FMA, 8 lanes (only in files built with -mavx2 -mfma, called after cpu_has_avx2_fma()),
//   F1 — plain C++, 1 lane (other CPUs).
// A kernel works on blocks of V::kLanes items: quaternions and vec3 stay packed in memory (x y z w /
// x y z per item, as glm stores them). Quaternions are transposed to one register per component on
// load (in the lane order of load_in_quat_order); packed vec3 are handled as 3 registers of floats,
// with per-item factors spread over them by expand3.
//
// Everything here has internal linkage (an unnamed namespace): each file that includes it gets its
// own copy compiled for its own instruction set, so the linker can never hand an AVX2 copy of a
// helper to code that runs on a CPU without AVX2. Include nothing here that defines inline
// functions with external linkage for the same reason (no glm, no standard containers).
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define GESTURA_SIMD_HAS_F8 1
#endif

namespace gestura::simd {
namespace {

// --- F1: one lane -------------------------------------------------------------------------------

struct F1 {
  static constexpr std::size_t kLanes = 1;
  float v;
};
inline F1 operator+(F1 a, F1 b) { return {a.v + b.v}; }
inline F1 operator-(F1 a, F1 b) { return {a.v - b.v}; }
inline F1 operator*(F1 a, F1 b) { return {a.v * b.v}; }
inline F1 fmadd(F1 a, F1 b, F1 c) { return {a.v * b.v + c.v}; }  // a·b + c
inline F1 fnmadd(F1 a, F1 b, F1 c) { return {c.v - a.v * b.v}; }  // c − a·b
inline F1 operator/(F1 a, F1 b) { return {a.v / b.v}; }
inline F1 max(F1 a, F1 b) { return {a.v > b.v ? a.v : b.v}; }  // b when a is NaN, as maxps
inline F1 select(bool mask, F1 a, F1 b) { return mask ? a : b; }  // a where mask holds, else b
inline bool any(bool mask) { return mask; }
inline unsigned bits(bool mask) { return mask ? 1u : 0u; }
inline F1 sqrt(F1 a) { return {__builtin_sqrtf(a.v)}; }
inline bool equal(F1 a, F1 b) { return a.v == b.v; }
inline bool either(bool a, bool b) { return a || b; }
inline bool load_mask(const int* p, F1) { return *p != 0; }  // nonzero = set
inline F1 load_int(const int* p, F1) { return {static_cast<float>(*p)}; }
inline F1 load(const float* p, F1) { return {*p}; }
inline void store(float* p, F1 a) { *p = a.v; }
inline F1 set1(float x, F1) { return {x}; }
// Lanes where `mask` holds get `a` negated.
inline F1 negate_where(F1 a, bool mask) { return {mask ? -a.v : a.v}; }
inline bool less(F1 a, F1 b) { return a.v < b.v; }
inline bool less_equal(F1 a, F1 b) { return a.v <= b.v; }
inline bool not_equal(F1 a, F1 b) { return a.v != b.v; }
inline bool both(bool a, bool b) { return a && b; }
inline F1 rsqrt(F1 a) { return {1.0f / __builtin_sqrtf(a.v)}; }
inline void load_quats(const float* p, F1& x, F1& y, F1& z, F1& w) { x = {p[0]}, y = {p[1]}, z = {p[2]}, w = {p[3]}; }
inline void store_quats(float* p, F1 x, F1 y, F1 z, F1 w) { p[0] = x.v, p[1] = y.v, p[2] = z.v, p[3] = w.v; }
// Lane l's quaternion to dst[l], for lanes below n.
inline void scatter_quats(F1 x, F1 y, F1 z, F1 w, float* const* dst, std::size_t n) {
  if (n) dst[0][0] = x.v, dst[0][1] = y.v, dst[0][2] = z.v, dst[0][3] = w.v;
}
// Per-item values in the lane order load_quats() gives (F8 permutes; here the identity).
inline F1 load_in_quat_order(const float* p, F1) { return {*p}; }
// The per-item value `w` spread over a block of packed vec3: register i holds floats 3·i … of the block.
inline void expand3(F1 w, F1& e0, F1& e1, F1& e2) { e0 = e1 = e2 = w; }

#if defined(__SSE2__)
// --- F4: SSE2 -----------------------------------------------------------------------------------

struct F4 {
  static constexpr std::size_t kLanes = 4;
  __m128 v;
};
inline F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline F4 fmadd(F4 a, F4 b, F4 c) { return {_mm_add_ps(_mm_mul_ps(a.v, b.v), c.v)}; }
inline F4 fnmadd(F4 a, F4 b, F4 c) { return {_mm_sub_ps(c.v, _mm_mul_ps(a.v, b.v))}; }
inline F4 operator/(F4 a, F4 b) { return {_mm_div_ps(a.v, b.v)}; }
inline F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
inline F4 select(F4 mask, F4 a, F4 b) { return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))}; }
inline bool any(F4 mask) { return _mm_movemask_ps(mask.v) != 0; }
inline unsigned bits(F4 mask) { return static_cast<unsigned>(_mm_movemask_ps(mask.v)); }  // bit i = lane i
inline F4 sqrt(F4 a) { return {_mm_sqrt_ps(a.v)}; }
inline F4 equal(F4 a, F4 b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
inline F4 either(F4 a, F4 b) { return {_mm_or_ps(a.v, b.v)}; }
inline F4 load_mask(const int* p, F4) { return {_mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))}; }  // all bits per lane
inline F4 load_int(const int* p, F4) { return {_mm_cvtepi32_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))}; }
inline F4 load(const float* p, F4) { return {_mm_loadu_ps(p)}; }
inline void store(float* p, F4 a) { _mm_storeu_ps(p, a.v); }
inline F4 set1(float x, F4) { return {_mm_set1_ps(x)}; }
inline F4 negate_where(F4 a, F4 mask) { return {_mm_xor_ps(a.v, _mm_and_ps(mask.v, _mm_set1_ps(-0.0f)))}; }
inline F4 less(F4 a, F4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline F4 less_equal(F4 a, F4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
inline F4 not_equal(F4 a, F4 b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
inline F4 both(F4 a, F4 b) { return {_mm_and_ps(a.v, b.v)}; }
// 1/√x to about 2e-7 relative: the 12-bit estimate refined by one Newton step (cheaper than sqrt + div).
inline F4 rsqrt(F4 a) {
  const __m128 y = _mm_rsqrt_ps(a.v);
  return {_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), y),
                     _mm_sub_ps(_mm_set1_ps(3.0f), _mm_mul_ps(_mm_mul_ps(a.v, y), y)))};
}
inline void load_quats(const float* p, F4& x, F4& y, F4& z, F4& w) {
  __m128 r0 = _mm_loadu_ps(p), r1 = _mm_loadu_ps(p + 4), r2 = _mm_loadu_ps(p + 8), r3 = _mm_loadu_ps(p + 12);
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  x = {r0}, y = {r1}, z = {r2}, w = {r3};
}
inline void store_quats(float* p, F4 x, F4 y, F4 z, F4 w) {
  _MM_TRANSPOSE4_PS(x.v, y.v, z.v, w.v);
  _mm_storeu_ps(p, x.v), _mm_storeu_ps(p + 4, y.v), _mm_storeu_ps(p + 8, z.v), _mm_storeu_ps(p + 12, w.v);
}
inline F4 load_in_quat_order(const float* p, F4) { return {_mm_loadu_ps(p)}; }
inline void scatter_quats(F4 x, F4 y, F4 z, F4 w, float* const* dst, std::size_t n) {
  _MM_TRANSPOSE4_PS(x.v, y.v, z.v, w.v);
  const __m128 q[4] = {x.v, y.v, z.v, w.v};
  for (std::size_t l = 0; l < 4; ++l)
    if (l < n) _mm_storeu_ps(dst[l], q[l]);
}
inline void expand3(F4 w, F4& e0, F4& e1, F4& e2) {
  e0 = {_mm_shuffle_ps(w.v, w.v, _MM_SHUFFLE(1, 0, 0, 0))};  // w0 w0 w0 w1
  e1 = {_mm_shuffle_ps(w.v, w.v, _MM_SHUFFLE(2, 2, 1, 1))};  // w1 w1 w2 w2
  e2 = {_mm_shuffle_ps(w.v, w.v, _MM_SHUFFLE(3, 3, 3, 2))};  // w2 w3 w3 w3
}
#endif

#if defined(GESTURA_SIMD_HAS_F8)
// --- F8: AVX2 + FMA -----------------------------------------------------------------------------

struct F8 {
  static constexpr std::size_t kLanes = 8;
  __m256 v;
};
inline F8 operator+(F8 a, F8 b) { return {_mm256_add_ps(a.v, b.v)}; }
inline F8 operator-(F8 a, F8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline F8 operator*(F8 a, F8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline F8 fmadd(F8 a, F8 b, F8 c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }
inline F8 fnmadd(F8 a, F8 b, F8 c) { return {_mm256_fnmadd_ps(a.v, b.v, c.v)}; }
inline F8 operator/(F8 a, F8 b) { return {_mm256_div_ps(a.v, b.v)}; }
inline F8 max(F8 a, F8 b) { return {_mm256_max_ps(a.v, b.v)}; }
inline F8 select(F8 mask, F8 a, F8 b) { return {_mm256_blendv_ps(b.v, a.v, mask.v)}; }
inline bool any(F8 mask) { return _mm256_movemask_ps(mask.v) != 0; }
inline unsigned bits(F8 mask) { return static_cast<unsigned>(_mm256_movemask_ps(mask.v)); }
inline F8 sqrt(F8 a) { return {_mm256_sqrt_ps(a.v)}; }
inline F8 equal(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
inline F8 either(F8 a, F8 b) { return {_mm256_or_ps(a.v, b.v)}; }
inline F8 load_mask(const int* p, F8) { return {_mm256_castsi256_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)))}; }
inline F8 load_int(const int* p, F8) { return {_mm256_cvtepi32_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)))}; }
inline F8 load(const float* p, F8) { return {_mm256_loadu_ps(p)}; }
inline void store(float* p, F8 a) { _mm256_storeu_ps(p, a.v); }
inline F8 set1(float x, F8) { return {_mm256_set1_ps(x)}; }
inline F8 negate_where(F8 a, F8 mask) { return {_mm256_xor_ps(a.v, _mm256_and_ps(mask.v, _mm256_set1_ps(-0.0f)))}; }
inline F8 less(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
inline F8 less_equal(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)}; }
inline F8 not_equal(F8 a, F8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)}; }
inline F8 both(F8 a, F8 b) { return {_mm256_and_ps(a.v, b.v)}; }
inline F8 rsqrt(F8 a) {
  const __m256 y = _mm256_rsqrt_ps(a.v);
  return {_mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y),
                        _mm256_fnmadd_ps(_mm256_mul_ps(a.v, y), y, _mm256_set1_ps(3.0f)))};
}
// Eight packed quaternions ↔ x, y, z, w registers. Four full loads and one 4×4 transpose per 128-bit
// half, no lane crossing: lane i holds item kQuatLane[i] (0 2 4 6 | 1 3 5 7), so per-item values
// that meet quaternion components are loaded with load_in_quat_order().
inline void load_quats(const float* p, F8& x, F8& y, F8& z, F8& w) {
  const __m256 r0 = _mm256_loadu_ps(p), r1 = _mm256_loadu_ps(p + 8);
  const __m256 r2 = _mm256_loadu_ps(p + 16), r3 = _mm256_loadu_ps(p + 24);
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
  const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
  x = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0))};
  y = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2))};
  z = {_mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0))};
  w = {_mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
}
inline void store_quats(float* p, F8 x, F8 y, F8 z, F8 w) {
  // The same transpose per half brings each item's x y z w back together.
  const __m256 t0 = _mm256_unpacklo_ps(x.v, y.v), t1 = _mm256_unpackhi_ps(x.v, y.v);
  const __m256 t2 = _mm256_unpacklo_ps(z.v, w.v), t3 = _mm256_unpackhi_ps(z.v, w.v);
  _mm256_storeu_ps(p, _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)));
  _mm256_storeu_ps(p + 8, _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)));
  _mm256_storeu_ps(p + 16, _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)));
  _mm256_storeu_ps(p + 24, _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2)));
}
inline F8 load_in_quat_order(const float* p, F8) {
  return {_mm256_permutevar8x32_ps(_mm256_loadu_ps(p), _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7))};
}
// Lane l (natural order) of x, y, z, w as one quaternion to dst[l], for lanes below n.
inline void scatter_quats(F8 x, F8 y, F8 z, F8 w, float* const* dst, std::size_t n) {
  const __m256 t0 = _mm256_unpacklo_ps(x.v, y.v), t1 = _mm256_unpackhi_ps(x.v, y.v);
  const __m256 t2 = _mm256_unpacklo_ps(z.v, w.v), t3 = _mm256_unpackhi_ps(z.v, w.v);
  const __m256 r[4] = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                       _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
  for (std::size_t l = 0; l < 4; ++l) {  // r[l] holds lane l (low half) and lane l + 4 (high half)
    if (l < n) _mm_storeu_ps(dst[l], _mm256_castps256_ps128(r[l]));
    if (l + 4 < n) _mm_storeu_ps(dst[l + 4], _mm256_extractf128_ps(r[l], 1));
  }
}
inline void expand3(F8 w, F8& e0, F8& e1, F8& e2) {
  e0 = {_mm256_permutevar8x32_ps(w.v, _mm256_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2))};
  e1 = {_mm256_permutevar8x32_ps(w.v, _mm256_setr_epi32(2, 3, 3, 3, 4, 4, 4, 5))};
  e2 = {_mm256_permutevar8x32_ps(w.v, _mm256_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7))};
}
#endif

}  // namespace
}  // namespace gestura::simd
