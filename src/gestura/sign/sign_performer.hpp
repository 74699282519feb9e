#pragma once
// From a plan to motion: every frame, each hand's planned state (palm position, hand frame, shape)
// becomes joint rotations — the arm by inverse kinematics from the clavicle to the wrist (position
// and orientation, joint limits, a pull toward a relaxed posture that gives the elbow its natural
// swivel), the fingers from the hand posture — with the hand kept out of the body.
#include "gestura/anim/clip.hpp"
#include "gestura/sign/sign_planner.hpp"

namespace gestura {

struct PerformOptions {
  float fps = 30.0f;
  float body_margin = 0.004f;  // metres the hand is kept off the collision body
};

struct PerformanceStats {
  int frames = 0;
  float max_position_error = 0.0f;     // metres, IK residual of the wrist, any frame
  float max_orientation_error = 0.0f;  // radians
  float max_penetration = 0.0f;        // metres, hand points inside the collision body after solving
  // How far the performed hand is from the plan at the planned key instants (the frame nearest
  // the end of every segment that leaves a hand in a signing posture): the distance of the point
  // where the hand meets the body (planned_contact) for a hand at the body, of the palm centre for
  // a hand in space, and the angle between the performed and planned hand frames. Measured on the final pose, so
  // everything the performer did (keeping the hand out of the body, clamping to limits) counts.
  float key_position_error = 0.0f;     // metres, postures at the body (HandState::at_body)
  float key_space_position_error = 0.0f;  // metres, postures out in the signing space
  float key_orientation_error = 0.0f;  // radians
  float key_position_time = 0.0f;      // seconds: when the largest position error happened
  float key_space_position_time = 0.0f;
  float key_orientation_time = 0.0f;   // seconds: when the largest orientation error happened
  // How high a signing hand's elbow rose above its own shoulder joint, any frame (metres; negative:
  // it stayed below). Signers raise the elbow to shoulder height only at the top of the head.
  float max_elbow_rise = -1.0f;
};

// A clip on the rig's skeleton, keyed every frame on the arms and fingers.
Clip perform_plan(const SignPlan& plan, const SigningRig& rig, const PerformOptions& options = {},
                  PerformanceStats* stats = nullptr);

}  // namespace gestura
