// The AVX2+FMA skinning kernels. Only these functions carry the avx2/fma target, so the rest of the
// library stays runnable on any x86-64; skinning.cpp calls them only after cpu_has_avx2_fma().
#include "gestura/body/skinning_kernels.hpp"

#ifdef GESTURA_SKINNING_HAS_AVX2
#include <immintrin.h>

namespace gestura::skinning_detail {

#define GESTURA_AVX2 __attribute__((target("avx2,fma")))

namespace {

// A glm::mat4 is 16 column-major floats: one 256-bit register holds columns 0,1 and another
// columns 2,3. Blending four joints is then 8 FMAs, and transforming (x, y, z, 1) is
// lo·(x x x x y y y y) + hi·(z z z z 1 1 1 1) followed by adding the two 128-bit halves.
[[gnu::always_inline]] GESTURA_AVX2 inline void blend(const float* base, const JointIndices& j, const vec4& w,
                                                     __m256& lo, __m256& hi) {
  const float* m0 = base + 16 * j.x;
  const float* m1 = base + 16 * j.y;
  const float* m2 = base + 16 * j.z;
  const float* m3 = base + 16 * j.w;
  const __m256 w0 = _mm256_broadcast_ss(&w.x), w1 = _mm256_broadcast_ss(&w.y);
  const __m256 w2 = _mm256_broadcast_ss(&w.z), w3 = _mm256_broadcast_ss(&w.w);
  lo = _mm256_mul_ps(w0, _mm256_loadu_ps(m0));
  hi = _mm256_mul_ps(w0, _mm256_loadu_ps(m0 + 8));
  lo = _mm256_fmadd_ps(w1, _mm256_loadu_ps(m1), lo);
  hi = _mm256_fmadd_ps(w1, _mm256_loadu_ps(m1 + 8), hi);
  lo = _mm256_fmadd_ps(w2, _mm256_loadu_ps(m2), lo);
  hi = _mm256_fmadd_ps(w2, _mm256_loadu_ps(m2 + 8), hi);
  lo = _mm256_fmadd_ps(w3, _mm256_loadu_ps(m3), lo);
  hi = _mm256_fmadd_ps(w3, _mm256_loadu_ps(m3 + 8), hi);
}

// lo·(a a a a b b b b) + hi·(c c c c d d d d), halves summed: the blended matrix times (a, b, c, d).
[[gnu::always_inline]] GESTURA_AVX2 inline __m128 transform(__m256 lo, __m256 hi, const float* v, __m256 fourth) {
  const __m256 ab = _mm256_blend_ps(_mm256_broadcast_ss(v), _mm256_broadcast_ss(v + 1), 0xF0);
  const __m256 cd = _mm256_blend_ps(_mm256_broadcast_ss(v + 2), fourth, 0xF0);
  const __m256 r = _mm256_fmadd_ps(lo, ab, _mm256_mul_ps(hi, cd));
  return _mm_add_ps(_mm256_castps256_ps128(r), _mm256_extractf128_ps(r, 1));
}

// 1/√x to about 1e-7 relative: the 12-bit estimate refined by one Newton step (cheaper than sqrt + div).
[[gnu::always_inline]] GESTURA_AVX2 inline __m128 inverse_sqrt(__m128 x) {
  const __m128 y = _mm_rsqrt_ps(x);
  return _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), y), _mm_fnmadd_ps(_mm_mul_ps(x, y), y, _mm_set1_ps(3.0f)));
}
[[gnu::always_inline]] GESTURA_AVX2 inline __m256 inverse_sqrt(__m256 x) {
  const __m256 y = _mm256_rsqrt_ps(x);
  return _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y),
                       _mm256_fnmadd_ps(_mm256_mul_ps(x, y), y, _mm256_set1_ps(3.0f)));
}

[[gnu::always_inline]] GESTURA_AVX2 inline void store3(float* out, __m128 r) {
  _mm_storel_pi(reinterpret_cast<__m64*>(out), r);
  _mm_store_ss(out + 2, _mm_movehl_ps(r, r));
}

