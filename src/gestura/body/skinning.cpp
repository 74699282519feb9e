#include "gestura/body/skinning.hpp"

#include <cmath>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "gestura/body/skinning_kernels.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

using namespace skinning_detail;

SkinningPath resolve_skinning_path(SkinningPath requested) { return resolve_simd_path(requested, "skinning"); }

void skinning_matrices(std::span<const mat4> model, std::span<const mat4> inverse_bind, std::span<mat4> out) {
  if (model.size() != inverse_bind.size() || model.size() != out.size())
    throw Error("skinning_matrices: " + std::to_string(model.size()) + " model matrices, " +
                std::to_string(inverse_bind.size()) + " inverse bind matrices, " + std::to_string(out.size()) +
                " outputs");
  for (std::size_t j = 0; j < model.size(); ++j) out[j] = model[j] * inverse_bind[j];
}

void check_influences(std::span<const JointIndices> joints, std::span<const vec4> weights,
                      std::size_t joint_count, float tolerance) {
  if (joints.size() != weights.size())
    throw Error("skin influences: " + std::to_string(joints.size()) + " joint quadruples but " +
                std::to_string(weights.size()) + " weight quadruples");
  for (std::size_t v = 0; v < joints.size(); ++v) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      const std::string where = "skin influences: vertex " + std::to_string(v) + " slot " + std::to_string(k);
      if (joints[v][k] >= joint_count)
        throw Error(where + ": joint " + std::to_string(joints[v][k]) + " out of range (" +
                    std::to_string(joint_count) + " joints)");
      if (!std::isfinite(weights[v][k]) || weights[v][k] < 0.0f) throw Error(where + ": bad weight");
      sum += weights[v][k];
    }
    if (std::abs(sum - 1.0f) > tolerance)
      throw Error("skin influences: vertex " + std::to_string(v) + ": weights sum to " + std::to_string(sum));
  }
}

namespace {

void check_sizes(const char* kernel, std::size_t joints, std::size_t weights, std::size_t rest,
                 std::size_t out, std::size_t rest_normals, std::size_t out_normals, bool normals_required) {
  const bool normals_ok = normals_required ? (rest_normals == rest && out_normals == rest)
                                           : ((rest_normals == 0 && out_normals == 0) ||
                                              (rest_normals == rest && out_normals == rest));
  if (joints != rest || weights != rest || out != rest || !normals_ok)
    throw Error(std::string(kernel) + ": per-vertex spans disagree in length (joints " + std::to_string(joints) +
                ", weights " + std::to_string(weights) + ", rest positions " + std::to_string(rest) +
                ", out positions " + std::to_string(out) + ", rest normals " + std::to_string(rest_normals) +
                ", out normals " + std::to_string(out_normals) + ")");
}

void lbs(std::span<const mat4> skinning, std::span<const JointIndices> joints, std::span<const vec4> weights,
         std::span<const vec3> rest_positions, std::span<const vec3> rest_normals, std::span<vec3> out_positions,
         std::span<vec3> out_normals, SkinningPath path) {
  const vec3* rn = rest_normals.empty() ? nullptr : rest_normals.data();
  vec3* on = out_normals.empty() ? nullptr : out_normals.data();
#ifdef GESTURA_SKINNING_HAS_AVX2
  if (resolve_skinning_path(path) == SkinningPath::Avx2)
    return lbs_avx2(skinning.data(), joints.data(), weights.data(), rest_positions.data(), rn,
                    out_positions.data(), on, rest_positions.size());
#else
  resolve_skinning_path(path);
#endif
  lbs_portable(skinning.data(), skinning.size(), joints.data(), weights.data(), rest_positions.data(), rn,
               out_positions.data(), on, rest_positions.size());
}

}  // namespace

void skin_positions(std::span<const mat4> skinning, std::span<const JointIndices> joints,
                    std::span<const vec4> weights, std::span<const vec3> rest_positions,
                    std::span<vec3> out_positions, SkinningPath path) {
  check_sizes("skin_positions", joints.size(), weights.size(), rest_positions.size(), out_positions.size(), 0, 0,
              false);
  lbs(skinning, joints, weights, rest_positions, {}, out_positions, {}, path);
}

