#pragma once
// Internal to skinning.cpp / skinning_avx2.cpp: raw-pointer kernels behind the span API, and the
// per-vertex dual-quaternion step both DQS paths compile (once plainly, once for AVX2+FMA).
// Preconditions are those of skinning.hpp, already checked by the caller; `count` vertices.
#include <cmath>
#include <cstddef>

#include "gestura/body/skinning.hpp"

namespace gestura::skinning_detail {

// `rest_normals`/`out_normals` null = positions only. `joint_count` matrices in `skinning`.
void lbs_portable(const mat4* skinning, std::size_t joint_count, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count);
void dqs_portable(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
                  const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
                  vec3* out_normals, std::size_t count);

#if defined(__x86_64__) || defined(__i386__)
#define GESTURA_SKINNING_HAS_AVX2 1
void lbs_avx2(const mat4* skinning, const JointIndices* joints, const vec4* weights,
              const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
              vec3* out_normals, std::size_t count);
void dqs_avx2(const DualQuat* skinning, const JointIndices* joints, const vec4* weights,
              const vec3* rest_positions, const vec3* rest_normals, vec3* out_positions,
              vec3* out_normals, std::size_t count);
#endif

// One vertex of DQS, on plain floats so that the compiler maps it onto whatever vector unit the
// enclosing function targets. dq = 8 floats per joint (real xyzw, dual xyzw).
[[gnu::always_inline]] inline void dqs_vertex(const float* dq, const JointIndices& j, const vec4& w,
                                              const vec3& p, const vec3* n, vec3& out_p, vec3* out_n) {
  const float* q[4] = {dq + 8 * j.x, dq + 8 * j.y, dq + 8 * j.z, dq + 8 * j.w};
  // Antipodality: flip each influence onto the hemisphere of the first one.
  float s[4] = {w.x, w.y, w.z, w.w};
  for (int k = 1; k < 4; ++k) {
    const float d = q[0][0] * q[k][0] + q[0][1] * q[k][1] + q[0][2] * q[k][2] + q[0][3] * q[k][3];
    s[k] = d < 0.0f ? -s[k] : s[k];
  }
  float b[8];
  for (int e = 0; e < 8; ++e) b[e] = s[0] * q[0][e] + s[1] * q[1][e] + s[2] * q[2][e] + s[3] * q[3][e];
  const float inv = 1.0f / std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
  const float rx = b[0] * inv, ry = b[1] * inv, rz = b[2] * inv, rw = b[3] * inv;
  const float dx = b[4] * inv, dy = b[5] * inv, dz = b[6] * inv, dw = b[7] * inv;
  // Translation t = 2 · (rw·d − dw·r + r × d).
  const float tx = 2.0f * (rw * dx - dw * rx + (ry * dz - rz * dy));
  const float ty = 2.0f * (rw * dy - dw * ry + (rz * dx - rx * dz));
  const float tz = 2.0f * (rw * dz - dw * rz + (rx * dy - ry * dx));
  // Rotation of a vector v: v + 2 · r × (r × v + rw·v).
  auto rotate = [&](const vec3& v, float& ox, float& oy, float& oz) {
    const float cx = ry * v.z - rz * v.y + rw * v.x;
    const float cy = rz * v.x - rx * v.z + rw * v.y;
    const float cz = rx * v.y - ry * v.x + rw * v.z;
    ox = v.x + 2.0f * (ry * cz - rz * cy);
    oy = v.y + 2.0f * (rz * cx - rx * cz);
    oz = v.z + 2.0f * (rx * cy - ry * cx);
  };
  float px, py, pz;
  rotate(p, px, py, pz);
  out_p = vec3(px + tx, py + ty, pz + tz);
  if (n) {
    float nx, ny, nz;
    rotate(*n, nx, ny, nz);
    *out_n = vec3(nx, ny, nz);  // a rotation keeps the unit length of a unit normal
  }
}

}  // namespace gestura::skinning_detail