// Eight packed vec3 (24 floats) ↔ x, y, z registers; lane i is vertex i.
[[gnu::always_inline]] GESTURA_AVX2 inline void load8(const float* p, __m256& x, __m256& y, __m256& z) {
  const __m256 a = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p)), _mm_loadu_ps(p + 12), 1);
  const __m256 b = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p + 4)), _mm_loadu_ps(p + 16), 1);
  const __m256 c = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p + 8)), _mm_loadu_ps(p + 20), 1);
  // Per 128-bit lane: a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3.
  const __m256 xy = _mm256_shuffle_ps(b, c, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
  const __m256 yz = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
  x = _mm256_shuffle_ps(a, xy, _MM_SHUFFLE(2, 0, 3, 0));
  y = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
  z = _mm256_shuffle_ps(yz, c, _MM_SHUFFLE(3, 0, 3, 1));
}

[[gnu::always_inline]] GESTURA_AVX2 inline void store8(float* p, __m256 x, __m256 y, __m256 z) {
  const __m256 xy = _mm256_shuffle_ps(x, y, _MM_SHUFFLE(2, 0, 2, 0));  // x0 x2 y0 y2
  const __m256 yz = _mm256_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1));  // y1 y3 z1 z3
  const __m256 zx = _mm256_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0));  // z0 z2 x1 x3
  const __m256 a = _mm256_shuffle_ps(xy, zx, _MM_SHUFFLE(2, 0, 2, 0));  // x0 y0 z0 x1
  const __m256 b = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));  // y1 z1 x2 y2
  const __m256 c = _mm256_shuffle_ps(zx, yz, _MM_SHUFFLE(3, 1, 3, 1));  // z2 x3 y3 z3
  _mm_storeu_ps(p, _mm256_castps256_ps128(a));
  _mm_storeu_ps(p + 4, _mm256_castps256_ps128(b));
  _mm_storeu_ps(p + 8, _mm256_castps256_ps128(c));
  _mm_storeu_ps(p + 12, _mm256_extractf128_ps(a, 1));
  _mm_storeu_ps(p + 16, _mm256_extractf128_ps(b, 1));
  _mm_storeu_ps(p + 20, _mm256_extractf128_ps(c, 1));
}

// Four 128-bit rows (one per vertex in each lane) → four registers of their x, y, z, w.
[[gnu::always_inline]] GESTURA_AVX2 inline void transpose4(__m256 r0, __m256 r1, __m256 r2, __m256 r3, __m256& x,
                                                          __m256& y, __m256& z, __m256& w) {
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
  const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
  x = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  y = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  z = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  w = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
}

}  // namespace

GESTURA_AVX2 void lbs_avx2(const mat4* skinning, const JointIndices* joints, const vec4* weights,
                           const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                           vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* base = &skinning[0][0][0];
  const __m256 one = _mm256_set1_ps(1.0f);
  if (!out_normals) {
    for (std::size_t v = 0; v < count; ++v) {
      __m256 lo, hi;
      blend(base, joints[v], weights[v], lo, hi);
      store3(&out_positions[v].x, transform(lo, hi, &rest_positions[v].x, one));
    }
    return;
  }
  // Normals leave the per-vertex step unnormalised into a small aligned buffer; eight at a time they
  // are transposed to x/y/z registers, normalised and stored. Cheaper than a horizontal dot product
  // per vertex, and the 16-byte stores forward to the 16-byte loads that read them back.
  const __m256 zero = _mm256_setzero_ps();
  alignas(32) float normal[8][4];
  auto skin_one = [&](std::size_t v, float* unnormalised) GESTURA_AVX2 {
    __m256 lo, hi;
    blend(base, joints[v], weights[v], lo, hi);
    store3(&out_positions[v].x, transform(lo, hi, &rest_positions[v].x, one));
    _mm_store_ps(unnormalised, transform(lo, hi, &rest_normals[v].x, zero));  // w lane is 0
  };
  std::size_t v = 0;
  for (; v + 8 <= count; v += 8) {
    for (std::size_t i = 0; i < 8; ++i) skin_one(v + i, normal[i]);
    __m256 row[4];  // lane i of the low half is vertex i, of the high half vertex i + 4
    for (int i = 0; i < 4; ++i)
      row[i] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(normal[i])), _mm_load_ps(normal[i + 4]), 1);
    __m256 x, y, z, w;
    transpose4(row[0], row[1], row[2], row[3], x, y, z, w);
    const __m256 inv = inverse_sqrt(_mm256_fmadd_ps(x, x, _mm256_fmadd_ps(y, y, _mm256_mul_ps(z, z))));
    store8(&out_normals[v].x, _mm256_mul_ps(x, inv), _mm256_mul_ps(y, inv), _mm256_mul_ps(z, inv));
  }
  for (; v < count; ++v) {
    skin_one(v, normal[0]);
    const __m128 n = _mm_load_ps(normal[0]);
    store3(&out_normals[v].x, _mm_mul_ps(n, inverse_sqrt(_mm_dp_ps(n, n, 0x7F))));
  }
}