void skin_positions_normals(std::span<const mat4> skinning, std::span<const JointIndices> joints,
                            std::span<const vec4> weights, std::span<const vec3> rest_positions,
                            std::span<const vec3> rest_normals, std::span<vec3> out_positions,
                            std::span<vec3> out_normals, SkinningPath path) {
  check_sizes("skin_positions_normals", joints.size(), weights.size(), rest_positions.size(),
              out_positions.size(), rest_normals.size(), out_normals.size(), true);
  lbs(skinning, joints, weights, rest_positions, rest_normals, out_positions, out_normals, path);
}

void skinning_dual_quaternions(std::span<const mat4> skinning, std::span<DualQuat> out) {
  if (skinning.size() != out.size())
    throw Error("skinning_dual_quaternions: " + std::to_string(skinning.size()) + " matrices, " +
                std::to_string(out.size()) + " outputs");
  for (std::size_t j = 0; j < skinning.size(); ++j) {
    const mat4& m = skinning[j];
    // Gram–Schmidt on the columns removes scale and shear before extracting the rotation.
    const vec3 x = glm::normalize(vec3(m[0]));
    const vec3 y = glm::normalize(vec3(m[1]) - glm::dot(vec3(m[1]), x) * x);
    const vec3 z = glm::cross(x, y);
    const quat r = glm::normalize(glm::quat_cast(mat3(x, y, z)));
    const vec3 t(m[3]);
    out[j].real = r;
    out[j].dual = 0.5f * (quat(0.0f, t.x, t.y, t.z) * r);
  }
}

void skin_dual_quaternion(std::span<const DualQuat> skinning, std::span<const JointIndices> joints,
                          std::span<const vec4> weights, std::span<const vec3> rest_positions,
                          std::span<const vec3> rest_normals, std::span<vec3> out_positions,
                          std::span<vec3> out_normals, SkinningPath path) {
  check_sizes("skin_dual_quaternion", joints.size(), weights.size(), rest_positions.size(), out_positions.size(),
              rest_normals.size(), out_normals.size(), false);
  const vec3* rn = rest_normals.empty() ? nullptr : rest_normals.data();
  vec3* on = out_normals.empty() ? nullptr : out_normals.data();
#ifdef GESTURA_SKINNING_HAS_AVX2
  if (resolve_skinning_path(path) == SkinningPath::Avx2)
    return dqs_avx2(skinning.data(), joints.data(), weights.data(), rest_positions.data(), rn,
                    out_positions.data(), on, rest_positions.size());
#else
  resolve_skinning_path(path);
#endif
  dqs_portable(skinning.data(), joints.data(), weights.data(), rest_positions.data(), rn, out_positions.data(), on,
               rest_positions.size());
}

static_assert(sizeof(DualQuat) == 8 * sizeof(float), "kernels read a DualQuat as 8 packed floats");

namespace skinning_detail {

#if defined(__SSE2__)
namespace {

template <int i>
inline __m128 lane(__m128 v) {
  return _mm_shuffle_ps(v, v, _MM_SHUFFLE(i, i, i, i));
}

// The vertex's four weighted joint matrices summed into four 128-bit columns. The weights come in
// with one load and four shuffles.
inline void blend_columns(const float* base, const JointIndices& j, const vec4& weight, __m128 c[4]) {
  const float* m0 = base + 16 * j.x;
  const float* m1 = base + 16 * j.y;
  const float* m2 = base + 16 * j.z;
  const float* m3 = base + 16 * j.w;
  const __m128 w = _mm_loadu_ps(&weight.x);
  const __m128 w0 = lane<0>(w), w1 = lane<1>(w), w2 = lane<2>(w), w3 = lane<3>(w);
  for (int col = 0; col < 4; ++col) {
    const __m128 a = _mm_add_ps(_mm_mul_ps(w0, _mm_loadu_ps(m0 + 4 * col)), _mm_mul_ps(w1, _mm_loadu_ps(m1 + 4 * col)));
    const __m128 b = _mm_add_ps(_mm_mul_ps(w2, _mm_loadu_ps(m2 + 4 * col)), _mm_mul_ps(w3, _mm_loadu_ps(m3 + 4 * col)));
    c[col] = _mm_add_ps(a, b);
  }
}

// c0·x + c1·y + c2·z (+ c3 for a point) for v = (x, y, z) read with one 16-byte load. `v` must have
// four readable floats (the caller keeps the last vertex of a span out of this).
inline __m128 transform_vector(const __m128 c[4], const float* v) {
  const __m128 p = _mm_loadu_ps(v);
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(c[0], lane<0>(p)), _mm_mul_ps(c[1], lane<1>(p))), _mm_mul_ps(c[2], lane<2>(p)));
}

