#include "gestura/sign/body_repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "gestura/sign/arm_reach.hpp"
#include "gestura/sign/movement_timing.hpp"

namespace gestura {

namespace {

constexpr float kBodyClearance = 0.005f;  // planned hand surfaces stay this far off the body
constexpr float kAtBody = 0.035f;         // a hand surface this near the body is at the body (close + 1 cm)
constexpr float kPassThrough = 0.02f;     // a planned hand this deep in the body went into it, not onto it
constexpr int kKeepOutPasses = 8;
constexpr float kLongTurnWorthTrying = deg(100.0f);  // turns this large may go the long way round
constexpr float kLongTurnMargin = 0.3f;   // radians of clamped turn the long way must save
constexpr float kRiseForward = 0.2f;      // a hand rising from rest comes forward by this much of its rise…
constexpr float kMaxRiseForward = 0.15f;  // …up to this (metres)
constexpr float kDetourStep = 0.01f;       // detours round the body are searched in these steps
constexpr float kMaxDetour = 0.30f;        // … up to this far out
constexpr float kDetourTolerance = 0.002f;  // a path may pass this much nearer the body than its ends
constexpr std::size_t kDetourSamples = 12;         // the path is checked at the 11 instants between its ends
constexpr int kSurfaceSamples = 8;          // a movement is searched for where it enters the body …
constexpr int kSurfaceBisections = 10;      // … and where exactly, by bisection
// A hand out in space moves at most this far from its notated place to where the arm can turn it
// as notated (arm_reach.hpp), and no more than kMinSpaceShift farther than it is from the body
// (a hand "near" a site stays near it; neutral space, well in front of the body, is the region
// that gives way most); it keeps kSpaceClearance from the body (or what it had, if less). Within
// kTurnSettled radians of clamped joint range it is turned.
constexpr float kMaxSpaceShift = 0.24f;
constexpr float kMinSpaceShift = 0.06f;
constexpr float kSpaceClearance = kAtBody;
constexpr float kMaxSideShift = 0.10f;  // side to side: a hand keeps to its side of the body
constexpr float kTurnSettled = deg(2.0f);
// Palm centres this close belong to hands held together: one is placed relative to the other, and
// moving either alone would part them.
constexpr float kHandsTogether = 0.15f;

}  // namespace

BodyRepair::BodyRepair(const SigningRig& rig) : rig_(rig), scratch_(rig.rest) {
  // Sites on the head and trunk (not on the arms, which move; a hand "close" above the shoulder
  // top is out of its own arm's reach, and is placed in the space in front of it).
  for (const BodySite& site : rig.sites) {
    bool on_moving_arm = false;
    for (const HandRig& hr : rig.hands) {
      for (int j : hr.arm.joints) on_moving_arm |= j == site.joint;
      for (const auto& finger : hr.fingers)
        for (int j : finger) on_moving_arm |= j == site.joint;
    }
    if (!on_moving_arm) body_site_points_.push_back(site_position(site, rig.bind_model));
  }
}

float BodyRepair::clearance(std::span<const vec3> points, const vec3& at) const {
  float nearest = 1e9f;
  for (const vec3& p : points) nearest = std::min(nearest, body_signed_distance(rig_, rig_.bind_model, at + p));
  return nearest;
}

namespace {
float distance_to_segment(const vec3& p, const vec3& a, const vec3& b) {
  const vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::distance(p, a + t * ab);
}
}  // namespace

// A finger counts along its length (knuckle to tip), not at its points alone: an index held up
// with its middle close to the nose has its ends 5 cm from the nose and from the face's capsule
// (the nose stands 2.3 cm out of it), and was taken for a hand out in space and moved aside.
bool BodyRepair::near_a_body_site(std::span<const vec3> points, const vec3& at) const {
  for (const vec3& site : body_site_points_) {
    for (const vec3& p : points)
      if (glm::distance(at + p, site) < kAtBody) return true;
    if (points.size() < kHandPointCount) continue;
    for (std::size_t f = 0; f < 4; ++f)  // index .. little finger: knuckle to tip
      if (distance_to_segment(site, at + points[kKnucklePoints + f], at + points[kTipPoints + 1 + f]) < kAtBody)
        return true;
  }
  return false;
}

bool BodyRepair::at_the_body(std::span<const vec3> points, const vec3& at) const {
  return clearance(points, at) - kBodyClearance < kAtBody || near_a_body_site(points, at);
}

void BodyRepair::keep_out(Hand hand, HandState& state) {
  state.at_body = false;
  if (!state.active) return;
  const HandPoints points = planned_hand_points(rig_, hand, state, scratch_);
  float nearest = 1e9f;
  for (int pass = 0; pass < kKeepOutPasses; ++pass) {
    float deepest = 0.0f;
    vec3 outward(0, 0, 1);
    nearest = 1e9f;
    for (const vec3& p : points) {
      vec3 n;
      const float d = body_signed_distance(rig_, rig_.bind_model, state.position + p, &n) - kBodyClearance;
      nearest = std::min(nearest, d);
      if (d < deepest) deepest = d, outward = n;
    }
    if (deepest >= 0.0f) break;
    // Out is away from the body at the palm centre while that is outside: a fingertip past the
    // middle of the neck has its nearest surface at the back of it.
    vec3 palm_outward;
    if (body_signed_distance(rig_, rig_.bind_model, state.position, &palm_outward) > 0.0f) outward = palm_outward;
    state.position += outward * (-deepest);
    nearest = 0.0f;
  }
  state.at_body = nearest < kAtBody || near_a_body_site(points, state.position);
}

void BodyRepair::stop_at_surface(Hand hand, const HandState& from, HandState& to) {
  if (!from.active || !to.active) return;
  const HandPoints points = planned_hand_points(rig_, hand, to, scratch_);
  // A movement starting at the body is left to keep_out and the detour. Pushing a movement's end
  // out along the nearest surface normal instead of stopping it could carry a hand that went
  // through the head out at the back of it, or across the face to its other side.
  if (clearance(points, from.position) < kBodyClearance) return;
  auto at = [&](float t) { return glm::mix(from.position, to.position, t); };
  // The bisection runs from the last sample clear of the body (the start is) to the first one deep
  // in it: the sample just before the deep one may itself be a little inside the body already.
  float outside = 0.0f;
  for (int k = 1; k <= kSurfaceSamples; ++k) {
    float inside = static_cast<float>(k) / kSurfaceSamples;
    const float c = clearance(points, at(inside));
    if (c >= kBodyClearance) outside = inside;
    if (c > -kPassThrough) continue;
    for (int i = 0; i < kSurfaceBisections; ++i) {
      const float mid = 0.5f * (outside + inside);
      (clearance(points, at(mid)) >= kBodyClearance ? outside : inside) = mid;
    }
    to.position = at(outside);
    return;
  }
}

void BodyRepair::settle_in_space(Hand hand, HandState& state, const HandState& other, const vec3& movement) {
  keep_out(hand, state);
  if (!state.active || state.at_body) return;
  if (other.active && glm::distance(other.position, state.position) < kHandsTogether) return;
  const HandTurn turn{hand, state.position, state.orientation};
  const HandPoints points = planned_hand_points(rig_, hand, state, scratch_);
  const float room = clearance(points, state.position);
  const ReachableShift shift = nearest_reachable_shift(
      rig_, std::span(&turn, 1), std::clamp(room + kMinSpaceShift, kMinSpaceShift, kMaxSpaceShift), kTurnSettled,
      [&](const vec3& offset) {
        return std::abs(offset.x) <= kMaxSideShift && glm::dot(offset, movement) >= -0.5f * glm::dot(movement, movement) &&
               clearance(points, state.position + offset) >= std::min(room, kSpaceClearance) &&
               !at_the_body(points, state.position + offset);
      });
  if (shift.offset == vec3(0.0f)) return;
  state.position += shift.offset;
  keep_out(hand, state);
}

void BodyRepair::settle_together(ByHand<HandState>& states, const ByHand<bool>& posed) {
  const bool together = posed[Hand::Right] && posed[Hand::Left] &&
                        glm::distance(states[Hand::Right].position, states[Hand::Left].position) < kHandsTogether;
  if (!together) {
    for (Hand hand : kBothHands)
      if (posed[hand]) settle_in_space(hand, states[hand], states[other_hand(hand)]);
    return;
  }
  for (Hand hand : kBothHands) keep_out(hand, states[hand]);
  if (states[Hand::Right].at_body || states[Hand::Left].at_body) return;
  const HandTurn turns[2] = {{Hand::Right, states[Hand::Right].position, states[Hand::Right].orientation},
                             {Hand::Left, states[Hand::Left].position, states[Hand::Left].orientation}};
  const ByHand<HandPoints> points{{planned_hand_points(rig_, Hand::Right, states[Hand::Right], scratch_),
                                   planned_hand_points(rig_, Hand::Left, states[Hand::Left], scratch_)}};
  auto both_clear = [&](const vec3& offset) {
    return std::min(clearance(points[Hand::Right], states[Hand::Right].position + offset),
                    clearance(points[Hand::Left], states[Hand::Left].position + offset));
  };
  const float room = both_clear(vec3(0.0f));
  const ReachableShift shift = nearest_reachable_shift(
      rig_, turns, std::clamp(room + kMinSpaceShift, kMinSpaceShift, kMaxSpaceShift), kTurnSettled,
      [&](const vec3& offset) {
        return both_clear(offset) >= std::min(room, kSpaceClearance) &&
               !at_the_body(points[Hand::Right], states[Hand::Right].position + offset) &&
               !at_the_body(points[Hand::Left], states[Hand::Left].position + offset);
      });
  for (Hand hand : kBothHands) {
    states[hand].position += shift.offset;
    keep_out(hand, states[hand]);
  }
}

void BodyRepair::detour_around_body(Hand hand, HandSegment& seg) {
  seg.detour = vec3(0.0f);
  if (!seg.from.active && !seg.to.active) return;
  if (seg.paths.empty() && seg.from.position == seg.to.position) return;  // a hold
  const std::array<HandPoints, 2> ends{planned_hand_points(rig_, hand, seg.from, scratch_),
                                       planned_hand_points(rig_, hand, seg.to, scratch_)};
  // Hand points in the hand's own frame, so that the interpolated turn can carry them.
  std::array<HandPoints, 2> local;
  for (std::size_t e = 0; e < 2; ++e) {
    const quat inv = glm::inverse(e == 0 ? seg.from.orientation : seg.to.orientation);
    for (std::size_t i = 0; i < kHandPointCount; ++i) local[e][i] = inv * ends[e][i];
  }
  struct Instant {
    vec3 position;
    HandPoints points;
    float bump;
  };
  std::array<Instant, kDetourSamples - 1> path;
  one_segment_.segments.assign(1, seg);
  const float span = seg.end - seg.start;
  for (std::size_t k = 1; k < kDetourSamples; ++k) {
    const float u = static_cast<float>(k) / kDetourSamples;
    const float progress = seg.linear_blend ? u : profile_progress(VelocityProfile::MinimumJerk, u);
    const HandState at = sample_hand(one_segment_, seg.start + u * span);
    Instant& in = path[k - 1];
    in.position = at.position;
    for (std::size_t i = 0; i < kHandPointCount; ++i) in.points[i] = at.orientation * glm::mix(local[0][i], local[1][i], progress);
    in.bump = std::sin(kPi * progress);
  }
  const float required =
      std::min({clearance(ends[0], seg.from.position), clearance(ends[1], seg.to.position), kBodyClearance}) -
      kDetourTolerance;
  auto worst_clearance = [&](const vec3& detour) {
    float worst = 1e9f;
    for (const Instant& in : path)
      worst = std::min(worst, clearance(in.points, in.position + detour * in.bump));
    return worst;
  };
  if (worst_clearance(vec3(0.0f)) >= required) return;
  // The first direction that works, smallest detour first: forward; forward and out to the hand's
  // side; forward and up; out along the body's normal at either end.
  const float side = hand == Hand::Right ? -1.0f : 1.0f;
  vec3 from_normal(0, 0, 1), to_normal(0, 0, 1);
  body_signed_distance(rig_, rig_.bind_model, seg.from.position, &from_normal);
  body_signed_distance(rig_, rig_.bind_model, seg.to.position, &to_normal);
  const vec3 directions[] = {vec3(0, 0, 1), glm::normalize(vec3(side, 0, 1)), glm::normalize(vec3(0, 1, 1)), from_normal,
                             to_normal};
  vec3 best(0.0f);
  float best_clearance = -1e9f;
  for (float amount = kDetourStep; amount <= kMaxDetour + 1e-4f; amount += kDetourStep)
    for (const vec3& d : directions) {
      const float c = worst_clearance(d * amount);
      if (c >= required) {
        seg.detour = d * amount;
        return;
      }
      if (c > best_clearance) best_clearance = c, best = d * amount;
    }
  seg.detour = best;  // nothing clears it: the detour that comes closest
}

void BodyRepair::choose_turn_way(Hand hand, HandSegment& seg) {
  if (!seg.from.active && !seg.to.active) return;
  const quat a = seg.from.orientation, b = seg.to.orientation;
  if (std::abs(glm::dot(a, b)) > std::cos(0.5f * kLongTurnWorthTrying)) return;  // a small turn
  float excess[2] = {0.0f, 0.0f};
  for (int way = 0; way < 2; ++way)
    for (float u : {0.25f, 0.5f, 0.75f}) {
      const vec3 at = glm::mix(seg.from.position, seg.to.position, u) + seg.detour * std::sin(kPi * u);
      excess[way] += arm_reach_excess(rig_, hand, at, blend_turn(a, b, u, way == 1));
    }
  seg.long_turn = excess[1] + kLongTurnMargin < excess[0];
}

void BodyRepair::come_up_in_front(HandSegment& seg) {
  if (seg.from.active == seg.to.active) return;
  const HandState& signing = seg.to.active ? seg.to : seg.from;
  if (signing.position.z < 0.0f) return;  // a place behind the shoulders (the back) is reached round the side
  const float rise = std::abs(seg.to.position.y - seg.from.position.y);
  seg.detour.z = std::max(seg.detour.z, std::min(kRiseForward * rise, kMaxRiseForward));
}

void BodyRepair::repair_end(Hand hand, HandSegment& seg) {
  stop_at_surface(hand, seg.from, seg.to);
  keep_out(hand, seg.to);
}

void BodyRepair::repair_way(Hand hand, HandSegment& seg) {
  detour_around_body(hand, seg);
  come_up_in_front(seg);
  choose_turn_way(hand, seg);
  if (!seg.long_turn) return;
  const vec3 first = seg.detour;
  detour_around_body(hand, seg);
  if (glm::length(seg.detour) < glm::length(first)) seg.detour = first;  // never less room than judged with
  come_up_in_front(seg);
}

}  // namespace gestura
