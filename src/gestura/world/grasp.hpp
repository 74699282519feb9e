#pragma once
// Reaching and grasping (alias-movement-through-environments.txt §6.2; realtime-virtual-humans.txt
// §3, the grasping motion generator): a grasp chosen from the object's size and shape, the hand
// frame it asks for, the arm brought there by the pseudo-inverse Jacobian (damped least squares,
// ik/dls.hpp) with position and orientation, and the fingers closed until their skin touches the
// object's surface — touching, not entering it.
//
// Grasps (after Cutkosky's taxonomy, reduced):
//   power      a cylinder (or a thin box's edge) up to ~9 cm thick: palm against its side, fingers
//              wrapped round it, thumb opposed — a bottle, a door's lever handle, a rail
//   spherical  a ball of 5–16 cm: palm over it, fingers spread round it
//   precision  anything smaller than ~5 cm across: the hand over it, the index and middle fingers'
//              pads pressing it, the thumb opposed (a two-finger precision grip)
//   flat       larger than a hand can close round: the palm laid on the surface (pushing a door)
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/sign/signing_rig.hpp"
#include "gestura/world/environment.hpp"

namespace gestura {

enum class GraspType : std::uint8_t { Power, Spherical, Precision, Flat };
const char* grasp_name(GraspType type);

struct GraspPlan {
  GraspType type = GraspType::Flat;
  Hand hand = Hand::Right;
  vec3 palm_centre{0.0f};   // where the palm centre goes (world)
  vec3 palm_normal{0.0f};   // out of the palm, toward the object
  vec3 finger{0.0f};        // along the extended fingers
  WorldPrimitive object;    // the part of the object the hand holds (for contact)
  float size = 0.0f;        // the grasped dimension (diameter, thickness)
  // The grasp may turn about this line and keep holding the same way (round a bar's axis, about a
  // ball's vertical, about a flat palm's normal): what the reach tries when the first turn cannot be
  // had within the arm's limits.
  vec3 pivot_point{0.0f};
  vec3 pivot_axis{0.0f, 1.0f, 0.0f};
};

// The grasp turned by `angle` about its pivot line.
GraspPlan turned(const GraspPlan& grasp, float angle);

// The grasp for a primitive reached from `from` (the shoulder, world) with `hand`.
GraspPlan choose_grasp(const WorldPrimitive& part, const vec3& from, Hand hand, const SigningRig& rig);

// The grasp of an object: its part nearest to `from` (a lever handle on a door, the bottle on a
// table). None when the object has no primitive parts (meshes cannot be grasped).
std::optional<GraspPlan> choose_object_grasp(const Environment& env, int object, const vec3& from, Hand hand,
                                             const SigningRig& rig);

// The wrist's world rotation that puts the hand in the grasp's frame.
quat grasp_wrist_rotation(const GraspPlan& grasp, const SigningRig& rig);

struct ReachResult {
  bool reached = false;          // the palm centre within 1 cm of the target
  float position_error = 0.0f;   // metres
  float orientation_error = 0.0f;  // radians
  int iterations = 0;
};

// Moves the arm of `hand` in `pose` (world model: its root placed) so the palm centre reaches
// `palm_centre` with the wrist turned to `wrist_rotation` (optional): damped least squares over the
// clavicle, shoulder, elbow and wrist, from a bent-elbow ready posture when `from_ready`.
ReachResult reach_arm(const SigningRig& rig, Hand hand, const vec3& palm_centre, const std::optional<quat>& wrist_rotation,
                      Pose& pose, bool from_ready = true);

// Reaches for the grasp and its turns about the pivot (0, ±25°, ±50°, ±75°…), keeping the one whose
// palm gets nearest (within 1 cm) with the least turn error. `grasp` is updated to the one used.
ReachResult reach_for_grasp(const SigningRig& rig, GraspPlan& grasp, Pose& pose);

// Finger closure for a grasp: per finger (thumb … pinky) the curl 0..1 at which its skin first
// touches the object, found by bisection on the skinned finger against the object's exact shape.
struct FingerClosure {
  std::array<float, 5> curl{};        // 0 open … 1 fully bent
  std::array<bool, 5> touching{};     // whether the finger reached the surface
};
FingerClosure close_fingers(const SigningRig& rig, const GraspPlan& grasp, Pose& pose);

struct GraspResult {
  ReachResult reach;
  FingerClosure closure;
  std::array<float, 5> distances{};  // each finger's skin to the object (finger_distances)
};

// Reach (reach_for_grasp), close the fingers (close_fingers), and where some part of the hand the
// fingers cannot lift out still enters the object, set the palm back by that much and grasp again.
GraspResult perform_grasp(const SigningRig& rig, GraspPlan& grasp, Pose& pose);

// Writes the finger joints of `hand` for curls (the grasp's preshape: thumb opposed for power,
// spherical and precision grasps).
void set_finger_curls(const SigningRig& rig, Hand hand, GraspType type, const std::array<float, 5>& curl, Pose& pose);

// Signed distance of each finger's skin to the grasped object (min over its vertices), for checks.
std::array<float, 5> finger_distances(const SigningRig& rig, const GraspPlan& grasp, const Pose& pose);

}  // namespace gestura