namespace {

// Blends one vertex's four dual quaternions (one 256-bit register each: real | dual), each weight
// negated when its rotation lies in the other hemisphere from the first influence's.
[[gnu::always_inline]] GESTURA_AVX2 inline __m256 blend_dual(const float* dq, const JointIndices& j, const vec4& w) {
  const __m256 q0 = _mm256_loadu_ps(dq + 8 * j.x), q1 = _mm256_loadu_ps(dq + 8 * j.y);
  const __m256 q2 = _mm256_loadu_ps(dq + 8 * j.z), q3 = _mm256_loadu_ps(dq + 8 * j.w);
  const __m128 r0 = _mm256_castps256_ps128(q0);
  // (r0·r0, r0·r1, r0·r2, r0·r3) by horizontal adds; lane 0 is positive, so the first weight keeps its sign.
  const __m128 dots = _mm_hadd_ps(_mm_hadd_ps(_mm_mul_ps(r0, r0), _mm_mul_ps(r0, _mm256_castps256_ps128(q1))),
                                  _mm_hadd_ps(_mm_mul_ps(r0, _mm256_castps256_ps128(q2)),
                                              _mm_mul_ps(r0, _mm256_castps256_ps128(q3))));
  const __m128 sign = _mm_and_ps(dots, _mm_set1_ps(-0.0f));
  alignas(16) float s[4];
  _mm_store_ps(s, _mm_xor_ps(_mm_loadu_ps(&w.x), sign));  // re-read as broadcasts: load ports, not shuffles
  __m256 b = _mm256_mul_ps(_mm256_broadcast_ss(s), q0);
  b = _mm256_fmadd_ps(_mm256_broadcast_ss(s + 1), q1, b);
  b = _mm256_fmadd_ps(_mm256_broadcast_ss(s + 2), q2, b);
  return _mm256_fmadd_ps(_mm256_broadcast_ss(s + 3), q3, b);
}

// v + 2·r × (r × v + w·v), eight vectors at once.
[[gnu::always_inline]] GESTURA_AVX2 inline void rotate8(__m256 rx, __m256 ry, __m256 rz, __m256 rw, __m256& x,
                                                       __m256& y, __m256& z) {
  const __m256 cx = _mm256_fmadd_ps(rw, x, _mm256_fmsub_ps(ry, z, _mm256_mul_ps(rz, y)));
  const __m256 cy = _mm256_fmadd_ps(rw, y, _mm256_fmsub_ps(rz, x, _mm256_mul_ps(rx, z)));
  const __m256 cz = _mm256_fmadd_ps(rw, z, _mm256_fmsub_ps(rx, y, _mm256_mul_ps(ry, x)));
  const __m256 two = _mm256_set1_ps(2.0f);
  x = _mm256_fmadd_ps(two, _mm256_fmsub_ps(ry, cz, _mm256_mul_ps(rz, cy)), x);
  y = _mm256_fmadd_ps(two, _mm256_fmsub_ps(rz, cx, _mm256_mul_ps(rx, cz)), y);
  z = _mm256_fmadd_ps(two, _mm256_fmsub_ps(rx, cy, _mm256_mul_ps(ry, cx)), z);
}

}  // namespace

