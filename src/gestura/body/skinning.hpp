#pragma once
// Deformation kernels: linear-blend skinning (LBS) and dual-quaternion skinning (DQS) over spans.
//
// Contracts shared by every kernel here:
//  - `skinning` holds one matrix per joint: joint model matrix × inverse bind matrix (see
//    skinning_matrices), i.e. it maps a rest-pose model-space point to its posed model-space place.
//  - Per vertex: 4 joint indices (glm::u16vec4) and 4 weights (vec4). Weights are used as given (the
//    kernels do not renormalise); unused slots carry weight 0 and any valid index. Every index must
//    be < skinning.size() — check untrusted data once with check_influences(), not per frame.
//  - All per-vertex spans have the same length (checked, gestura::Error otherwise); outputs are
//    caller-owned and must not overlap the inputs. No allocation happens inside the kernels.
//  - LBS output normals are normalised; DQS rotates them (unit in, unit out).
//
// Each kernel has two implementations: a portable one (SSE2 intrinsics on x86-64, plain C++
// otherwise) and an AVX2+FMA one chosen at run time when the CPU has both (SkinningPath::Auto). They
// agree within 1e-5 (FMA rounding; LBS normals take 1/√x as an estimate refined by one Newton step on
// both paths). The portable LBS keeps up to 256 skinning matrices as rows on the stack and skins four
// vertices per step (skinning.cpp).
// Throughput on the MakeHuman mesh: bench/skinning.cpp (workload W5).
#include <cstdint>
#include <span>

#include "gestura/body/mesh.hpp"
#include "gestura/core/math.hpp"
#include "gestura/core/simd_path.hpp"

namespace gestura {

using SkinningPath = SimdPath;  // core/simd_path.hpp; cpu_has_avx2_fma() is declared there too

// Auto → the best available path. Avx2 on a CPU without it throws gestura::Error.
SkinningPath resolve_skinning_path(SkinningPath requested);

// out[j] = model[j] · inverse_bind[j]. Sizes must match.
void skinning_matrices(std::span<const mat4> model, std::span<const mat4> inverse_bind, std::span<mat4> out);

// Throws gestura::Error naming the first vertex whose joint index is out of range, whose weight is
// negative or non-finite, or whose weights do not sum to 1 within `tolerance`.
void check_influences(std::span<const JointIndices> joints, std::span<const vec4> weights,
                      std::size_t joint_count, float tolerance = 1e-3f);

// LBS positions: out[v] = Σ_k w_k · skinning[j_k] · (rest[v], 1).
void skin_positions(std::span<const mat4> skinning, std::span<const JointIndices> joints,
                    std::span<const vec4> weights, std::span<const vec3> rest_positions,
                    std::span<vec3> out_positions, SkinningPath path = SkinningPath::Auto);

// LBS positions and normals. Normals are transformed by the upper 3x3 of the blended matrix and then
// normalised. That is exact for rotations and uniform scale (the renormalisation removes the scale);
// under non-uniform scale the correct transform is the inverse transpose, which we do not pay for:
// avatar skeletons here carry unit scale, and the error stays small for mild scale.
void skin_positions_normals(std::span<const mat4> skinning, std::span<const JointIndices> joints,
                            std::span<const vec4> weights, std::span<const vec3> rest_positions,
                            std::span<const vec3> rest_normals, std::span<vec3> out_positions,
                            std::span<vec3> out_normals, SkinningPath path = SkinningPath::Auto);

// A unit dual quaternion: rotation `real`, translation encoded in `dual` = ½ · (0, t) · real.
// Layout is 8 floats (real x y z w, dual x y z w) so a kernel loads one joint in one go.
struct DualQuat {
  quat real{1.0f, 0.0f, 0.0f, 0.0f};
  quat dual{0.0f, 0.0f, 0.0f, 0.0f};
};

// The rigid part of each skinning matrix as a dual quaternion. Scale and shear are dropped (DQS
// blends rigid motions only): the rotation is taken from the orthonormalised upper 3x3.
void skinning_dual_quaternions(std::span<const mat4> skinning, std::span<DualQuat> out);

// DQS (Kavan et al. 2007): per vertex, blend the joints' dual quaternions with the weights, each
// flipped onto the hemisphere of the vertex's first influence (antipodality: q and −q are the same
// rotation, and blending across hemispheres would cancel them), normalise, and apply. Normals are
// rotated by the blended rotation. Pass empty normal spans to skin positions only.
void skin_dual_quaternion(std::span<const DualQuat> skinning, std::span<const JointIndices> joints,
                          std::span<const vec4> weights, std::span<const vec3> rest_positions,
                          std::span<const vec3> rest_normals, std::span<vec3> out_positions,
                          std::span<vec3> out_normals, SkinningPath path = SkinningPath::Auto);

}  // namespace gestura
