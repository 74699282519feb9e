#pragma once
// The walk cycle (alias-movement-through-environments.txt §6.1, after Zeltzer): each leg alternates a
// stance phase of five segments — heel strike, foot flat, mid-stance, heel off, toe off — and a swing
// phase of three — acceleration, mid-swing, deceleration. The segments are parameters, not equal
// lengths of time; speeding up or slowing down the walk changes the time each takes. A higher level
// schedules the steps from the time and distance available (here: from the body's trajectory), a
// lower one poses the legs in each segment (walk.hpp).
//
// Footsteps come from the trajectory the body follows: the step clock runs at the cadence the
// speed asks for (step length grows with speed, Grieve's rule of thumb), a foot lands where the
// pelvis will be at that foot's mid-stance (half a step ahead, half the stance width to its side),
// turning on the spot is stepping round, and a stop ends with the feet side by side under the
// pelvis. Each plant sits on the ground found below it, and on stairs it slides along the foot to lie
// on one tread.
#include <vector>

#include "gestura/world/environment.hpp"
#include "gestura/world/trajectory.hpp"
#include "gestura/world/walk_rig.hpp"

namespace gestura {

enum class GaitPhase : std::uint8_t {
  HeelStrike, FootFlat, MidStance, HeelOff, ToeOff,  // stance
  EarlySwing, MidSwing, LateSwing,                   // swing
};
const char* gait_phase_name(GaitPhase phase);

struct GaitParams {
  // Step length at the reference speed, as a fraction of body height (0.41·1.70 m ≈ 0.70 m at 1.3 m/s).
  float step_length = 0.41f;
  float reference_speed = 1.3f;
  float min_cadence = 1.5f;            // steps per second whenever the body moves or turns
  float max_cadence = 2.6f;
  float turn_per_step = deg(30.0f);    // stepping round on the spot
  float max_foot_turn = deg(30.0f);    // a landing foot points at most this far from the body's heading
  float double_support = 0.2f;         // of a step period: both feet down after each heel strike
  // Stance segment boundaries as fractions of the stance (heel strike ends at foot flat, …).
  float foot_flat_at = 0.12f, mid_stance_at = 0.3f, heel_off_at = 0.55f, toe_off_at = 0.82f;
  float heel_strike_angle = deg(14.0f);   // toes up at heel strike
  float toe_off_angle = deg(48.0f);       // heel up at toe off
  float swing_clearance = 0.045f;          // the foot's lowest point above the ground mid-swing
  float toe_out = deg(5.0f);
  // Pelvis and upper body, at the reference speed (scaled with speed).
  float bob = 0.018f, sway = 0.018f, lowering = 0.02f;
  float pelvis_rotation = deg(5.0f), pelvis_list = deg(3.5f), thorax_counter = 0.7f;
  float arm_swing = deg(18.0f), elbow_bend = deg(14.0f);
  float finger_curl = deg(18.0f);
};

struct Footstep {
  int foot = 0;              // 0 left, 1 right
  float lift = 0.0f;         // toe off of the previous plant (seconds)
  float land = 0.0f;         // heel strike
  vec3 position{0.0f};       // plant frame origin (on the sole under the ankle), on the ground
  float yaw = 0.0f;          // foot direction
  vec3 normal{0, 1, 0};      // ground normal under the foot
};

struct FootstepPlan {
  // Where each foot stands at time 0 (before its first step).
  Footstep initial[2];
  std::vector<Footstep> steps;  // by landing time; feet alternate within a walk
  // Per foot, its steps' indices in order.
  std::vector<std::size_t> of_foot[2];
};

// Contract: the trajectory has at least one sample. `env` may be null (flat ground at the
// trajectory's height).
FootstepPlan plan_footsteps(const RootTrajectory& body, const WalkRig& rig, const GaitParams& params, const Environment* env);

// Where a foot is at time t: the plant it stands on (and its stance progress), or its swing from one
// plant to the next.
struct FootState {
  bool swinging = false;
  GaitPhase phase = GaitPhase::MidStance;
  const Footstep* from = nullptr;  // the plant stood on (stance) or left (swing)
  const Footstep* to = nullptr;    // swing: the plant it goes to
  float stance_fraction = 0.5f;    // stance: 0 at heel strike … 1 at toe off; 0.5 when standing still
  float swing_fraction = 0.0f;     // swing: 0 at toe off … 1 at heel strike
  float stance_start = 0.0f, stance_end = 0.0f;  // seconds (end = +inf while standing)
};
FootState foot_state(const FootstepPlan& plan, int foot, float t, const GaitParams& params);

// Step length for a speed (m), and the cadence (steps/s) the step clock runs at.
float step_length_for(const GaitParams& params, float body_height, float speed);

}  // namespace gestura