// 1/√x to about 2e-7: the estimate and one Newton step, as the AVX2 path computes it.
inline __m128 inverse_sqrt4(__m128 x) {
  const __m128 y = _mm_rsqrt_ps(x);
  return _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), y), _mm_sub_ps(_mm_set1_ps(3.0f), _mm_mul_ps(_mm_mul_ps(x, y), y)));
}

void store3(float* out, __m128 r) {
  _mm_storel_pi(reinterpret_cast<__m64*>(out), r);
  _mm_store_ss(out + 2, _mm_movehl_ps(r, r));
}

// Four packed vec3 (12 floats) ↔ x, y, z registers; lane i is vertex i.
void load4(const float* p, __m128& x, __m128& y, __m128& z) {
  const __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4), c = _mm_loadu_ps(p + 8);
  // a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3
  const __m128 xy = _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
  const __m128 yz = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
  x = _mm_shuffle_ps(a, xy, _MM_SHUFFLE(2, 0, 3, 0));
  y = _mm_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
  z = _mm_shuffle_ps(yz, c, _MM_SHUFFLE(3, 0, 3, 1));
}

void store4(float* p, __m128 x, __m128 y, __m128 z) {
  const __m128 xy = _mm_shuffle_ps(x, y, _MM_SHUFFLE(2, 0, 2, 0));  // x0 x2 y0 y2
  const __m128 yz = _mm_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1));  // y1 y3 z1 z3
  const __m128 zx = _mm_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0));  // z0 z2 x1 x3
  _mm_storeu_ps(p, _mm_shuffle_ps(xy, zx, _MM_SHUFFLE(2, 0, 2, 0)));
  _mm_storeu_ps(p + 4, _mm_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0)));
  _mm_storeu_ps(p + 8, _mm_shuffle_ps(zx, yz, _MM_SHUFFLE(3, 1, 3, 1)));
}

// One vertex with nothing read or written past it: scalar loads, 12-byte stores, its own normalisation.
void lbs_one(const float* base, const JointIndices& j, const vec4& w, const vec3& p, const vec3* n, vec3& out_p, vec3* out_n) {
  __m128 c[4];
  blend_columns(base, j, w, c);
  const float pv[4] = {p.x, p.y, p.z, 0.0f};
  store3(&out_p.x, _mm_add_ps(transform_vector(c, pv), c[3]));
  if (!n) return;
  const float nv[4] = {n->x, n->y, n->z, 0.0f};
  const __m128 r = transform_vector(c, nv);
  const __m128 sq = _mm_mul_ps(r, r);
  const __m128 len2 = _mm_add_ss(_mm_add_ss(sq, _mm_shuffle_ps(sq, sq, 1)), _mm_shuffle_ps(sq, sq, 2));
  store3(&out_n->x, _mm_mul_ps(r, lane<0>(inverse_sqrt4(len2))));
}

}  // namespace

