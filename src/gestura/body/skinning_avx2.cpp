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
GESTURA_AVX2 [[gnu::always_inline]] inline void blend(const float* base, const JointIndices& j, const vec4& w,
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
GESTURA_AVX2 [[gnu::always_inline]] inline __m128 transform(__m256 lo, __m256 hi, const float* v, __m256 fourth) {
  const __m256 ab = _mm256_blend_ps(_mm256_broadcast_ss(v), _mm256_broadcast_ss(v + 1), 0xF0);
  const __m256 cd = _mm256_blend_ps(_mm256_broadcast_ss(v + 2), fourth, 0xF0);
  const __m256 r = _mm256_fmadd_ps(lo, ab, _mm256_mul_ps(hi, cd));
  return _mm_add_ps(_mm256_castps256_ps128(r), _mm256_extractf128_ps(r, 1));
}

GESTURA_AVX2 [[gnu::always_inline]] inline void store3(float* out, __m128 r) {
  _mm_storel_pi(reinterpret_cast<__m64*>(out), r);
  _mm_store_ss(out + 2, _mm_movehl_ps(r, r));
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
  const __m256 zero = _mm256_setzero_ps();
  for (std::size_t v = 0; v < count; ++v) {
    __m256 lo, hi;
    blend(base, joints[v], weights[v], lo, hi);
    store3(&out_positions[v].x, transform(lo, hi, &rest_positions[v].x, one));
    const __m128 n = transform(lo, hi, &rest_normals[v].x, zero);  // w lane is 0
    const __m128 len = _mm_sqrt_ps(_mm_dp_ps(n, n, 0x7F));
    store3(&out_normals[v].x, _mm_div_ps(n, len));
  }
}

GESTURA_AVX2 void dqs_avx2(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
                           const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                           vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* dq = &skinning[0].real.x;
  if (rest_normals) {
    for (std::size_t v = 0; v < count; ++v)
      dqs_vertex(dq, joints[v], weights[v], rest_positions[v], &rest_normals[v], out_positions[v], &out_normals[v]);
  } else {
    for (std::size_t v = 0; v < count; ++v)
      dqs_vertex(dq, joints[v], weights[v], rest_positions[v], nullptr, out_positions[v], nullptr);
  }
}

}  // namespace gestura::skinning_detail
#endif
