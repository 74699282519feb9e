#include "gestura/sign/arm_reach.hpp"

#include <algorithm>

#include "gestura/ik/swivel_arm.hpp"

namespace gestura {

namespace {

constexpr float kShellStep = 0.03f;       // metres between search shells
constexpr float kMetresPerRadian = 0.25f;  // the hand solver's trade of place for turn in space
constexpr float kPositionWeight = 4.0f;    // a clamped shoulder or elbow moves the hand
constexpr float kClearlyLess = 1e-3f;      // radians of excess that make one shift better
constexpr float kMirrorTolerance = 0.002f;  // metres (and quaternion components) of a mirrored pair

// A right and a left hand whose places and turns are each other's mirror image across x = 0 (a
// turn mirrors as (w, x, −y, −z) in the hands' frames).
bool mirrored_pair(std::span<const HandTurn> hands) {
  if (hands.size() != 2 || hands[0].hand == hands[1].hand) return false;
  const HandTurn& a = hands[0];
  const HandTurn& b = hands[1];
  const vec3 place = a.palm - vec3(-b.palm.x, b.palm.y, b.palm.z);
  const quat o = b.orientation;
  const quat mirrored(o.w, o.x, -o.y, -o.z);
  const float turn = std::min(glm::length(glm::vec4(a.orientation.w - mirrored.w, a.orientation.x - mirrored.x,
                                                    a.orientation.y - mirrored.y, a.orientation.z - mirrored.z)),
                              glm::length(glm::vec4(a.orientation.w + mirrored.w, a.orientation.x + mirrored.x,
                                                    a.orientation.y + mirrored.y, a.orientation.z + mirrored.z)));
  return glm::length(place) < kMirrorTolerance && turn < kMirrorTolerance;
}

}  // namespace

float arm_reach_excess(const SigningRig& rig, Hand hand, const vec3& palm_position, const quat& orientation) {
  const Skeleton& s = rig.skeleton();
  const HandRig& h = rig.hand(hand);
  // The shoulder as the hand solver seeds it: the rest of the body neutral, the clavicle relaxed.
  const mat4 shoulder_parent = parent_model_matrix(s, rig.neutral, h.shoulder);
  const vec3 shoulder_at = vec3(shoulder_parent * vec4(s.rest_translations[joint_slot(h.shoulder)], 1.0f));
  const quat parent_rotation = glm::normalize(glm::quat_cast(mat3(shoulder_parent)));
  const quat wrist = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), orientation}, h.rest_frame.rotation,
                                        h.rest_wrist_rotation);
  const SwivelGoal goal{palm_position - wrist * h.palm_centre_local, wrist};
  const SwivelSolution arm = solve_swivel_arm(s, h.swivel, shoulder_at, parent_rotation, goal, SwivelPreference{});
  return kPositionWeight * arm.position_excess + arm.orientation_excess;
}

ReachableShift nearest_reachable_shift(const SigningRig& rig, std::span<const HandTurn> hands, float max_shift,
                                       float settled, const std::function<bool(const vec3&)>& allowed) {
  auto excess_at = [&](const vec3& offset) {
    float e = 0.0f;
    for (const HandTurn& t : hands) e += arm_reach_excess(rig, t.hand, t.palm + offset, t.orientation);
    return e;
  };
  // The directions are visited in mirrored order for a left hand, and a shift wins only by a clear
  // margin: mirrored hands (symmetric signs) then take mirrored shifts, not whichever of two
  // equally good ones rounding favours.
  const float mirror = hands.empty() || hands.front().hand == Hand::Right ? 1.0f : -1.0f;
  // A pair that mirrors itself across the midline (a symmetric sign's hands held together) has
  // mirrored shifts of equal excess: it moves in the midline plane, or it would come out lopsided
  // (HOUSE's roof 2 cm to the right, the left fingertips across the right ones).
  const int sideways = mirrored_pair(hands) ? 0 : 1;
  ReachableShift best{vec3(0.0f), excess_at(vec3(0.0f))};
  if (best.excess < settled) return best;
  float best_score = best.excess * kMetresPerRadian;
  for (float r = kShellStep; r <= max_shift + 1e-4f; r += kShellStep) {
    ReachableShift shell_best{vec3(0.0f), 1e9f};
    for (int x = -sideways; x <= sideways; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          if (x == 0 && y == 0 && z == 0) continue;
          const vec3 offset = r * glm::normalize(vec3(mirror * static_cast<float>(x), y, z));
          const float e = excess_at(offset);
          if (e < shell_best.excess - kClearlyLess && (!allowed || allowed(offset))) shell_best = {offset, e};
        }
    if (shell_best.excess < settled) return shell_best;  // the nearest shell that makes the turn
    const float score = shell_best.excess * kMetresPerRadian + r;
    if (score < best_score) best_score = score, best = shell_best;
  }
  return best;
}

}  // namespace gestura
