#include "gestura/sign/hand_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "gestura/ik/dls.hpp"
#include "gestura/ik/residual.hpp"
#include "gestura/ik/swivel_arm.hpp"

namespace gestura {

namespace {

constexpr int kEscapePasses = 5;           // pushes out of the body per frame
constexpr float kEscapeTolerance = 0.002f;  // metres deeper than the margin that calls for the straight way out
constexpr float kEscapeStep = 0.01f;        // metres per step of it
constexpr int kEscapeSteps = 15;
constexpr float kLostHand = 0.03f;         // metres of IK residual that make a frame consider keeping last frame's arm
constexpr float kContactTolerance = 0.002f;  // metres a hand's contact point may miss before it is corrected

constexpr float kSpaceTurnWeight = 0.25f;  // metres a radian of turn weighs against place, out in space…
constexpr float kBodyTurnWeight = 0.08f;   // …and at the body, where the place is a point a signer keeps
constexpr float kContactTurnCost = deg(2.0f);  // turn a contact correction may cost, or up to kTurnRead:
constexpr float kTurnRead = deg(24.0f);  // just inside the 25° within which a 45°-step notated turn still
                                         // reads as itself (synthesis_problem's tolerance)

// The arm a frame keeps (solve_hand): a continued arm that lands over kLandingTolerance (metres, a
// radian of turn weighed as the solver weighs it) off its plan, ends in the body or is lost is also
// solved without history; that arm is only tried when its elbow is kSameElbow or more elsewhere on
// the circle. The arms are compared by how they read (arm_score, in units of what still reads as
// the notated sign), and another arm is kept only when it scores kReadingGain better.
constexpr float kLandingTolerance = 0.01f;
constexpr float kSameElbow = deg(10.0f);
constexpr float kReadingGain = 0.1f;
// What still reads as the notated place and turn (SynthesisTolerance, sign_synthesis.hpp, which
// gives the reasons): 2 cm at the body, where a contact must stay a contact; 5 cm out in the
// signing space, where a place is a region a hand's width across; 25° of turn, within which a
// 45°-step orientation symbol reads as itself and not its neighbour; 1 cm of hand in the body.
constexpr float kReadPlaceAtBody = 0.02f;
constexpr float kReadPlaceInSpace = 0.05f;
constexpr float kReadTurn = deg(25.0f);
constexpr float kReadDepth = 0.01f;

float wrap_angle(float a) { return std::remainder(a, 2.0f * kPi); }

// The arm chain's joint rotations, to go back to (no allocation: this is per-frame code).
struct ArmSnapshot {
  static constexpr std::size_t kMaxJoints = 8;  // clavicle to wrist is 4 on H-Anim arms
  const IkChain* arm;
  std::array<quat, kMaxJoints> rotations;
  ArmSnapshot(const IkChain& chain, const Pose& pose) : arm(&chain) {
    for (std::size_t i = 0; i < std::min(kMaxJoints, chain.joints.size()); ++i)
      rotations[i] = pose.rotations[joint_slot(chain.joints[i])];
  }
  void restore(Pose& pose) const {
    for (std::size_t i = 0; i < std::min(kMaxJoints, arm->joints.size()); ++i)
      pose.rotations[joint_slot(arm->joints[i])] = rotations[i];
  }
};

// Damped least squares, then the chain clamped into its joint limits as the final pose will be
// (the solver's own limit handling leaves angles a hair outside), so that what is measured
// against the body afterwards is what will be performed.
IkResult solve_within_limits(const Skeleton& s, const IkChain& arm, const mat4& base, const IkTarget& target,
                             const IkSettings& settings, IkWorkspace& workspace, Pose& pose) {
  IkResult r = solve_dls(s, arm, base, target, settings, workspace, pose);
  bool clamped = false;
  for (int j : arm.joints) clamped |= clamp_joint_to_limits(s, j, pose.rotations[joint_slot(j)]);
  if (clamped) {  // the residual of the pose that will be performed
    load_angles(s, arm, pose, workspace);
    quat effector_rotation;
    const vec3 effector = chain_forward(s, arm, pose, base, workspace, effector_rotation);
    const int iterations = r.iterations;
    r = measure_residual(effector, effector_rotation, target, settings);
    r.iterations = iterations;
  }
  return r;
}

// How deep the hand's deepest surface point is inside the body plus `margin` (0 when clear).
float hand_depth(const SigningRig& rig, const HandRig& h, float margin, const Pose& pose, std::vector<mat4>& model,
                 HandPoints& points) {
  local_to_model(rig.skeleton(), pose, model);
  return std::max(0.0f, margin + hand_penetration(rig, h.hand, model, points));
}

}  // namespace

vec3 planned_contact(const SigningRig& rig, Hand hand, const HandState& state, std::span<const mat4> model,
                     std::span<const vec3> points, std::size_t& index) {
  const HandRig& h = rig.hand(hand);
  const quat wrist_rotation = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation},
                                                 h.rest_frame.rotation, h.rest_wrist_rotation);
  const mat4 to_wrist = glm::inverse(model[joint_slot(h.wrist)]);
  float nearest = 1e9f;
  vec3 best = state.position;
  index = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const vec3 local = vec3(to_wrist * vec4(points[i], 1.0f));
    const vec3 planned = state.position + wrist_rotation * (local - h.palm_centre_local);
    const float d = body_signed_distance(rig, model, planned);
    if (d < nearest) nearest = d, best = planned, index = i;
  }
  return best;
}