namespace {

constexpr std::size_t kRowJoints = 256;  // skinning matrices the row kernel keeps on the stack (12 KB)

// Four vertices per step with the matrices as rows. A skinning matrix's useful part is 3 rows of 4
// (x, y, z and translation), so a vertex blends 3 registers per influence instead of 4 columns; and a
// block blends only the influence slots up to the last one with weight in any of its four vertices
// (rigid and two-joint vertices come in runs; a slot of weight exactly 0 adds nothing). The four
// blended matrices are then transposed row by row, so that transforming positions and normals and
// normalising the normals run on four vertices per instruction.
// The blend of four vertices' first N influences (the rest are 0 in all four), row by row.
template <int N>
void blend_rows(const float* rows, const JointIndices* joints, const vec4* weights, __m128 r[3][4]) {
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint16_t index[4] = {joints[i].x, joints[i].y, joints[i].z, joints[i].w};
    const __m128 w = _mm_loadu_ps(&weights[i].x);
    const __m128 wk[4] = {lane<0>(w), lane<1>(w), lane<2>(w), lane<3>(w)};
    for (int row = 0; row < 3; ++row) {
      __m128 sum = _mm_mul_ps(wk[0], _mm_load_ps(rows + 12 * std::size_t{index[0]} + 4 * row));
      for (int k = 1; k < N; ++k) sum = _mm_add_ps(sum, _mm_mul_ps(wk[k], _mm_load_ps(rows + 12 * std::size_t{index[k]} + 4 * row)));
      r[row][i] = sum;
    }
  }
}

void lbs_rows(const float* rows, const JointIndices* joints, const vec4* weights, const vec3* rest_positions,
              const vec3* rest_normals, vec3* out_positions, vec3* out_normals, std::size_t count) {
  const __m128 zero = _mm_setzero_ps();
  for (std::size_t v = 0; v + 4 <= count; v += 4) {
    // Influence slots with weight in any of the four.
    const __m128 used = _mm_or_ps(_mm_or_ps(_mm_cmpneq_ps(_mm_loadu_ps(&weights[v].x), zero), _mm_cmpneq_ps(_mm_loadu_ps(&weights[v + 1].x), zero)),
                                  _mm_or_ps(_mm_cmpneq_ps(_mm_loadu_ps(&weights[v + 2].x), zero), _mm_cmpneq_ps(_mm_loadu_ps(&weights[v + 3].x), zero)));
    const int mask = _mm_movemask_ps(used);
    __m128 r[3][4];  // r[row][vertex]
    if (mask & 8) blend_rows<4>(rows, joints + v, weights + v, r);
    else if (mask & 4) blend_rows<3>(rows, joints + v, weights + v, r);
    else if (mask & 2) blend_rows<2>(rows, joints + v, weights + v, r);
    else blend_rows<1>(rows, joints + v, weights + v, r);
    // r[row][vertex] → r[row][column], lane = vertex.
    for (int row = 0; row < 3; ++row) _MM_TRANSPOSE4_PS(r[row][0], r[row][1], r[row][2], r[row][3]);
    __m128 x, y, z;
    load4(&rest_positions[v].x, x, y, z);
    auto apply = [&](int row, __m128 px, __m128 py, __m128 pz) {
      return _mm_add_ps(_mm_add_ps(_mm_mul_ps(r[row][0], px), _mm_mul_ps(r[row][1], py)), _mm_mul_ps(r[row][2], pz));
    };
    store4(&out_positions[v].x, _mm_add_ps(apply(0, x, y, z), r[0][3]), _mm_add_ps(apply(1, x, y, z), r[1][3]),
           _mm_add_ps(apply(2, x, y, z), r[2][3]));
    if (!out_normals) continue;
    load4(&rest_normals[v].x, x, y, z);
    const __m128 nx = apply(0, x, y, z), ny = apply(1, x, y, z), nz = apply(2, x, y, z);
    const __m128 inv = inverse_sqrt4(_mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, nx), _mm_mul_ps(ny, ny)), _mm_mul_ps(nz, nz)));
    store4(&out_normals[v].x, _mm_mul_ps(nx, inv), _mm_mul_ps(ny, inv), _mm_mul_ps(nz, inv));
  }
}

}  // namespace