// Eight vertices per step: blend each vertex's dual quaternion in one register, then transpose the
// eight blends so that normalising and applying them runs on eight vertices per instruction.
GESTURA_AVX2 void dqs_avx2(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
                           const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                           vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* dq = &skinning[0].real.x;
  alignas(32) float blended[8][8];
  std::size_t v = 0;
  for (; v + 8 <= count; v += 8) {
    for (int i = 0; i < 8; ++i) _mm256_store_ps(blended[i], blend_dual(dq, joints[v + i], weights[v + i]));
    // Lane i of the low half is vertex i, of the high half vertex i + 4 (as load8 arranges them).
    __m256 real[4], dual[4];
    for (int i = 0; i < 4; ++i) {
      real[i] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(blended[i])), _mm_load_ps(blended[i + 4]), 1);
      dual[i] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(blended[i] + 4)),
                                     _mm_load_ps(blended[i + 4] + 4), 1);
    }
    __m256 rx, ry, rz, rw, dx, dy, dz, dw;
    transpose4(real[0], real[1], real[2], real[3], rx, ry, rz, rw);
    transpose4(dual[0], dual[1], dual[2], dual[3], dx, dy, dz, dw);
    const __m256 len2 = _mm256_fmadd_ps(rx, rx, _mm256_fmadd_ps(ry, ry, _mm256_fmadd_ps(rz, rz, _mm256_mul_ps(rw, rw))));
    const __m256 inv = inverse_sqrt(len2);
    rx = _mm256_mul_ps(rx, inv), ry = _mm256_mul_ps(ry, inv), rz = _mm256_mul_ps(rz, inv), rw = _mm256_mul_ps(rw, inv);
    dx = _mm256_mul_ps(dx, inv), dy = _mm256_mul_ps(dy, inv), dz = _mm256_mul_ps(dz, inv), dw = _mm256_mul_ps(dw, inv);
    // t = 2 · (rw·d − dw·r + r × d)
    const __m256 two = _mm256_set1_ps(2.0f);
    const __m256 tx = _mm256_mul_ps(two, _mm256_add_ps(_mm256_fmsub_ps(rw, dx, _mm256_mul_ps(dw, rx)),
                                                       _mm256_fmsub_ps(ry, dz, _mm256_mul_ps(rz, dy))));
    const __m256 ty = _mm256_mul_ps(two, _mm256_add_ps(_mm256_fmsub_ps(rw, dy, _mm256_mul_ps(dw, ry)),
                                                       _mm256_fmsub_ps(rz, dx, _mm256_mul_ps(rx, dz))));
    const __m256 tz = _mm256_mul_ps(two, _mm256_add_ps(_mm256_fmsub_ps(rw, dz, _mm256_mul_ps(dw, rz)),
                                                       _mm256_fmsub_ps(rx, dy, _mm256_mul_ps(ry, dx))));
    __m256 px, py, pz;
    load8(&rest_positions[v].x, px, py, pz);
    rotate8(rx, ry, rz, rw, px, py, pz);
    store8(&out_positions[v].x, _mm256_add_ps(px, tx), _mm256_add_ps(py, ty), _mm256_add_ps(pz, tz));
    if (rest_normals) {
      __m256 nx, ny, nz;
      load8(&rest_normals[v].x, nx, ny, nz);
      rotate8(rx, ry, rz, rw, nx, ny, nz);
      store8(&out_normals[v].x, nx, ny, nz);
    }
  }
  for (; v < count; ++v)  // the last few vertices one by one
    dqs_vertex(dq, joints[v], weights[v], rest_positions[v], rest_normals ? &rest_normals[v] : nullptr,
               out_positions[v], out_normals ? &out_normals[v] : nullptr);
}

}  // namespace gestura::skinning_detail
#endif