namespace {

// The analytic arm for the hand's place and turn (the swivel solver), from `prefer`.
SwivelSolution seed_arm(const SigningRig& rig, const HandRig& h, const HandState& state, const SwivelPreference& prefer,
                        Pose& pose) {
  const Skeleton& s = rig.skeleton();
  const quat wrist_rotation = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation},
                                                 h.rest_frame.rotation, h.rest_wrist_rotation);
  // Seed: the clavicle relaxed, the arm from the analytic solver at a natural elbow swivel
  // (continuing last frame's, or the best of the whole circle). It is exact when the joint ranges
  // allow the hand's place and turn; when they do not, wrist and forearm stop at their limits (the
  // nearest turn the arm can make) and the palm is put back where it belongs for that turn.
  pose.rotations[joint_slot(h.clavicle)] = rig.neutral.rotations[joint_slot(h.clavicle)];
  const mat4 shoulder_parent = parent_model_matrix(s, pose, h.shoulder);
  const vec3 shoulder_at = vec3(shoulder_parent * vec4(s.rest_translations[joint_slot(h.shoulder)], 1.0f));
  const quat shoulder_parent_rotation = glm::normalize(glm::quat_cast(mat3(shoulder_parent)));
  SwivelGoal goal{state.position - wrist_rotation * h.palm_centre_local, wrist_rotation};
  SwivelSolution arm = solve_swivel_arm(s, h.swivel, shoulder_at, shoulder_parent_rotation, goal, prefer);
  if (arm.orientation_excess > deg(1.0f)) {
    apply_swivel_solution(s, h.swivel, arm, pose);
    const quat reached = glm::normalize(glm::quat_cast(mat3(parent_model_matrix(s, pose, h.wrist)))) *
                         pose.rotations[joint_slot(h.wrist)];
    goal.wrist_position = state.position - reached * h.palm_centre_local;
    arm = solve_swivel_arm_at(s, h.swivel, shoulder_at, shoulder_parent_rotation, goal, arm.swivel, prefer);
  }
  return arm;
}