// SSE2 (every x86-64). Up to kRowJoints joints: lbs_rows on the matrices copied as rows; otherwise, and
// for the last few vertices, one vertex at a time with the blended matrix as four 128-bit columns.
void lbs_portable(const mat4* skinning, std::size_t joint_count, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* base = &skinning[0][0][0];
  std::size_t v = 0;
  if (joint_count <= kRowJoints) {
    alignas(16) float rows[kRowJoints * 12];
    for (std::size_t j = 0; j < joint_count; ++j) {
      __m128 c0 = _mm_loadu_ps(base + 16 * j), c1 = _mm_loadu_ps(base + 16 * j + 4);
      __m128 c2 = _mm_loadu_ps(base + 16 * j + 8), c3 = _mm_loadu_ps(base + 16 * j + 12);
      _MM_TRANSPOSE4_PS(c0, c1, c2, c3);  // now the matrix's rows; the 4th (0 0 0 1) is not needed
      _mm_store_ps(rows + 12 * j, c0), _mm_store_ps(rows + 12 * j + 4, c1), _mm_store_ps(rows + 12 * j + 8, c2);
    }
    lbs_rows(rows, joints, weights, rest_positions, rest_normals, out_positions, out_normals, count);
    v = count / 4 * 4;
  }
  for (; v < count; ++v)
    lbs_one(base, joints[v], weights[v], rest_positions[v], rest_normals ? &rest_normals[v] : nullptr, out_positions[v],
            out_normals ? &out_normals[v] : nullptr);
}
#else
// Plain C++ for targets without SSE2.
void lbs_portable(const mat4* skinning, std::size_t, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count) {
  for (std::size_t v = 0; v < count; ++v) {
    const JointIndices j = joints[v];
    const vec4 w = weights[v];
    const float* m0 = &skinning[j.x][0][0];
    const float* m1 = &skinning[j.y][0][0];
    const float* m2 = &skinning[j.z][0][0];
    const float* m3 = &skinning[j.w][0][0];
    float b[16];  // blended column-major matrix
    for (int e = 0; e < 16; ++e) b[e] = w.x * m0[e] + w.y * m1[e] + w.z * m2[e] + w.w * m3[e];
    const vec3 p = rest_positions[v];
    out_positions[v] = vec3(b[0] * p.x + b[4] * p.y + b[8] * p.z + b[12], b[1] * p.x + b[5] * p.y + b[9] * p.z + b[13],
                            b[2] * p.x + b[6] * p.y + b[10] * p.z + b[14]);
    if (out_normals) {
      const vec3 n = rest_normals[v];
      const float nx = b[0] * n.x + b[4] * n.y + b[8] * n.z;
      const float ny = b[1] * n.x + b[5] * n.y + b[9] * n.z;
      const float nz = b[2] * n.x + b[6] * n.y + b[10] * n.z;
      const float inv = 1.0f / std::sqrt(nx * nx + ny * ny + nz * nz);
      out_normals[v] = vec3(nx * inv, ny * inv, nz * inv);
    }
  }
}
#endif

#if defined(__SSE2__)
namespace {

// a × b + w·v style helpers for four vectors at once (SSE2 has no FMA).
inline __m128 mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
inline __m128 add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
inline __m128 sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }

// v + 2·r × (r × v + w·v)
void rotate4(__m128 rx, __m128 ry, __m128 rz, __m128 rw, __m128& x, __m128& y, __m128& z) {
  const __m128 cx = add(sub(mul(ry, z), mul(rz, y)), mul(rw, x));
  const __m128 cy = add(sub(mul(rz, x), mul(rx, z)), mul(rw, y));
  const __m128 cz = add(sub(mul(rx, y), mul(ry, x)), mul(rw, z));
  const __m128 two = _mm_set1_ps(2.0f);
  x = add(x, mul(two, sub(mul(ry, cz), mul(rz, cy))));
  y = add(y, mul(two, sub(mul(rz, cx), mul(rx, cz))));
  z = add(z, mul(two, sub(mul(rx, cy), mul(ry, cx))));
}

}  // namespace

