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
  lbs_portable(skinning.data(), joints.data(), weights.data(), rest_positions.data(), rn, out_positions.data(), on,
               rest_positions.size());
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
// SSE2 (every x86-64): the blended matrix as four 128-bit columns, the vertex as c0·x + c1·y + c2·z + c3.
void lbs_portable(const mat4* skinning, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count) {
  if (count == 0) return;
  const float* base = &skinning[0][0][0];
  for (std::size_t v = 0; v < count; ++v) {
    const JointIndices j = joints[v];
    const float* m[4] = {base + 16 * j.x, base + 16 * j.y, base + 16 * j.z, base + 16 * j.w};
    const float* w = &weights[v].x;
    __m128 c[4];
    for (int col = 0; col < 4; ++col) {
      __m128 sum = _mm_mul_ps(_mm_set1_ps(w[0]), _mm_loadu_ps(m[0] + 4 * col));
      for (int k = 1; k < 4; ++k) sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w[k]), _mm_loadu_ps(m[k] + 4 * col)));
      c[col] = sum;
    }
    const vec3& p = rest_positions[v];
    const __m128 r = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c[0], _mm_set1_ps(p.x)), _mm_mul_ps(c[1], _mm_set1_ps(p.y))),
                                _mm_add_ps(_mm_mul_ps(c[2], _mm_set1_ps(p.z)), c[3]));
    _mm_storel_pi(reinterpret_cast<__m64*>(&out_positions[v].x), r);
    _mm_store_ss(&out_positions[v].z, _mm_movehl_ps(r, r));
    if (out_normals) {
      const vec3& nr = rest_normals[v];
      const __m128 n = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c[0], _mm_set1_ps(nr.x)), _mm_mul_ps(c[1], _mm_set1_ps(nr.y))),
                                  _mm_mul_ps(c[2], _mm_set1_ps(nr.z)));
      const __m128 sq = _mm_mul_ps(n, n);
      const __m128 len2 = _mm_add_ss(_mm_add_ss(sq, _mm_shuffle_ps(sq, sq, 1)), _mm_shuffle_ps(sq, sq, 2));
      const __m128 len = _mm_sqrt_ss(len2);
      const __m128 unit = _mm_div_ps(n, _mm_shuffle_ps(len, len, 0));
      _mm_storel_pi(reinterpret_cast<__m64*>(&out_normals[v].x), unit);
      _mm_store_ss(&out_normals[v].z, _mm_movehl_ps(unit, unit));
    }
  }
}
#else
// Plain C++ for targets without SSE2.
void lbs_portable(const mat4* skinning, const JointIndices* joints, const vec4* weights,
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