// From the seed `arm` to the final arm: damped least squares, the contact point put on its place,
// the hand pushed out of the body. `depth` is set to how deep the final hand is (hand_depth).
IkResult refine_arm(const SigningRig& rig, const HandRig& h, const HandState& state, float body_margin,
                    const SwivelSolution& arm, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                    HandPoints& points, float& depth) {
  const Skeleton& s = rig.skeleton();
  const quat wrist_rotation = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), state.orientation},
                                                 h.rest_frame.rotation, h.rest_wrist_rotation);
  apply_swivel_solution(s, h.swivel, arm, pose);

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
  settings.orientation_scale = glm::mix(kSpaceTurnWeight, kBodyTurnWeight, state.body_weight);
  settings.null_space_gain = 0.3f;
  IkResult r = solve_within_limits(s, h.arm, base, target, settings, solver.workspace, pose);

  // At the body, what must be in place is the part of the hand that meets it, not the palm
  // centre: where the arm cannot make the exact turn, an index fingertip 10 cm out from the palm
  // centre would swing centimetres off the chin it touches. Shift the target by the contact
  // point's miss and solve again.
  if (state.body_weight > 0.0f) {
    local_to_model(s, pose, model);
    hand_surface_points(rig, h.hand, model, points);
    std::size_t contact = 0;
    const vec3 planned = planned_contact(rig, h.hand, state, model, points, contact);
    const vec3 miss = (planned - points[contact]) * state.body_weight;
    if (glm::length(miss) > kContactTolerance) {
      // Kept unless it costs the notated turn: a hand turned away from its notated orientation
      // reads as another sign, a contact point a few centimetres off does not.
      const ArmSnapshot before(h.arm, pose);
      target.position += miss;
      const IkResult moved = solve_within_limits(s, h.arm, base, target, settings, solver.workspace, pose);
      if (moved.orientation_error > std::max(r.orientation_error + kContactTurnCost, kTurnRead)) {
        before.restore(pose);
        target.position -= miss;
      } else {
        r = moved;
      }
    }
  }

  // Keep the hand out of the body: push the whole hand out, a few times (leaving one part of the
  // body can enter another). Out is away from the body at the palm centre while that is outside:
  // a fingertip that went past the middle of the neck has its nearest surface at the back, and
  // pushing along its own normal would drive the hand further in.
  for (int pass = 0; pass < kEscapePasses; ++pass) {
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
    vec3 palm_outward;
    const mat4& w = model[joint_slot(h.wrist)];
    if (body_signed_distance(rig, model, vec3(w * vec4(h.palm_centre_local, 1.0f)), &palm_outward) > 0.0f)
      outward = palm_outward;
    target.position += outward * (-deepest);
    // Getting out of the body comes before the exact hand orientation.
    IkSettings escape = settings;
    escape.orientation_scale = 0.08f;
    r = solve_within_limits(s, h.arm, base, target, escape, solver.workspace, pose);
  }

  // Still inside: the arm could not follow the pushes (a place too near its own shoulder for the
  // notated turn, fingers curled into the head). Move the hand straight out from the body at its
  // planned place, keeping the notated turn, a step at a time until it is clear; if nothing
  // clears it, the least deep of the tries. Rare (a few frames of a few signs in thousands).
  depth = hand_depth(rig, h, body_margin, pose, model, points);
  if (depth > kEscapeTolerance) {
    local_to_model(s, pose, model);
    vec3 out(0, 0, 1);
    body_signed_distance(rig, model, state.position, &out);
    ArmSnapshot best(h.arm, pose);
    float best_depth = depth;
    IkResult best_r = r;
    // Out from the body, or forward into the signing space (the way out when the place is
    // beyond the arm's reach, right above its own shoulder), or between the two.
    const vec3 ways[] = {out, vec3(0, 0, 1), glm::normalize(out + vec3(0, 0, 1) + vec3(0, 0, 1e-3f))};
    for (int step = 1; step <= kEscapeSteps && best_depth > kEscapeTolerance; ++step)
      for (const vec3& way : ways) {
        target.position = state.position + way * (kEscapeStep * static_cast<float>(step));
        r = solve_within_limits(s, h.arm, base, target, settings, solver.workspace, pose);
        depth = hand_depth(rig, h, body_margin, pose, model, points);
        if (depth < best_depth) best_depth = depth, best_r = r, best = ArmSnapshot(h.arm, pose);
        if (best_depth <= kEscapeTolerance) break;
      }
    best.restore(pose);
    r = best_r;
    depth = best_depth;
  }
  return r;
}

// Where the posed hand misses its plan: `place` in metres (the part that meets the body for a hand
// at the body, the palm centre in space) and `turn` in radians.
struct PlanMiss {
  float place = 0.0f;
  float turn = 0.0f;
};

