#pragma once
// Putting one hand where a HandState says: the arm by the analytic swivel solver (a natural elbow,
// joint limits respected), refined by damped least squares, then pushed out of the collision body.
// One rule decides the arm a frame keeps (solve_hand): the elbow continues last frame's; where
// that arm lands over 1 cm off its plan, ends in the body or is lost, the posture is also solved
// as a hand without history is, and, when even that is lost, last frame's arm is a candidate; the
// one kept reads best as the notated sign (place and turn against what still reads as them), with
// a hand in the body counted against it.
// Where a hand lands depends on its plan, hardly on where the arm came from.
// One frame of perform_plan, and what the sentence layer uses to solve a single posture, so both
// solve exactly the same problem.
#include <optional>
#include <span>
#include <vector>

#include "gestura/ik/chain.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

// What a hand's solver carries from one frame to the next.
struct HandSolverState {
  explicit HandSolverState(const IkChain& arm) : workspace(arm) {}
  std::optional<float> swivel;  // the elbow swivel chosen last frame (none after rest)
  IkWorkspace workspace;
  std::vector<float> seed;      // this frame's analytic angles, the posture DLS keeps to
};

struct HandSolveResult {
  float position_error = 0.0f;     // metres, the IK residual before leaving the body
  float orientation_error = 0.0f;  // radians
};

// Contract: `state.active`; `pose` holds the rest of the body with the fingers already posed for
// state.shape (apply_hand_posture). Poses the arm chain, clavicle to wrist, for the hand's place and turn;
// `search_circle` lets the swivel solver look around the whole elbow circle (the costly part;
// animation asks for it every few frames). `model` and `points` are scratch buffers. Does not clamp
// the pose to joint limits (the caller does, once both hands are solved).
HandSolveResult solve_hand(const SigningRig& rig, Hand hand, const HandState& state, float body_margin,
                           bool search_circle, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                           HandPoints& points);

// One hand of one frame: the fingers posed for state.shape and, for a signing hand, the arm solved
// (solve_hand, which holds the whole arm-choosing rule); a resting hand's arm hangs exactly in the rest pose (a stretched arm at its limits
// is a singular target for the iterative solvers) and forgets its swivel. What perform_plan does
// for each hand every frame, and what the sentence layer does to solve a single posture.
HandSolveResult pose_hand(const SigningRig& rig, Hand hand, const HandState& state, float body_margin,
                          bool search_circle, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                          HandPoints& points);

// The point where a hand at the body meets it: of the hand's surface points (hand_surface_points
// of the posed `model`, passed as `points`), the one nearest the body once the hand is placed and
// turned as `state` plans. Returns that point's planned position; `index` is its place in `points`.
// Contract: `model` holds the hand's fingers as posed for state.shape.
vec3 planned_contact(const SigningRig& rig, Hand hand, const HandState& state, std::span<const mat4> model,
                     std::span<const vec3> points, std::size_t& index);

}  // namespace gestura
