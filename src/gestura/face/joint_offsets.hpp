#pragma once
// Offset rotations layered onto joints a clip may already drive: shoulders raised on the clavicles
// while the arm IK keys them, a lean of the spine, the eyes turned. Each offset enters and leaves
// with the §5.2.5 sinusoidal ramps (as face actions and head actions do) and may oscillate. Offsets
// on one joint add to its Euler angles (skeleton.hpp joint_angles), and the sum stays in the
// joint's limits.
//
// Angles are in the joint's own Euler order and axes (for the default avatar's joints, whose rest
// rotations are the identity: x pitch, + bends forward / turns the eyes down; y yaw, + turns to the
// avatar's left; z roll).
#include <span>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

struct JointOffset {
  std::string_view joint;           // skeleton joint name (static storage)
  vec3 angles{0.0f};                // radians, full weight
  float start = 0.0f, end = 0.0f;   // seconds
  float ramp_in = 0.0f, ramp_out = 0.0f;  // seconds; ramp_in + ramp_out <= end - start
  float frequency = 0.0f;           // Hz; > 0: angles · sin(2πf(t − start)) under the ramps
  // The joint's children keep their orientation in the parent's space (the offset is undone in
  // their local rotations), so a raised clavicle lifts the arm without swinging it outwards.
  bool children_keep_orientation = false;
};

// An offset with default_ramp (face_action.hpp) on both sides.
JointOffset make_offset(std::string_view joint, vec3 angles, float start, float end, float frequency = 0.0f);

// The summed angles of every offset on `joint` at time t.
vec3 offset_angles(std::span<const JointOffset> offsets, std::string_view joint, float t);

// Composes the offsets onto the clip's rotation tracks: a joint's keys become its existing keys
// (or its rest rotation when the track is empty) plus 8 steps per ramp and 16 per oscillation
// cycle, each turned by the offset at that time and clamped to the joint's limits (a joint with
// no free axis is not clamped).
// Sizes the clip's joint tracks to the skeleton when it has none. Returns the names of joints the
// skeleton does not have (their offsets are skipped). Throws gestura::Error naming the offset for
// non-finite values, an end before the start, ramps longer than the offset, or a clip made for
// another skeleton.
std::vector<std::string_view> add_joint_offsets(std::span<const JointOffset> offsets, const Skeleton& skeleton,
                                                Clip& clip);

}  // namespace gestura::face