PlanMiss plan_miss(const SigningRig& rig, const HandRig& h, const HandState& state, const Pose& pose,
                   std::vector<mat4>& model, HandPoints& points) {
  local_to_model(rig.skeleton(), pose, model);
  const mat4& w = model[joint_slot(h.wrist)];
  float place = glm::distance(vec3(w * vec4(h.palm_centre_local, 1.0f)), state.position);
  if (state.at_body) {
    hand_surface_points(rig, h.hand, model, points);
    std::size_t contact = 0;
    const vec3 planned = planned_contact(rig, h.hand, state, model, points, contact);
    place = glm::distance(planned, points[contact]);
  }
  const float turn =
      glm::length(rotation_error(glm::normalize(glm::quat_cast(mat3(w))), planned_wrist_rotation(rig, h.hand, state)));
  return {place, turn};
}

// How far the posed hand lands from where `state` plans it: the part that meets the body for a hand
// at the body, the palm centre in space, and its turn weighed as the solver weighs it.
float landing_miss(const SigningRig& rig, const HandRig& h, const HandState& state, const Pose& pose,
                   std::vector<mat4>& model, HandPoints& points) {
  const auto [place, turn] = plan_miss(rig, h, state, pose, model, points);
  return place + glm::mix(kSpaceTurnWeight, kBodyTurnWeight, state.body_weight) * turn;
}

// How the posed hand reads against its plan, in units of what still reads as the notated sign: the
// place miss (as landing_miss measures it) over kReadPlaceAtBody or kReadPlaceInSpace and the turn
// over kReadTurn, whichever is worse, plus a unit for each of the two that no longer reads. Up to 1
// the hand reads as notated (what `check` judges); a place and a turn both wrong are two errors a
// viewer sees, worse than either alone. Unlike landing_miss, a turn does not buy a place: an arm
// that keeps the turn a few degrees nearer by landing 5.5 cm off in space reads worse than one
// 4.8 cm off at a turn 16° off.
float reading_miss(const SigningRig& rig, const HandRig& h, const HandState& state, const Pose& pose,
                   std::vector<mat4>& model, HandPoints& points) {
  const auto [place, turn] = plan_miss(rig, h, state, pose, model, points);
  const float p = place / (state.at_body ? kReadPlaceAtBody : kReadPlaceInSpace), t = turn / kReadTurn;
  return std::max(p, t) + static_cast<float>(p > 1.0f) + static_cast<float>(t > 1.0f);
}

}  // namespace

namespace {

// One arm the frame could take, and what it is worth (choose_arm).
struct ArmCandidate {
  ArmSnapshot pose;
  std::optional<float> swivel;  // the elbow swivel to continue from next frame
  HandSolveResult result;
  float score = 0.0f;    // arm_score
  float reading = 0.0f;  // reading_miss alone
};

// How an arm reads (reading_miss), with a hand inside the body, which a viewer sees at once, counted
// in the same units (a unit per kReadDepth deeper than the margin and kEscapeTolerance). No cost on
// elbow height here: an arm continued low would then be kept 2 cm off where one without history
// lands on its place (ASL OUTSIDE), and the sign would depend on where the arm came from.
float arm_score(const SigningRig& rig, const HandRig& h, const HandState& state, float body_margin, const Pose& pose,
                std::vector<mat4>& model, HandPoints& points, float& reading) {
  reading = reading_miss(rig, h, state, pose, model, points);
  const float depth = hand_depth(rig, h, body_margin, pose, model, points);
  return reading + std::max(0.0f, depth - body_margin - kEscapeTolerance) / kReadDepth;
}

// The arm solved from `prefer` (seed_arm, then refine_arm), as a candidate.
ArmCandidate solve_arm(const SigningRig& rig, const HandRig& h, const HandState& state, float body_margin,
                       const SwivelPreference& prefer, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                       HandPoints& points) {
  const SwivelSolution arm = seed_arm(rig, h, state, prefer, pose);
  float depth = 0.0f;
  const IkResult r = refine_arm(rig, h, state, body_margin, arm, solver, pose, model, points, depth);
  ArmCandidate c{ArmSnapshot(h.arm, pose), arm.swivel, HandSolveResult{r.position_error, r.orientation_error}};
  c.score = arm_score(rig, h, state, body_margin, pose, model, points, c.reading);
  return c;
}

}  // namespace

