#pragma once
// A serial chain of skeleton joints for the iterative solvers (CCD, damped least squares).
//
// The chain runs from a root joint to a tip joint, each joint the parent of the next, and ends in an
// effector: a point (and frame) fixed in the tip joint's frame — the palm centre, a fingertip site.
// The solvers work in joint-angle space: every free Euler axis of every chain joint is one degree of
// freedom, so anatomical limits (Skeleton::dofs) are plain per-angle boxes and can be clamped after
// every update. Locked axes stay at zero.
//
// Everything a solve touches lives in an IkWorkspace sized once per chain, so solving never allocates.
#include <cstdint>
#include <span>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct IkChain {
  std::vector<int> joints;           // skeleton indices, root first; joints[k] is the parent of joints[k+1]
  vec3 effector_offset{0.0f};        // effector position in the tip joint's frame
  quat effector_rotation{1.0f, 0.0f, 0.0f, 0.0f};  // effector frame relative to the tip joint's frame
  // One entry per degree of freedom, in chain order and, within a joint, outermost Euler axis first.
  std::vector<std::uint8_t> dof_link;   // index into joints
  std::vector<std::uint8_t> dof_axis;   // 0 = x, 1 = y, 2 = z
  std::vector<std::uint8_t> dof_slot;   // position of that axis in the joint's rotation order (0 = outermost)

  std::size_t size() const { return joints.size(); }
  std::size_t dof_count() const { return dof_axis.size(); }
};

// Builds the chain from `root` down to `tip` (tip must descend from root). Throws gestura::Error
// naming the joints when they are not on one parent path, or when the chain has more than 64 joints.
IkChain make_chain(const Skeleton& skeleton, int root, int tip, const vec3& effector_offset = vec3(0.0f),
                   const quat& effector_rotation = quat(1.0f, 0.0f, 0.0f, 0.0f));

// Where the effector should go. The orientation is optional: without it only the position counts.
struct IkTarget {
  vec3 position{0.0f};
  quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // effector frame in model space
  bool has_orientation = false;
};

struct IkSettings {
  int max_iterations = 200;                  // CCD averages ~33 sweeps on the arm; its slow tail needs more
  float position_tolerance = 1e-5f;          // metres; stop when both residuals are below tolerance
  float orientation_tolerance = deg(0.05f);  // radians
  // Metres per radian that make orientation error commensurable with position error:
  // E = |Pd − Pc|² + orientation_scale² · Eo. 0.1 m ≈ a hand's length.
  float orientation_scale = 0.1f;
  // Damped least squares only.
  float damping = 0.02f;                     // λ in Jᵀ(JJᵀ + λ²I)⁻¹; larger = steadier, slower near the goal
  float max_step = 0.2f;                     // longest error vector (m, or scaled rad) followed per iteration
  float max_angle_step = 0.25f;              // largest change of any joint angle per iteration (rad);
                                             // keeps steps sane near singular, stretched poses
  float null_space_gain = 0.2f;              // pull toward `preferred_angles` inside the null space
  std::span<const float> preferred_angles;   // per dof (radians); empty = no posture preference
};

struct IkResult {
  int iterations = 0;
  float position_error = 0.0f;      // metres, after the solve
  float orientation_error = 0.0f;   // radians, after the solve (0 without an orientation target)
  bool converged = false;           // both residuals within tolerance
};

// Scratch for one chain: every array a solve needs, sized by the chain. Reuse it across solves.
struct IkWorkspace {
  explicit IkWorkspace(const IkChain& chain);

  std::vector<float> angles;          // per dof
  std::vector<float> lower, upper;    // per dof limits
  std::vector<vec3> link_angles;      // per link: Euler angles (x, y, z)
  std::vector<vec3> positions;        // per link: model-space joint position
  std::vector<quat> rotations;        // per link: model-space joint rotation
  std::vector<vec3> axes;             // per dof: model-space rotation axis
  std::vector<float> jacobian;        // 6 × dofs, row-major
  std::vector<float> step;            // per dof
  std::vector<float> previous;        // per dof: angles before the last step (for rejecting it)
  std::vector<std::uint8_t> active;   // per dof: 1 = free to move this iteration
};

// The model transform of joint `joint`'s parent in `pose` (identity for a root), found by walking up
// the parents. No allocation; cost is the depth of the joint.
mat4 parent_model_matrix(const Skeleton& skeleton, const Pose& pose, int joint);

// --- Building blocks shared by the solvers (exposed for tests) -------------------------------

// Reads the chain's joint angles from `pose` (within the workspace's angle and limit arrays).
// Throws gestura::Error when `ws` was sized for another chain or `pose` for another skeleton.
void load_angles(const Skeleton& skeleton, const IkChain& chain, const Pose& pose, IkWorkspace& ws);
// Writes the workspace angles back as local rotations of the chain joints.
void store_angles(const Skeleton& skeleton, const IkChain& chain, IkWorkspace& ws, Pose& pose);
// Forward kinematics of the chain from the workspace angles: fills positions, rotations and axes;
// returns the effector position and writes its model rotation to `effector_rotation`.
vec3 chain_forward(const Skeleton& skeleton, const IkChain& chain, const Pose& pose, const mat4& base,
                   IkWorkspace& ws, quat& effector_rotation);

// Rotation vector (axis · angle, shortest way) turning `from` into `to`.
vec3 rotation_error(const quat& from, const quat& to);

}  // namespace gestura
