#pragma once
// The skeleton as flat arrays, parents before children.
//
// This is the 1999 operation stack of sign-language-interpreter.txt §4.1 (Push / Pop / Deform&Draw)
// flattened: walking joints in index order with parents[i] < i visits every segment after its parent,
// so one forward loop replaces the explicit matrix stack.
//
// Each joint has a rest transform (offset and orientation relative to its parent) and up to three
// rotational degrees of freedom with a rotation order and anatomical limits. A joint's local
// transform during animation *replaces* the rest transform (it is not a delta): a pose stores full
// local transforms, and rest_pose() gives the pose with every joint at rest.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/rotation_order.hpp"

namespace gestura {

// Rotational degrees of freedom of a joint, expressed as Euler angles relative to the rest
// orientation: local_rotation = rest_rotation · euler_to_quat(angles, order).
struct JointDofs {
  RotationOrder order = RotationOrder::XYZ;
  std::uint8_t axes = 0;            // bit 0 = x, bit 1 = y, bit 2 = z free; others locked at 0
  vec3 min_angle{0.0f};             // radians, per axis; only meaningful for free axes
  vec3 max_angle{0.0f};

  int count() const { return (axes & 1) + ((axes >> 1) & 1) + ((axes >> 2) & 1); }
  bool free(int axis) const { return (axes >> axis) & 1; }
};

// Denavit–Hartenberg description of a revolute joint (alias-movement-through-environments.txt §4.1):
// transform = Rz(theta) · Tz(d) · Tx(a) · Rx(alpha), theta being the joint variable's offset.
struct DenavitHartenberg {
  float a = 0.0f, alpha = 0.0f, d = 0.0f, theta = 0.0f;
  mat4 matrix(float joint_angle) const;
};

struct Skeleton {
  std::vector<std::string> names;
  std::vector<std::int16_t> parents;       // -1 for roots; parents[i] < i
  std::vector<vec3> rest_translations;     // offset from the parent joint, parent's frame, metres
  std::vector<quat> rest_rotations;        // orientation relative to the parent
  std::vector<vec3> rest_scales;
  std::vector<JointDofs> dofs;             // per joint
  std::vector<std::optional<DenavitHartenberg>> dh;  // optional per joint; empty vector = none

  std::size_t size() const { return names.size(); }
  int find(std::string_view name) const;  // -1 when absent

  // Appends a joint; returns its index. parent must already exist (or be -1).
  int add_joint(std::string name, int parent, const vec3& rest_translation,
                const quat& rest_rotation = quat(1.0f, 0.0f, 0.0f, 0.0f));

  // Throws gestura::Error naming the first problem: sizes disagree, parent order, duplicate or
  // empty names, non-finite rest values, min > max limits.
  void validate() const;

  int total_dofs() const;
};

// A joint's slot in the per-joint arrays (poses, model matrices, clip tracks). Joints are ints so
// that -1 can say "none"; only an existing joint has a slot.
constexpr std::size_t joint_slot(int joint) { return static_cast<std::size_t>(joint); }

// A pose: local transforms of every joint, structure of arrays.
struct Pose {
  std::vector<vec3> translations;
  std::vector<quat> rotations;
  std::vector<vec3> scales;

  std::size_t size() const { return rotations.size(); }
  void resize(std::size_t n);
};

Pose rest_pose(const Skeleton& skeleton);

// Local → model space. Contract: parents.size() == local sizes == out.size(), parents[i] < i.
// `root` is applied to the roots (identity for the avatar's own space).
void local_to_model(std::span<const std::int16_t> parents, std::span<const vec3> translations,
                    std::span<const quat> rotations, std::span<const vec3> scales,
                    std::span<mat4> out, const mat4& root = mat4(1.0f));
void local_to_model(const Skeleton& skeleton, const Pose& pose, std::span<mat4> out);

// One joint's position in model space (column 3 of its model matrix).
inline vec3 joint_position(std::span<const mat4> model, int joint) { return vec3(model[joint_slot(joint)][3]); }
// Joint positions in model space (column 3 of each model matrix).
void model_positions(std::span<const mat4> model, std::span<vec3> out);

// The segment transform of sign-language-interpreter.txt §3, M = B · R1 · R2 · R3 · B⁻¹: rotate a
// segment by Euler angles about its joint centre B (a point in the parent's frame).
mat4 segment_transform(const vec3& joint_centre, const vec3& angles, RotationOrder order);

// Euler angles of a local rotation relative to the joint's rest orientation, in the joint's order.
vec3 joint_angles(const Skeleton& skeleton, int joint, const quat& local_rotation);
quat joint_rotation(const Skeleton& skeleton, int joint, const vec3& angles);

// Clamps every joint of `pose` into its limits (locked axes to 0). Returns the number of joints
// changed. Joints with no free axis keep their rotation (they are not articulated).
int clamp_to_limits(const Skeleton& skeleton, Pose& pose);
// The same for one joint's local rotation; returns whether it changed.
bool clamp_joint_to_limits(const Skeleton& skeleton, int joint, quat& local_rotation);
bool within_limits(const Skeleton& skeleton, int joint, const quat& local_rotation,
                   float tolerance = deg(0.5f));

}  // namespace gestura