HandSolveResult solve_hand(const SigningRig& rig, Hand hand, const HandState& state, float body_margin,
                           bool search_circle, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                           HandPoints& points) {
  // The one rule for which arm a frame takes. Continuing last frame's elbow keeps the arm on one
  // solution. Where that solution cannot make the place and turn (the elbow low while the hand
  // must point down above the other hand, a hand leaving the ear near the ends of the joint
  // ranges) it would hold the hand centimetres off, or lose it, and where the hand lands would
  // depend on where the arm came from. So when the continued arm lands over kLandingTolerance off
  // its plan, ends in the body or is lost (IK residual over kLostHand), the posture is also solved
  // as a hand without history is (the whole elbow circle searched); when even the better of those
  // is lost, last frame's arm is a candidate too. A lost arm gives way to one that is not;
  // otherwise the arm kept is the continued one unless another scores kReadingGain better
  // (arm_score: how it reads, body depth) and reads as the notated sign (an elbow
  // that jumps round its circle is seen: it has to buy a hand that reads), or the continued arm is
  // in the body.
  const HandRig& h = rig.hand(hand);
  const ArmSnapshot last_frame(h.arm, pose);
  const std::optional<float> last_swivel = solver.swivel;
  SwivelPreference prefer;
  prefer.previous = solver.swivel;
  prefer.search_circle = search_circle;
  ArmCandidate best = solve_arm(rig, h, state, body_margin, prefer, solver, pose, model, points);
  const float continued_miss = landing_miss(rig, h, state, pose, model, points);
  // (A hand touching the body is within the margin of it: only a hand really inside counts.)
  const bool inside = hand_depth(rig, h, body_margin, pose, model, points) > body_margin + kEscapeTolerance;
  const bool continued_lost = best.result.position_error > kLostHand;
  if (last_swivel && (continued_miss > kLandingTolerance || inside || continued_lost)) {
    SwivelPreference fresh_prefer;
    fresh_prefer.search_circle = true;
    ArmCandidate fresh = solve_arm(rig, h, state, body_margin, fresh_prefer, solver, pose, model, points);
    const bool fresh_lost = fresh.result.position_error > kLostHand;
    const bool elsewhere = std::abs(wrap_angle(*fresh.swivel - *best.swivel)) > kSameElbow;
    if ((continued_lost && !fresh_lost) ||
        (elsewhere && continued_lost == fresh_lost && fresh.score < best.score - kReadingGain &&
         (fresh.reading <= 1.0f || inside)))
      best = std::move(fresh);
  }
  if (best.result.position_error > kLostHand) {
    last_frame.restore(pose);
    float reading = 0.0f;
    const float score = arm_score(rig, h, state, body_margin, pose, model, points, reading);
    local_to_model(rig.skeleton(), pose, model);
    const float palm = glm::distance(vec3(model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f)), state.position);
    if (score < best.score - kReadingGain && hand_depth(rig, h, body_margin, pose, model, points) <= kEscapeTolerance) {
      best = ArmCandidate{last_frame, last_swivel, HandSolveResult{palm, best.result.orientation_error}};
      best.score = score, best.reading = reading;
    }
  }
  best.pose.restore(pose);
  solver.swivel = best.swivel;
  return best.result;
}

HandSolveResult pose_hand(const SigningRig& rig, Hand hand, const HandState& state, float body_margin,
                          bool search_circle, HandSolverState& solver, Pose& pose, std::vector<mat4>& model,
                          HandPoints& points) {
  apply_hand_posture(rig, hand, state.shape, pose);
  if (state.active) return solve_hand(rig, hand, state, body_margin, search_circle, solver, pose, model, points);
  for (int j : rig.hand(hand).arm.joints) pose.rotations[joint_slot(j)] = rig.rest.rotations[joint_slot(j)];
  solver.swivel.reset();
  return {};
}

}  // namespace gestura