// Four vertices per step: blend each vertex's dual quaternion (signs from scalar dot products),
// transpose the four blends, then normalise and apply them four vertices per instruction.
void dqs_portable(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* dq = &skinning[0].real.x;
  std::size_t v = 0;
  for (; v + 4 <= count; v += 4) {
    __m128 real[4], dual[4];
    for (int i = 0; i < 4; ++i) {
      const JointIndices& j = joints[v + static_cast<std::size_t>(i)];
      const vec4& w = weights[v + static_cast<std::size_t>(i)];
      const float* q[4] = {dq + 8 * j.x, dq + 8 * j.y, dq + 8 * j.z, dq + 8 * j.w};
      float s[4] = {w.x, w.y, w.z, w.w};
      for (int k = 1; k < 4; ++k)  // antipodality against the first influence
        if (q[0][0] * q[k][0] + q[0][1] * q[k][1] + q[0][2] * q[k][2] + q[0][3] * q[k][3] < 0.0f) s[k] = -s[k];
      __m128 r = mul(_mm_set1_ps(s[0]), _mm_loadu_ps(q[0])), d = mul(_mm_set1_ps(s[0]), _mm_loadu_ps(q[0] + 4));
      for (int k = 1; k < 4; ++k) {
        r = add(r, mul(_mm_set1_ps(s[k]), _mm_loadu_ps(q[k])));
        d = add(d, mul(_mm_set1_ps(s[k]), _mm_loadu_ps(q[k] + 4)));
      }
      real[i] = r;
      dual[i] = d;
    }
    _MM_TRANSPOSE4_PS(real[0], real[1], real[2], real[3]);
    _MM_TRANSPOSE4_PS(dual[0], dual[1], dual[2], dual[3]);
    const __m128 len2 = add(add(mul(real[0], real[0]), mul(real[1], real[1])),
                            add(mul(real[2], real[2]), mul(real[3], real[3])));
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2));
    const __m128 rx = mul(real[0], inv), ry = mul(real[1], inv), rz = mul(real[2], inv), rw = mul(real[3], inv);
    const __m128 dx = mul(dual[0], inv), dy = mul(dual[1], inv), dz = mul(dual[2], inv), dw = mul(dual[3], inv);
    // t = 2 · (rw·d − dw·r + r × d)
    const __m128 two = _mm_set1_ps(2.0f);
    const __m128 tx = mul(two, add(sub(mul(rw, dx), mul(dw, rx)), sub(mul(ry, dz), mul(rz, dy))));
    const __m128 ty = mul(two, add(sub(mul(rw, dy), mul(dw, ry)), sub(mul(rz, dx), mul(rx, dz))));
    const __m128 tz = mul(two, add(sub(mul(rw, dz), mul(dw, rz)), sub(mul(rx, dy), mul(ry, dx))));
    __m128 px, py, pz;
    load4(&rest_positions[v].x, px, py, pz);
    rotate4(rx, ry, rz, rw, px, py, pz);
    store4(&out_positions[v].x, add(px, tx), add(py, ty), add(pz, tz));
    if (rest_normals) {
      __m128 nx, ny, nz;
      load4(&rest_normals[v].x, nx, ny, nz);
      rotate4(rx, ry, rz, rw, nx, ny, nz);
      store4(&out_normals[v].x, nx, ny, nz);
    }
  }
  for (; v < count; ++v)  // the last few vertices one by one
    dqs_vertex(dq, joints[v], weights[v], rest_positions[v], rest_normals ? &rest_normals[v] : nullptr,
               out_positions[v], out_normals ? &out_normals[v] : nullptr);
}
#else
void dqs_portable(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* dq = &skinning[0].real.x;
  for (std::size_t v = 0; v < count; ++v)
    dqs_vertex(dq, joints[v], weights[v], rest_positions[v], rest_normals ? &rest_normals[v] : nullptr,
               out_positions[v], out_normals ? &out_normals[v] : nullptr);
}
#endif

}  // namespace skinning_detail
}  // namespace gestura
