#include "gestura/sign/hand_solver.hpp"

#include "gestura/ik/dls.hpp"
#include "gestura/ik/swivel_arm.hpp"
#include "gestura/sign/sign_performer.hpp"

namespace gestura {

HandSolveResult solve_hand(const SigningRig& rig, Hand hand, const HandState& state, float body_margin,
                           bool search_circle, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                           std::vector<vec3>& points) {
  const Skeleton& s = rig.skeleton();
  const HandRig& h = rig.hand(hand);
  const quat wrist_rotation = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation},
                                                 h.rest_frame.rotation, h.rest_wrist_rotation);
  // Seed: the clavicle relaxed, the arm from the analytic solver at a natural elbow swivel
  // (continuing last frame's). It is exact when the joint ranges allow the hand's place and
  // turn; when they do not, wrist and forearm stop at their limits (the nearest turn the arm
  // can make) and the palm is put back where it belongs for that turn.
  pose.rotations[static_cast<std::size_t>(h.clavicle)] = rig.neutral.rotations[static_cast<std::size_t>(h.clavicle)];
  const mat4 shoulder_parent = parent_model_matrix(s, pose, h.shoulder);
  const vec3 shoulder_at = vec3(shoulder_parent * vec4(s.rest_translations[static_cast<std::size_t>(h.shoulder)], 1.0f));
  const quat shoulder_parent_rotation = glm::normalize(glm::quat_cast(mat3(shoulder_parent)));
  SwivelGoal goal{state.position - wrist_rotation * h.palm_centre_local, wrist_rotation};
  SwivelPreference prefer;
  prefer.previous = solver.swivel;
  prefer.search_circle = search_circle;
  SwivelSolution arm = solve_swivel_arm(s, h.swivel, shoulder_at, shoulder_parent_rotation, goal, prefer);
  if (arm.orientation_excess > deg(1.0f)) {
    apply_swivel_solution(s, h.swivel, arm, pose);
    const quat reached = glm::normalize(glm::quat_cast(mat3(parent_model_matrix(s, pose, h.wrist)))) *
                         pose.rotations[static_cast<std::size_t>(h.wrist)];
    goal.wrist_position = state.position - reached * h.palm_centre_local;
    arm = solve_swivel_arm_at(s, h.swivel, shoulder_at, shoulder_parent_rotation, goal, arm.swivel, prefer);
  }
  apply_swivel_solution(s, h.swivel, arm, pose);
  solver.swivel = arm.swivel;

  // Refine with damped least squares over the whole chain, clavicle included (the swivel
  // solver leaves it relaxed, and its forearm twist is one pass short of exact). The posture
  // it is pulled toward is the seed itself, so it stays on the seed's elbow swivel. Where the
  // turn cannot be made at the planned place, a hand at the body keeps its place (a radian of
  // turn weighs like 8 cm of place) and turns as far as it can; a hand out in the signing
  // space gives way a few centimetres (a radian weighs like 25 cm), as a signer's would, to
  // keep the notated turn (fingers straight up low in front of the chest).
  IkTarget target;
  target.position = state.position;
  target.orientation = wrist_rotation;
  target.has_orientation = true;
  const mat4 base = parent_model_matrix(s, pose, h.arm.joints.front());
  load_angles(s, h.arm, pose, solver.workspace);
  solver.seed = solver.workspace.angles;
  IkSettings settings;
  settings.max_iterations = 20;  // from an exact seed a few steps do
  settings.position_tolerance = 1e-3f;
  settings.orientation_tolerance = deg(1.5f);
  settings.preferred_angles = solver.seed;
  settings.orientation_scale = state.at_body ? 0.08f : 0.25f;
  settings.null_space_gain = 0.3f;
  IkResult r = solve_dls(s, h.arm, base, target, settings, solver.workspace, pose);

  // Keep the hand out of the body: push the whole hand along the body's outward normal at its
  // deepest point, a few times (leaving one part of the body can enter another).
  for (int pass = 0; pass < 3; ++pass) {
    local_to_model(s, pose, model);
    hand_surface_points(rig, h.hand, model, points);
    float deepest = 0.0f;
    vec3 outward(0, 0, 1);
    for (const vec3& p : points) {
      vec3 n;
      const float d = body_signed_distance(rig, model, p, &n) - body_margin;
      if (d < deepest) deepest = d, outward = n;
    }
    if (deepest >= -1e-4f) break;
    target.position += outward * (-deepest);
    // Getting out of the body comes before the exact hand orientation.
    IkSettings escape = settings;
    escape.orientation_scale = 0.08f;
    r = solve_dls(s, h.arm, base, target, escape, solver.workspace, pose);
  }
  return HandSolveResult{r.position_error, r.orientation_error};
}

}  // namespace gestura
