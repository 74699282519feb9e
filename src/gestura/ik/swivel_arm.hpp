#pragma once
// Analytic arm IK with an elbow swivel angle (the closed-form arm of Tolani, Goswami & Badler 2000,
// "Real-time inverse kinematics techniques for anthropomorphic limbs", fitted to H-Anim joints).
//
// The arm is shoulder (3 DoF) → elbow (hinge, then forearm twist) → wrist (2 DoF). For a wrist
// goal (position and rotation):
//   * the shoulder–wrist distance fixes the elbow flexion;
//   * the elbow then lies on a circle about the shoulder–wrist line; its place on that circle is
//     the swivel angle φ (0 = the elbow straight below the line, + = out, away from the body);
//   * shoulder rotation follows from the elbow and wrist positions;
//   * forearm twist and the wrist's two angles follow from the hand rotation (one Euler
//     decomposition).
// Every φ gives an exact solution when the joint ranges allow it. The solver samples φ and picks
// the one with the least range excess, preferring a natural, low elbow slightly out from the body
// (and, frame to frame, the previous φ). Angles are then clamped: when no φ can turn the hand as
// asked, the wrist and forearm stop at their limits — the nearest turn the arm can make — instead
// of the shoulder twisting the whole arm around to chase it.
//
// The forearm twist axis need not run exactly along the forearm (the default avatar's A-pose tilts
// it a little): a few passes alternate between flexion and twist until both agree.
#include <optional>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct SwivelArm {
  int shoulder = -1, elbow = -1, wrist = -1;
  vec3 upper{0.0f}, fore{0.0f};            // the elbow in the shoulder's frame, the wrist in the elbow's
  quat elbow_rest{1, 0, 0, 0};             // the elbow frame at rest, in the shoulder's frame
  int hinge_axis = 0, twist_axis = 1;      // the elbow's outer and inner free Euler axes
  RotationOrder hand_order = RotationOrder::YZX;  // twist, then the wrist's outer and inner axes
  float outward = 1.0f;                    // +1: the arm's outside is +X (left arm), −1 (right arm)
};

// Contract: the elbow descends from the shoulder and the wrist from the elbow, through joints
// without degrees of freedom (twist helpers) that stay at rest; the elbow has exactly two free
// axes, the wrist two, and together with the elbow's inner axis they name three different axes;
// the wrist and the joints between elbow and wrist have no rest rotation. Throws gestura::Error
// naming the joint otherwise.
SwivelArm make_swivel_arm(const Skeleton& skeleton, int shoulder, int elbow, int wrist);

struct SwivelGoal {
  vec3 wrist_position{0.0f};
  quat wrist_rotation{1, 0, 0, 0};  // model space
};

// What decides among swivel angles.
struct SwivelPreference {
  float natural = deg(20.0f);            // the relaxed swivel (elbow a little out from below)
  std::optional<float> previous;         // last frame's swivel, to stay on one continuous solution
  // When the solution near `previous` has to clamp a joint, also search the whole circle for a
  // better one. Animation may ask for that only every few frames: the search is most of the cost.
  bool search_circle = true;
};

struct SwivelSolution {
  float swivel = 0.0f;
  vec3 shoulder{0.0f}, elbow{0.0f}, wrist{0.0f};  // Euler angles per joint, within limits
  float position_excess = 0.0f;     // radians the shoulder and elbow flexion were clamped by
  float orientation_excess = 0.0f;  // radians the twist and wrist were clamped by
  float cost = 0.0f;
};

// The best swivel for the goal. `shoulder_position` and `shoulder_parent` are the model-space
// position of the shoulder joint and rotation of its parent (the clavicle as it is now).
SwivelSolution solve_swivel_arm(const Skeleton& skeleton, const SwivelArm& arm, const vec3& shoulder_position,
                                const quat& shoulder_parent, const SwivelGoal& goal, const SwivelPreference& preference);

// The same at one given swivel angle (no search).
SwivelSolution solve_swivel_arm_at(const Skeleton& skeleton, const SwivelArm& arm, const vec3& shoulder_position,
                                   const quat& shoulder_parent, const SwivelGoal& goal, float swivel,
                                   const SwivelPreference& preference);

// Writes the solution's local rotations into `pose`.
void apply_swivel_solution(const Skeleton& skeleton, const SwivelArm& arm, const SwivelSolution& solution, Pose& pose);

// The swivel angle of an arm posed with its shoulder, elbow and wrist at these model-space
// positions (the inverse of the solver's elbow placement): to continue from a given posture.
float measure_swivel(const SwivelArm& arm, const vec3& shoulder, const vec3& elbow, const vec3& wrist);

}  // namespace gestura
