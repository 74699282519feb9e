#include "gestura/sign/sign_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/arm_reach.hpp"
#include "gestura/sign/hand_part.hpp"
#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/sign_limits.hpp"

namespace gestura {

namespace {

using sign::Element;
using sign::ElementKind;
using sign::MotionKind;

// Distances from a site to the hand's nearest surface, by proximity (metres). Without a contact
// symbol HamNoSys places the hand near the site, in the space just in front of it.
constexpr float kTouchGap = 0.0f;
constexpr float kCloseGap = 0.025f;
constexpr float kNearGap = 0.07f;
constexpr float kFarGap = 0.25f;
constexpr float kBesideOffset = 0.07f;  // hamlrbeside: beside the site, on the hand's side
constexpr float kFaceSideOffset = 0.045f;  // hamlrat at a central head site: its side (temple, mouth corner)
constexpr float kTrunkSideOffset = 0.09f;  // hamlrat at a central trunk site: its side (below the nipple)
constexpr float kBodyClearance = 0.005f;  // planned hand surfaces stay this far off the body
constexpr float kAtBody = kCloseGap + 0.01f;  // a hand surface this near the body is at the body
constexpr float kPassThrough = 0.02f;  // a planned hand this deep in the body went into it, not onto it
const vec3 kBaseHandOffset(-0.06f, -0.02f, -0.03f);  // a base hand waits this far in from the neutral space
constexpr float kLongTurnWorthTrying = deg(100.0f);  // turns this large may go the long way round
constexpr float kLongTurnMargin = 0.3f;   // radians of clamped turn the long way must save
constexpr float kRiseForward = 0.2f;      // a hand rising from rest comes forward by this much of its rise…
constexpr float kMaxRiseForward = 0.15f;  // …up to this (metres)
constexpr float kDetourStep = 0.01f;       // detours around the body are searched in these steps
constexpr float kMaxDetour = 0.30f;        // … up to this far out
constexpr float kDetourTolerance = 0.002f;  // a path may pass this much nearer the body than its ends
// A hand out in space moves at most this far from its notated place to where the arm can turn it
// as notated (arm_reach.hpp), and no more than `kMinSpaceShift` farther than it is from the body
// (a hand "near" a site stays near it; neutral space, well in front of the body, is the region
// that gives way most); it keeps `kSpaceClearance` from the body (or what it had, if less). Within `kTurnSettled` radians of clamped joint range it
// is turned.
constexpr float kMaxSpaceShift = 0.24f;
constexpr float kMinSpaceShift = 0.06f;
constexpr float kSpaceClearance = kAtBody;
constexpr float kMaxSideShift = 0.10f;  // side to side: a hand keeps to its side of the body
constexpr float kTurnSettled = deg(2.0f);
// Palm centres this close belong to hands held together: one is placed relative to the other,
// and moving either alone would part them.
constexpr float kHandsTogether = 0.15f;

// Durations of actions without a path (seconds, normal speed).
constexpr float kReplacementTime = 0.35f;
constexpr float kOscillationTime = 0.6f;
constexpr float kFingerPlayTime = 0.7f;
constexpr float kHoldTime = 0.3f;
constexpr float kContactTime = 0.25f;

MovementSize size_of(sign::Size s) {
  return s == sign::Size::small ? MovementSize::Small : s == sign::Size::large ? MovementSize::Large : MovementSize::Normal;
}
MovementSpeed speed_of(const sign::Manner& m) {
  return m.fast ? MovementSpeed::Fast : m.slow ? MovementSpeed::Slow : MovementSpeed::Normal;
}
Direction direction_of(sign::Direction d) { return static_cast<Direction>(d); }
vec3 mirror_x(vec3 v) { return vec3(-v.x, v.y, v.z); }

// The site's point and outward normal on the body, for the hand signing there.
struct SitePlace {
  vec3 point{0.0f};
  vec3 normal{0, 0, 1};
  bool found = false;
};

}  // namespace

HandPosture hand_posture_of(const sign::HandshapeForm& form) {
  ThumbModifier thumb = ThumbModifier::Default;
  switch (form.thumb) {
    case sign::ThumbPosition::out: thumb = ThumbModifier::Out; break;
    case sign::ThumbPosition::across: thumb = ThumbModifier::Across; break;
    case sign::ThumbPosition::open: thumb = ThumbModifier::Opposed; break;
    default: break;
  }
  std::optional<FingerBending> bending;
  if (form.bending) bending = static_cast<FingerBending>(*form.bending);
  HandPosture p = make_handshape(static_cast<BasicHandshape>(form.basic), thumb, bending);
  for (const sign::FingerModifier& m : form.finger_modifiers)
    if (m.bending && !m.fingers.empty()) apply_bending(p, static_cast<FingerSet>(m.fingers.bits & kAllFourFingers), static_cast<FingerBending>(*m.bending));
  return p;
}

HandPosture hand_posture_of(const sign::Handshape& handshape) {
  const HandPosture a = hand_posture_of(handshape.form);
  return handshape.between ? mix(a, hand_posture_of(*handshape.between), 0.5f) : a;
}

HandState rest_hand_state(const SigningRig& rig, Hand hand) {
  const HandRig& h = rig.hand(hand);
  HandState s;
  const mat4& w = rig.bind_model[static_cast<std::size_t>(h.wrist)];
  s.position = vec3(w * vec4(h.palm_centre_local, 1.0f));
  s.orientation = h.rest_frame.rotation;
  s.shape = make_handshape(BasicHandshape::Flat);
  for (auto& f : s.shape.fingers) f = FingerFlexion{deg(8), deg(10), deg(5)};  // relaxed, not rigid
  s.active = false;
  return s;
}

namespace {

class Planner {
 public:
  Planner(const SigningRig& rig, const PlanOptions& options) : rig_(rig), options_(options) {
    scratch_ = rig.rest;
    // Sites on the head and trunk (not on the arms, which move; a hand "close" above the
    // shoulder top is out of its own arm's reach, and is placed in the space in front of it).
    for (const BodySite& site : rig.sites) {
      bool on_moving_arm = false;
      for (const HandRig& hr : rig.hands)
        for (int j : hr.arm.joints)
          if (j == site.joint) on_moving_arm = true;
      for (const HandRig& hr : rig.hands)
        for (const auto& finger : hr.fingers)
          for (int j : finger)
            if (j == site.joint) on_moving_arm = true;
      if (!on_moving_arm) body_site_points_.push_back(site_position(site, rig.bind_model));
    }
    for (int h = 0; h < 2; ++h) state_[h] = rest_hand_state(rig, hand_of(h));
  }

  SignPlan run(const sign::HamSign& sign) {
    for (std::size_t i = 0; i < sign.segments.size(); ++i) perform_segment(sign.segments[i], i == 0);
    // Final hold, then back to rest.
    hold_both(scaled(options_.final_hold));
    plan_.sign_end = now();
    if (options_.to_rest)
      for (int h = 0; h < 2; ++h) {
        const HandState rest = rest_hand_state(rig_, hand_of(h));
        move_to(h, rest, transition_time(state_[h], rest));
      }
    sync();
    plan_.right = std::move(timeline_[0]);
    plan_.left = std::move(timeline_[1]);
    return plan_;
  }

 private:
  static Hand hand_of(int h) { return h == 0 ? Hand::Right : Hand::Left; }
  float now() const { return std::max(clock_[0], clock_[1]); }
  float scaled(float seconds) const { return seconds / options_.speed; }

  // ---- timeline primitives ------------------------------------------------------------------

  // `seg` comes with its duration in [start, end] (start usually 0); it is placed at the hand's clock.
  // Moves a planned state out of the body: notation may ask for a movement towards the body from a
  // place already close to it; a signer stops at the surface.
  // Also marks whether the hand ends up at the body (HandState::at_body).
  void keep_out(int h, HandState& s) {
    s.at_body = false;
    if (!s.active) return;
    const auto pts = hand_points(h, s);
    float nearest = 1e9f;
    for (int pass = 0; pass < 3; ++pass) {
      float deepest = 0.0f;
      vec3 outward(0, 0, 1);
      nearest = 1e9f;
      for (const vec3& p : pts) {
        vec3 n;
        const float d = body_signed_distance(rig_, rig_.bind_model, s.position + p, &n) - kBodyClearance;
        nearest = std::min(nearest, d);
        if (d < deepest) deepest = d, outward = n;
      }
      if (deepest >= 0.0f) break;
      // Out is away from the body at the palm centre while that is outside: a fingertip past
      // the middle of the neck has its nearest surface at the back of it.
      vec3 palm_outward;
      if (body_signed_distance(rig_, rig_.bind_model, s.position, &palm_outward) > 0.0f) outward = palm_outward;
      s.position += outward * (-deepest);
      nearest = 0.0f;
    }
    s.at_body = nearest < kAtBody || near_a_body_site(pts, s.position);
  }

  // The collision body is a few capsules and misses what stands out of them (the chin, nose,
  // lips): a hand this near one of the body's sites is at the body too. A finger counts along its
  // length (knuckle to tip), not at its ends alone: an index held up with its middle close to the
  // nose has both ends 5 cm from the nose and from the face's capsule (the nose stands 2.3 cm out
  // of it), and was taken for a hand out in space and moved 4 cm aside.
  bool near_a_body_site(const std::array<vec3, 11>& pts, const vec3& at) const {
    for (const vec3& site : body_site_points_) {
      for (const vec3& p : pts)
        if (glm::distance(at + p, site) < kAtBody) return true;
      for (std::size_t f = 0; f < 4; ++f)  // hand_points: tips of thumb..pinky at 2..6, knuckles of index..pinky at 7..10
        if (distance_to_segment(site, at + pts[7 + f], at + pts[3 + f]) < kAtBody) return true;
    }
    return false;
  }
  static float distance_to_segment(const vec3& p, const vec3& a, const vec3& b) {
    const vec3 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + t * ab);
  }

  // How far the hand's nearest point (hand_points) is from the body with its palm centre at `at`.
  float clearance(const std::array<vec3, 11>& pts, const vec3& at) const {
    float nearest = 1e9f;
    for (const vec3& p : pts) nearest = std::min(nearest, body_signed_distance(rig_, rig_.bind_model, at + p));
    return nearest;
  }

  // A place out in the signing space is a region: the hand takes the place in it, nearest the
  // notated one, where the arm can make the notated turn (fingers straight up raise the hand, a
  // palm turned in brings it closer), as a signer's does, rather than twisting at its limits.
  // A hand held to the other one stays where it is (settle_together moves such pairs). A hand
  // that ends a `movement` there does not give way against it by more than half of it (the
  // movement stays a movement that way).
  void settle_in_space(int h, HandState& s, const HandState& other, const vec3& movement = vec3(0.0f)) {
    keep_out(h, s);
    if (!s.active || s.at_body) return;
    if (other.active && glm::distance(other.position, s.position) < kHandsTogether) return;
    const HandTurn turn{hand_of(h), s.position, s.orientation};
    const auto pts = hand_points(h, s);
    const float room = clearance(pts, s.position);
    const ReachableShift shift = nearest_reachable_shift(
        rig_, std::span(&turn, 1), std::clamp(room + kMinSpaceShift, kMinSpaceShift, kMaxSpaceShift), kTurnSettled,
        [&](const vec3& offset) {
          return std::abs(offset.x) <= kMaxSideShift && glm::dot(offset, movement) >= -0.5f * glm::dot(movement, movement) &&
                 clearance(pts, s.position + offset) >= std::min(room, kSpaceClearance);
        });
    if (shift.offset == vec3(0.0f)) return;
    s.position += shift.offset;
    keep_out(h, s);
  }

  // The same for both hands of a posture; hands held together out in space move together.
  // Only the hands the posture places (`posed`) move.
  void settle_together(HandState (&target)[2], const bool (&posed)[2]) {
    const bool together = posed[0] && posed[1] && glm::distance(target[0].position, target[1].position) < kHandsTogether;
    if (!together) {
      for (int h = 0; h < 2; ++h)
        if (posed[h]) settle_in_space(h, target[h], target[1 - h]);
      return;
    }
    for (int h = 0; h < 2; ++h) keep_out(h, target[h]);
    if (target[0].at_body || target[1].at_body) return;
    const HandTurn turns[2] = {{Hand::Right, target[0].position, target[0].orientation},
                               {Hand::Left, target[1].position, target[1].orientation}};
    const std::array<std::array<vec3, 11>, 2> pts = {hand_points(0, target[0]), hand_points(1, target[1])};
    const float room = std::min(clearance(pts[0], target[0].position), clearance(pts[1], target[1].position));
    const ReachableShift shift = nearest_reachable_shift(
        rig_, turns, std::clamp(room + kMinSpaceShift, kMinSpaceShift, kMaxSpaceShift), kTurnSettled, [&](const vec3& offset) {
          return std::min(clearance(pts[0], target[0].position + offset), clearance(pts[1], target[1].position + offset)) >=
                 std::min(room, kSpaceClearance);
        });
    for (int h = 0; h < 2; ++h) {
      target[h].position += shift.offset;
      keep_out(h, target[h]);
    }
  }

  // A movement that would take the hand deep into the body (notation asking for a movement
  // towards or across the body from a place already close to it) stops where it meets the
  // surface, on the side it came from. Pushing its end out along the nearest surface normal
  // instead could carry a hand that went through the head out at the back of it, or across the
  // face to its other side.
  void stop_at_surface(int h, const HandState& from, HandState& to) {
    if (!from.active || !to.active) return;
    const auto pts = hand_points(h, to);
    if (clearance(pts, from.position) < kBodyClearance) return;  // starts at the body: keep_out and the detour handle it
    auto at = [&](float t) { return glm::mix(from.position, to.position, t); };
    constexpr int kSamples = 8;
    for (int k = 1; k <= kSamples; ++k) {
      float inside = static_cast<float>(k) / kSamples;
      if (clearance(pts, at(inside)) > -kPassThrough) continue;
      float outside = static_cast<float>(k - 1) / kSamples;
      for (int i = 0; i < 10; ++i) {
        const float mid = 0.5f * (outside + inside);
        (clearance(pts, at(mid)) >= kBodyClearance ? outside : inside) = mid;
      }
      to.position = at(outside);
      return;
    }
  }

  // A path between two places that would take the hand through the body on the way (from the
  // chin down to rest, from rest up past the head to its top, from one cheek to the other) bows
  // out around it, as a signer's hand does: the smallest detour, in the first direction that
  // works (forward; forward and out to the hand's side; forward and up; out along the body's
  // normal at either end), that keeps the hand along the way as far off the body as it is at
  // either end. Checked at 11 instants with the hand's interpolated turn and shape.
  void detour_around_body(int h, HandSegment& seg) {
    seg.detour = vec3(0.0f);
    if (!seg.from.active && !seg.to.active) return;
    if (seg.paths.empty() && seg.from.position == seg.to.position) return;  // a hold
    const std::array<vec3, 11> ends[2] = {hand_points(h, seg.from), hand_points(h, seg.to)};
    // Hand points in the hand's own frame, so they can be carried by the interpolated turn.
    std::array<vec3, 11> local[2];
    for (int e = 0; e < 2; ++e) {
      const quat inv = glm::inverse(e == 0 ? seg.from.orientation : seg.to.orientation);
      for (std::size_t i = 0; i < 11; ++i) local[e][i] = inv * ends[e][i];
    }
    constexpr int kSamples = 12;
    struct Instant {
      vec3 position;
      std::array<vec3, 11> points;
      float bump;
    };
    std::array<Instant, kSamples - 1> path;
    detour_timeline_.segments.assign(1, seg);
    const float span = seg.end - seg.start;
    for (int k = 1; k < kSamples; ++k) {
      const float u = static_cast<float>(k) / kSamples;
      const float progress = seg.linear_blend ? u : profile_progress(VelocityProfile::MinimumJerk, u);
      const HandState at = sample_hand(detour_timeline_, seg.start + u * span);
      Instant& in = path[static_cast<std::size_t>(k - 1)];
      in.position = at.position;
      for (std::size_t i = 0; i < 11; ++i) in.points[i] = at.orientation * glm::mix(local[0][i], local[1][i], progress);
      in.bump = std::sin(kPi * progress);
    }
    const float required = std::min({clearance(ends[0], seg.from.position), clearance(ends[1], seg.to.position),
                                     kBodyClearance}) - kDetourTolerance;
    auto worst_clearance = [&](const vec3& detour) {
      float worst = 1e9f;
      for (const Instant& in : path) {
        const vec3 at = in.position + detour * in.bump;
        for (const vec3& p : in.points) worst = std::min(worst, body_signed_distance(rig_, rig_.bind_model, at + p));
      }
      return worst;
    };
    if (worst_clearance(vec3(0.0f)) >= required) return;
    const float side = h == 0 ? -1.0f : 1.0f;  // the right hand's side is −x
    vec3 from_normal(0, 0, 1), to_normal(0, 0, 1);
    body_signed_distance(rig_, rig_.bind_model, seg.from.position, &from_normal);
    body_signed_distance(rig_, rig_.bind_model, seg.to.position, &to_normal);
    const vec3 directions[] = {vec3(0, 0, 1), glm::normalize(vec3(side, 0, 1)), glm::normalize(vec3(0, 1, 1)),
                               from_normal, to_normal};
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

  // A turn is taken the short way round unless that way passes a forearm twist or wrist bend the
  // arm cannot make and the long way does not: from the resting hand (palm in, fingers down) to
  // fingers up with the palm forward, the short way twists the forearm far past its range mid-way
  // and the arm would swing about to follow it.
  void choose_turn_way(int h, HandSegment& seg) {
    if (!seg.from.active && !seg.to.active) return;
    const quat a = seg.from.orientation, b = seg.to.orientation;
    if (std::abs(glm::dot(a, b)) > std::cos(0.5f * kLongTurnWorthTrying)) return;  // a small turn
    float excess[2] = {0.0f, 0.0f};
    for (int way = 0; way < 2; ++way)
      for (float u : {0.25f, 0.5f, 0.75f}) {
        const vec3 at = glm::mix(seg.from.position, seg.to.position, u) + seg.detour * std::sin(kPi * u);
        excess[way] += arm_reach_excess(rig_, hand_of(h), at, blend_turn(a, b, u, way == 1));
      }
    seg.long_turn = excess[1] + kLongTurnMargin < excess[0];
  }

  // A hand rising from rest (or sinking back to it) travels in front of the body, as a signer's
  // does, not straight up its side: the straight line from the hip to the face runs past the
  // armpit, where the arm can only follow with the elbow thrown back.
  static void come_up_in_front(HandSegment& seg) {
    if (seg.from.active == seg.to.active) return;
    const HandState& signing = seg.to.active ? seg.to : seg.from;
    if (signing.position.z < 0.0f) return;  // a place behind the shoulders (the back) is reached round the side
    const float rise = std::abs(seg.to.position.y - seg.from.position.y);
    seg.detour.z = std::max(seg.detour.z, std::min(kRiseForward * rise, kMaxRiseForward));
  }

  void add_segment(int h, HandSegment seg) {
    stop_at_surface(h, seg.from, seg.to);
    keep_out(h, seg.to);
    // The way to turn is judged where the detour takes the arm; a hand turning the long way has
    // its detour checked again with that turn (its fingers sweep elsewhere).
    detour_around_body(h, seg);
    come_up_in_front(seg);
    choose_turn_way(h, seg);
    if (seg.long_turn) {
      const vec3 first = seg.detour;
      detour_around_body(h, seg);
      if (glm::length(seg.detour) < glm::length(first)) seg.detour = first;  // never less room than judged with
      come_up_in_front(seg);
    }
    const float duration = std::max(seg.end - seg.start, 1e-3f);
    seg.start = clock_[h];
    seg.end = clock_[h] + duration;
    clock_[h] = seg.end;
    state_[h] = seg.to;
    timeline_[h].segments.push_back(std::move(seg));
  }
  void move_to(int h, const HandState& to, float duration) {
    HandSegment seg;
    seg.from = state_[h];
    seg.to = to;
    seg.end = duration;
    add_segment(h, seg);
  }
  void hold(int h, float duration) { move_to(h, state_[h], duration); }
  void hold_both(float duration) {
    sync();
    for (int h = 0; h < 2; ++h) hold(h, duration);
  }
  void sync() {
    const float t = now();
    for (int h = 0; h < 2; ++h)
      if (clock_[h] < t - 1e-6f) hold(h, t - clock_[h]);
  }
  float transition_time(const HandState& a, const HandState& b) const {
    return scaled(transition_duration(glm::distance(a.position, b.position)) + 0.1f);
  }

  // ---- posture --------------------------------------------------------------------------------

  // Which hands an action written for "the hand" drives, and whether the non-dominant copy mirrors.
  bool mirrored() const { return symmetry_.kind == sign::SymmetryKind::mirrored_lr; }
  bool both_hands() const { return symmetry_.kind != sign::SymmetryKind::none; }

  Direction hand_direction(int h, sign::Direction d, bool copy) const {
    const Direction dir = direction_of(d);
    return copy && mirrored() && h == 1 ? mirror_left_right(dir) : dir;
  }

  quat orientation_of(int h, const sign::Orientation& o, const quat& current, bool copy) const {
    const Hand hand = hand_of(h);
    const HandFrame now_frame = hand_frame_from_vectors(current * vec3(0, 1, 0), current * vec3(0, 0, 1), hand);
    vec3 finger = now_frame.finger;
    if (o.extended_finger) finger = direction_vector(hand_direction(h, *o.extended_finger, copy));
    if (o.extended_finger && o.extended_finger_between)
      finger = glm::normalize(finger + direction_vector(hand_direction(h, *o.extended_finger_between, copy)));
    vec3 palm = now_frame.palm;
    if (o.palm) {
      const Direction pd = hand_direction(h, *o.palm, copy);
      const auto frontal = palm_orientation_of(pd);
      palm = frontal ? palm_normal(finger, *frontal) : direction_vector(pd);
      if (o.palm_between) palm = glm::normalize(palm + direction_vector(hand_direction(h, *o.palm_between, copy)));
    }
    // Keep the palm perpendicular to the fingers.
    palm = palm - glm::dot(palm, finger) * finger;
    if (glm::length(palm) < 1e-3f) palm = glm::cross(finger, vec3(0, 1, 0.3f));
    return hand_frame_from_vectors(finger, glm::normalize(palm), hand).rotation;
  }

  // Geometry of the hand (palm surfaces, fingertips, knuckles) relative to its palm centre in model
  // space, for a state's shape and orientation.
  std::array<vec3, 11> hand_points(int h, const HandState& s) {
    const HandRig& hr = rig_.hand(hand_of(h));
    apply_hand_posture(rig_, hand_of(h), s.shape, scratch_);
    clamp_to_limits(rig_.skeleton(), scratch_);  // as the performer will
    const HandGeometry g = hand_geometry(rig_, hand_of(h), scratch_);
    const quat wrist = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), s.orientation}, hr.rest_frame.rotation,
                                          hr.rest_wrist_rotation);
    std::array<vec3, 11> pts;
    const vec3 palm_n = s.orientation * vec3(0, 0, 1);
    pts[0] = palm_n * hr.palm_half_thickness;
    pts[1] = -palm_n * hr.palm_half_thickness;
    for (int i = 0; i < 5; ++i) pts[static_cast<std::size_t>(2 + i)] = wrist * (g.tips[static_cast<std::size_t>(i)] - g.palm_centre);
    for (int i = 0; i < 4; ++i) pts[static_cast<std::size_t>(7 + i)] = wrist * (g.knuckles[static_cast<std::size_t>(i)] - g.palm_centre);
    return pts;
  }

  // Palm-centre position that puts the part of the hand facing the site `gap` metres out from the
  // site point: the hand points nearest the body along the site's normal (averaged when several
  // are about as near, like a flat palm) land on the site.
  vec3 place_at(int h, const HandState& s, const SitePlace& site, float gap) {
    const auto pts = hand_points(h, s);
    float nearest = 1e9f;
    for (const vec3& p : pts) nearest = std::min(nearest, glm::dot(p, site.normal));
    vec3 contact(0.0f);
    int count = 0;
    for (const vec3& p : pts)
      if (glm::dot(p, site.normal) < nearest + 0.004f) contact += p, ++count;
    contact /= static_cast<float>(count);
    contact -= site.normal * (glm::dot(contact, site.normal) - nearest);  // on the nearest plane
    return site.point + site.normal * gap - contact;
  }

  // Palm-centre position that puts a named part of the hand (HamNoSys: "hamchin hamseqbegin
  // hamfingertip hamseqend", the fingertips at the chin) `gap` metres out from the site point.
  // Falls back to place_at for a part that is not on the hand.
  vec3 place_part_at(int h, const HandState& s, const SitePlace& site, float gap, const sign::SitePoint& part) {
    const HandRig& hr = rig_.hand(hand_of(h));
    apply_hand_posture(rig_, hand_of(h), s.shape, scratch_);
    clamp_to_limits(rig_.skeleton(), scratch_);
    const auto on_hand = hand_part_site(rig_, hand_of(h), scratch_, s.shape, part);
    if (!on_hand) return place_at(h, s, site, gap);
    const quat wrist = wrist_rotation_for(HandFrame{vec3(), vec3(), vec3(), s.orientation}, hr.rest_frame.rotation,
                                          hr.rest_wrist_rotation);
    return site.point + site.normal * gap - wrist * (on_hand->point - hr.palm_centre_local);
  }

  // The hand part the last location named for hand `h`, if any, else the nearest part.
  vec3 place_at_last_site(int h, const HandState& s, float gap) {
    return last_part_[h] ? place_part_at(h, s, last_site_[h], gap, *last_part_[h]) : place_at(h, s, last_site_[h], gap);
  }

  SitePlace body_site(const std::string& name) const {
    SitePlace out;
    if (const BodySite* s = find_site(rig_.sites, name)) {
      out.point = site_position(*s, rig_.bind_model);
      out.normal = site_normal(*s, rig_.bind_model);
      // The hand signs in the space in front of (or beside) a body site, not along a surface
      // normal that may point down (the chin) or up: approach horizontally where the site allows.
      const vec3 flat(out.normal.x, 0.0f, out.normal.z);
      if (glm::length(flat) > 0.3f) out.normal = glm::normalize(flat);
      out.found = true;
    }
    return out;
  }

  // Neutral signing space: in front of the lower chest, on the hand's own side.
  SitePlace neutral_space(int h) const {
    SitePlace chest = body_site("chest");
    const float side = hand_of(h) == Hand::Right ? -1.0f : 1.0f;
    const vec3 base = chest.found ? chest.point : vec3(0, 1.25f, 0.12f);
    SitePlace out;
    out.point = base + vec3(side * (both_hands() ? 0.13f : 0.08f), -0.07f, 0.25f);
    out.normal = vec3(0, 0, 1);
    out.found = true;
    return out;
  }

  // A place on the other hand (hand constellations and hand sites).
  SitePlace other_hand_site(int h, sign::Site site) const {
    const int o = 1 - h;
    const HandState& other = state_[o];
    const vec3 finger = other.orientation * vec3(0, 1, 0), palm = other.orientation * vec3(0, 0, 1);
    const vec3 thumb = hand_frame_from_vectors(finger, palm, hand_of(o)).thumb_side;
    const float t = rig_.hand(hand_of(o)).palm_half_thickness;
    SitePlace out;
    out.found = true;
    switch (site) {
      case sign::Site::palm: out.point = other.position + palm * t; out.normal = palm; break;
      case sign::Site::thumb_ball: out.point = other.position + palm * t - finger * 0.03f + thumb * 0.02f; out.normal = palm; break;
      case sign::Site::hand_back: out.point = other.position - palm * t; out.normal = -palm; break;
      case sign::Site::thumb_side: out.point = other.position + thumb * 0.045f; out.normal = thumb; break;
      case sign::Site::pinky_side: out.point = other.position - thumb * 0.045f; out.normal = -thumb; break;
      case sign::Site::fingers: out.point = other.position + finger * 0.11f; out.normal = palm; break;
      case sign::Site::wrist_back: out.point = other.position - finger * 0.07f - palm * t; out.normal = -palm; break;
      case sign::Site::wrist_pulse: out.point = other.position - finger * 0.07f + palm * t; out.normal = palm; break;
      case sign::Site::lower_arm: out.point = other.position - finger * 0.17f - palm * 0.02f; out.normal = -palm; break;
      case sign::Site::elbow: case sign::Site::elbow_inside: out.point = other.position - finger * 0.30f; out.normal = -palm; break;
      case sign::Site::upper_arm: out.point = other.position - finger * 0.42f; out.normal = -palm; break;
      default: out.found = false;
    }
    return out;
  }

  SitePlace site_place(int h, sign::Site site, sign::Side side, bool on_other_hand) {
    using S = sign::Site;
    const sign::SiteRegion region = sign::site_region(site);
    if (site == S::neutral_space) return neutral_space(h);
    if (on_other_hand || region == sign::SiteRegion::hand || region == sign::SiteRegion::finger ||
        ((region == sign::SiteRegion::arm) && state_[1 - h].active)) {
      SitePlace p = other_hand_site(h, site);
      if (p.found) return p;
    }
    const std::string own = hand_of(h) == Hand::Right ? "r_" : "l_";
    const std::string other = hand_of(h) == Hand::Right ? "l_" : "r_";
    std::string name;
    switch (site) {
      case S::head: case S::forehead: name = "forehead"; break;
      case S::head_top: name = "head_top"; break;
      case S::eyebrows: name = "eyebrows"; break;
      case S::eyes: name = side == sign::Side::centre ? "eyebrows" : own + "eye"; break;
      case S::nose: case S::nostrils: name = "nose"; break;
      case S::ear: case S::earlobe: name = own + "ear"; break;
      case S::cheek: name = own + "cheek"; break;
      case S::lips: case S::tongue: case S::teeth: name = "lips"; break;
      case S::chin: name = "chin"; break;
      case S::under_chin: name = "under_chin"; break;
      case S::neck: name = "neck"; break;
      case S::shoulder_top: name = own + "shoulder_top"; break;
      case S::shoulders: name = "upper_chest"; break;
      case S::chest: name = "chest"; break;
      case S::stomach: name = "stomach"; break;
      case S::below_stomach: name = "belly"; break;
      // Arm sites are on the other arm, as signers use them.
      case S::upper_arm: name = other + "upper_arm"; break;
      case S::elbow: case S::elbow_inside: name = other + "elbow"; break;
      case S::lower_arm: case S::wrist_pulse: name = other + "forearm"; break;
      case S::wrist_back: name = other + "wrist_back"; break;
      default: name = "chest"; break;
    }
    SitePlace p = body_site(name);
    if (!p.found) p = neutral_space(h);
    if (site == S::earlobe) p.point.y -= 0.02f;
    if (site == S::eyes && side == sign::Side::centre) p.point.y -= 0.02f;
    const float outward = hand_of(h) == Hand::Right ? -1.0f : 1.0f;
    if (side == sign::Side::beside) p.point.x += outward * kBesideOffset;
    // hamlrat at a site the body has once, in the middle (forehead, chin, chest): that site's
    // own side, toward the hand (the temple side of the forehead, the right of the chest). Sites
    // the body has twice (cheek, eye, ear, shoulder) were named with the hand's side above.
    if (side == sign::Side::dominant_side && name.rfind(own, 0) != 0)
      p.point.x += outward * (region == sign::SiteRegion::trunk ? kTrunkSideOffset : kFaceSideOffset);
    return p;
  }

  static float gap_of(std::optional<sign::Proximity> p, sign::SiteRegion region) {
    if (!p) return region == sign::SiteRegion::trunk ? kNearGap + 0.05f : kNearGap;
    switch (*p) {
      case sign::Proximity::touch: case sign::Proximity::brushing: case sign::Proximity::interlocked:
      case sign::Proximity::crossed: return kTouchGap;
      case sign::Proximity::close: return kCloseGap;
      case sign::Proximity::far: return kFarGap;
      case sign::Proximity::behind: return kCloseGap;
    }
    return kNearGap;
  }

  // A location an action moves the hand to. One on the other hand or forearm while that hand
  // rests at the hip is not a place to go (the hand would dive to the hip). The parser reads a
  // hand part written after a place as the moving hand's; what is left (a finger named after a
  // handshape replacement, "hamfist, hammiddlefinger, hambetween, hamringfinger") describes the
  // moving hand too, so the hand stays where it is.
  vec3 action_location(int h, const sign::Location& loc, const HandState& s, bool copy) {
    const sign::SiteRegion region = sign::site_region(loc.site);
    const bool on_other_forearm =
        loc.site == sign::Site::lower_arm || loc.site == sign::Site::wrist_back || loc.site == sign::Site::wrist_pulse;
    const bool on_other_hand = loc.nondominant_hand || region == sign::SiteRegion::hand ||
                               region == sign::SiteRegion::finger || on_other_forearm;
    if (on_other_hand && !state_[1 - h].active) return s.position;
    return location_position(h, loc, s, copy);
  }

  vec3 location_position(int h, const sign::Location& loc, const HandState& s, bool copy) {
    sign::Side side = loc.side;
    const bool on_other = loc.nondominant_hand;
    SitePlace p = site_place(h, loc.site, side, on_other);
    if (loc.between) {
      const SitePlace q = site_place(h, loc.between->site, loc.between->side, on_other);
      p.point = 0.5f * (p.point + q.point);
      p.normal = glm::normalize(p.normal + q.normal);
    }
    // A copied (symmetric) location on the other side of the body mirrors the dominant one.
    (void)copy;
    last_site_[h] = p;
    has_site_[h] = true;
    last_part_[h] = loc.hand_part;
    const float gap = gap_of(loc.proximity, sign::site_region(loc.site));
    return loc.hand_part ? place_part_at(h, s, p, gap, *loc.hand_part) : place_at(h, s, p, gap);
  }

  // ---- the sign ------------------------------------------------------------------------------

  void perform_segment(const sign::ManualSign& m, bool first) {
    symmetry_ = m.symmetry;
    HandState target[2] = {state_[0], state_[1]};
    const sign::Posture& p = m.posture;
    const bool dominant_signs = !m.nondominant_only;
    auto on_hand = [](const std::optional<sign::Location>& l) {
      return l && (sign::site_region(l->site) == sign::SiteRegion::hand || sign::site_region(l->site) == sign::SiteRegion::finger);
    };
    // The dominant hand placed at a part of the other hand (its palm, back, fingers) or of its
    // forearm or wrist makes the other hand the base: it comes up in front, near the midline,
    // even when nothing else is written for it, instead of being met hanging at the hip.
    auto on_forearm = [](const std::optional<sign::Location>& l) {
      return l && (l->site == sign::Site::lower_arm || l->site == sign::Site::wrist_back || l->site == sign::Site::wrist_pulse);
    };
    const bool base_hand =
        dominant_signs && (on_hand(p.location.dominant) || on_forearm(p.location.dominant)) && !p.location.nondominant;
    const bool other_signs = m.nondominant_only || both_hands() || base_hand || p.handshape.nondominant.has_value() ||
                             p.location.nondominant.has_value() || p.orientation.nondominant.has_value();
    auto shape_for = [&](int h) -> HandPosture {
      const auto& own = h == 0 ? p.handshape.dominant : p.handshape.nondominant;
      if (own) return hand_posture_of(*own);
      if (h == 1 && p.handshape.dominant && (both_hands() || !m.nondominant_only)) return hand_posture_of(*p.handshape.dominant);
      return make_handshape(BasicHandshape::Flat);
    };
    bool posed[2] = {false, false};
    for (int h = 0; h < 2; ++h) {
      const bool active = h == 0 ? dominant_signs : other_signs;
      posed[h] = active;
      if (!active) continue;
      HandState& s = target[h];
      s.active = true;
      s.shape = shape_for(h);
      // Orientation: the hand's own notation, or the dominant one copied (mirrored) by symmetry.
      const auto& own_o = h == 0 ? p.orientation.dominant : p.orientation.nondominant;
      const bool copy_o = !own_o && h == 1;
      const sign::Orientation default_o{sign::Direction::up_out, std::nullopt, false,
                                        h == 0 ? sign::Direction::left : sign::Direction::right};
      // A base hand written with nothing of its own is a flat hand: palm up and fingers forward
      // to be touched on the hand, palm down and fingers across the body on the forearm or wrist.
      const bool plain_base = h == 1 && base_hand && !both_hands() && !own_o && !p.handshape.nondominant;
      const sign::Orientation base_o =
          on_forearm(p.location.dominant)
              ? sign::Orientation{sign::Direction::right, std::nullopt, false, sign::Direction::down}
              : sign::Orientation{sign::Direction::out, std::nullopt, false, sign::Direction::up};
      if (plain_base) s.shape = make_handshape(BasicHandshape::Flat);
      const sign::Orientation& o = plain_base ? base_o
                                   : own_o   ? *own_o
                                             : (p.orientation.dominant && h == 1 ? *p.orientation.dominant : default_o);
      s.orientation = orientation_of(h, o, s.orientation, !plain_base && (copy_o || (h == 1 && !own_o && both_hands())));
    }
    // A hand constellation names a part of each hand or wrist (the dominant hand's pinky side on
    // the other hand's palm, a wrist on the back of the other hand): the non-dominant hand waits in front, near the midline, and the dominant hand
    // brings its part to the named part of the other hand.
    auto on_hand_or_wrist = [&](const std::optional<sign::Location>& l) { return on_hand(l) || on_forearm(l); };
    const bool constellation = on_hand_or_wrist(p.location.dominant) && on_hand_or_wrist(p.location.nondominant);
    if (constellation) {
      target[1].active = true;
      target[1].position = neutral_space(1).point + kBaseHandOffset;
      state_[1] = target[1];
      const SitePlace other = other_hand_site(0, p.location.nondominant->site);
      const auto proximity = p.hands_contact ? p.hands_contact : p.location.dominant->proximity;
      const sign::Location& own = *p.location.dominant;  // the dominant hand's part that touches
      target[0].position = place_part_at(0, target[0], other, gap_of(proximity, sign::SiteRegion::hand),
                                         sign::SitePoint{own.site, own.fingers, own.finger_part, own.side});
    }
    // Locations: the non-dominant hand first, as the dominant hand may be placed on it.
    for (int h : {1, 0}) {
      if (constellation) break;
      if (!target[h].active) continue;
      const auto& own_l = h == 0 ? p.location.dominant : p.location.nondominant;
      if (h == 1 && base_hand) {
        target[1].position = neutral_space(1).point + kBaseHandOffset;
        state_[1] = target[1];
      } else if (own_l) {
        target[h].position = location_position(h, *own_l, target[h], false);
        if (h == 1) state_[1] = target[1];  // the dominant hand's placement reads it
      } else if (h == 1 && p.location.dominant && both_hands()) {
        sign::Location mirrored_loc = *p.location.dominant;
        target[h].position = location_position(h, mirrored_loc, target[h], true);
        if (mirrored() || symmetry_.kind == sign::SymmetryKind::parallel) {
          // Mirror the dominant hand's place across the body's midline when the site is central.
          const vec3 dom = location_position(0, *p.location.dominant, target[0], false);
          target[h].position = mirror_x(dom);
        }
        state_[1] = target[1];
      } else {
        target[h].position = neutral_space(h).point;
        if (h == 1) state_[1] = target[1];
      }
    }
    // Two hands at one central site stand side by side, each on its own side of the midline.
    if (both_hands() && target[0].active && target[1].active && p.location.dominant && !p.location.nondominant &&
        !p.hands_contact && p.location.dominant->side == sign::Side::centre &&
        sign::site_region(p.location.dominant->site) != sign::SiteRegion::hand &&
        sign::site_region(p.location.dominant->site) != sign::SiteRegion::finger) {
      const float half_gap = sign::site_region(p.location.dominant->site) == sign::SiteRegion::trunk ||
                                     p.location.dominant->site == sign::Site::neutral_space ? 0.11f : 0.07f;
      target[0].position.x = std::min(target[0].position.x, -half_gap);
      target[1].position.x = -target[0].position.x;
      state_[1] = target[1];
    }
    if (p.hands_contact && target[0].active && target[1].active && !constellation) {
      // The hands touch: bring the dominant hand's palm to the other hand.
      SitePlace other = other_hand_site(0, sign::Site::palm);
      target[0].position = place_at(0, target[0], other, gap_of(p.hands_contact, sign::SiteRegion::hand));
    }
    settle_together(target, posed);
    // Move in (from rest or from the previous segment), then hold the posture briefly.
    for (int h = 0; h < 2; ++h) state_[h] = timeline_[h].segments.empty() ? rest_hand_state(rig_, hand_of(h)) : timeline_[h].segments.back().to;
    for (int h = 0; h < 2; ++h) {
      const HandState to = target[h].active ? target[h] : state_[h];
      const float d = first && !options_.from_rest ? 1e-3f : transition_time(state_[h], to);
      move_to(h, to, d);
    }
    sync();
    if (first) plan_.sign_start = now();
    hold_both(scaled(options_.initial_hold));
    for (const Element& e : m.actions) {
      perform(e, mask_for_action());
      sync();
    }
  }

  // Which hands "the hand" of an action means: 1 = dominant, 2 = non-dominant, 3 = both (symmetry).
  int mask_for_action() const { return both_hands() ? 3 : 1; }

  void perform(const Element& e, int mask) {
    // Where this action starts, for a repetition "from the start" that may follow it.
    const HandState started[2] = {state_[0], state_[1]};
    perform_action(e, mask);
    if (e.kind != ElementKind::repetition && e.kind != ElementKind::contact) {
      for (int h = 0; h < 2; ++h) action_start_[h] = started[h], action_start_valid_[h] = true;
    }
  }

  void perform_action(const Element& e, int mask) {
    switch (e.kind) {
      case ElementKind::handshape:
      case ElementKind::orientation:
      case ElementKind::location:
      case ElementKind::motion: {
        const float start = now();
        std::vector<const Element*> one{&e};
        perform_simultaneous(one, mask, start);
        last_action_ = &e;
        last_mask_ = mask;
        break;
      }
      case ElementKind::contact: perform_contact(*e.contact(), mask); break;
      case ElementKind::repetition: perform_repetition(*e.repetition(), mask); break;
      case ElementKind::sequence:
        for (const Element& c : e.children) {
          perform(c, c.nondominant ? 2 : mask);
          sync();
        }
        last_action_ = &e;
        last_mask_ = mask;
        break;
      case ElementKind::parallel:
      case ElementKind::fusion: {
        std::vector<const Element*> leaves;
        bool flat = true;
        for (const Element& c : e.children) {
          if (c.kind == ElementKind::motion || c.kind == ElementKind::handshape || c.kind == ElementKind::orientation ||
              c.kind == ElementKind::location)
            leaves.push_back(&c);
          else
            flat = false;
        }
        if (flat && !leaves.empty()) {
          perform_simultaneous(leaves, mask, now());
        } else {
          for (const Element& c : e.children) perform(c, mask);  // nested groups: one after another
        }
        last_action_ = &e;
        last_mask_ = mask;
        break;
      }
      case ElementKind::hand_pair: {
        // Each branch drives its own hand, at the same time.
        const float start = now();
        for (std::size_t b = 0; b < e.children.size() && b < 2; ++b) {
          const int hand_mask = b == 0 ? 1 : 2;
          for (const Element& c : e.children[b].children.empty() ? std::vector<Element>{e.children[b]} : e.children[b].children)
            perform_on(c, hand_mask, start);
        }
        sync();
        last_action_ = &e;
        last_mask_ = mask;
        break;
      }
      case ElementKind::alternatives:
        if (!e.children.empty()) perform(e.children.front(), mask);
        break;
      case ElementKind::unspecified:
      case ElementKind::coreference: break;
    }
  }

  // Performs `e` for one hand starting no earlier than `start` without syncing the other hand.
  void perform_on(const Element& e, int hand_mask, float start) {
    const int h = hand_mask == 1 ? 0 : 1;
    if (clock_[h] < start) hold(h, start - clock_[h]);
    if (e.kind == ElementKind::motion || e.kind == ElementKind::handshape || e.kind == ElementKind::orientation ||
        e.kind == ElementKind::location) {
      std::vector<const Element*> one{&e};
      simultaneous_for_hand(one, h, false);
    } else if (e.kind == ElementKind::sequence || e.kind == ElementKind::parallel || e.kind == ElementKind::fusion) {
      for (const Element& c : e.children) perform_on(c, hand_mask, clock_[h]);
    } else if (e.kind == ElementKind::repetition && last_hand_action_[h]) {
      const Element* again = last_hand_action_[h];
      perform_on(*again, hand_mask, clock_[h]);
    }
  }

  void perform_simultaneous(const std::vector<const Element*>& leaves, int mask, float start) {
    const bool both = (mask & 3) == 3;
    for (int h = 0; h < 2; ++h) {
      if (!(mask & (1 << h))) continue;
      if (clock_[h] < start) hold(h, start - clock_[h]);
      const bool copy = h == 1 && (mask & 1);  // the non-dominant copy of a dominant action
      simultaneous_for_hand(leaves, h, copy, !both);
    }
    if (!both) return;
    // Both hands moved: settle their ends in space together, so hands held to each other stay so.
    HandState ends[2] = {timeline_[0].segments.back().to, timeline_[1].segments.back().to};
    const bool posed[2] = {true, true};
    settle_together(ends, posed);
    for (int h = 0; h < 2; ++h) timeline_[h].segments.back().to = state_[h] = ends[h];
  }

  // One segment for one hand combining all leaves: paths are summed, changes happen together.
  // `settle`: take the nearest place in space where the arm makes the turn (settle_in_space);
  // the caller does that when it moves both hands.
  void simultaneous_for_hand(const std::vector<const Element*>& leaves, int h, bool copy, bool settle = true) {
    HandSegment seg;
    seg.from = state_[h];
    seg.to = state_[h];
    seg.to.active = true;
    float duration = 0.0f;
    const bool alternate = copy && symmetry_.alternating;
    for (const Element* e : leaves) {
      if (const sign::Handshape* hs = e->handshape()) {
        seg.to.shape = hand_posture_of(*hs);
        duration = std::max(duration, scaled(kReplacementTime));
      } else if (const sign::Orientation* o = e->orientation()) {
        seg.to.orientation = orientation_of(h, *o, seg.to.orientation, copy);
        duration = std::max(duration, scaled(kReplacementTime));
      } else if (const sign::Location* l = e->location()) {
        seg.to.position = action_location(h, *l, seg.to, copy);
        duration = std::max(duration, transition_time(seg.from, seg.to));
      } else if (const sign::Motion* m = e->motion()) {
        duration = std::max(duration, add_motion(*m, h, copy, alternate, seg));
      }
    }
    seg.end = std::max(duration, 0.05f);
    // Paths are timed by their own duration; stretch them to the segment's. The hand ends where
    // the paths take it.
    for (Movement& mv : seg.paths) {
      mv.duration = seg.end;
      seg.to.position += sample(mv, mv.duration).position;
    }
    last_hand_action_[h] = leaves.empty() ? nullptr : leaves.front();
    if (settle) settle_in_space(h, seg.to, state_[1 - h], seg.to.position - seg.from.position);
    add_segment(h, std::move(seg));
  }

  // Adds a motion to a segment; returns its duration.
  float add_motion(const sign::Motion& m, int h, bool copy, bool alternate, HandSegment& seg) {
    const MovementSpeed speed = speed_of(m.manner);
    const MovementSize size = size_of(m.size);
    auto dir_vec = [&](sign::Direction d) { return direction_vector(hand_direction(h, d, copy)); };
    float duration = 0.0f;
    if (m.new_handshape) seg.to.shape = hand_posture_of(*m.new_handshape);
    if (m.new_orientation) seg.to.orientation = orientation_of(h, *m.new_orientation, seg.to.orientation, copy);
    switch (m.kind) {
      case MotionKind::straight:
      case MotionKind::crossing:
      case MotionKind::x_shaped: {
        if (m.target) {
          seg.to.position = action_location(h, *m.target, seg.to, copy);
          duration = scaled(straight_duration(glm::distance(seg.from.position, seg.to.position), speed));
          break;
        }
        vec3 d = m.direction ? dir_vec(*m.direction) : vec3(hand_of(h) == Hand::Right ? 1.0f : -1.0f, 0, 0);
        if (m.direction && m.direction_between) d = glm::normalize(d + dir_vec(*m.direction_between));
        if (alternate) d = -d;
        const float len = straight_length(size);
        MovementPath path = m.arc ? arc_path(d, len, glm::normalize(dir_vec(*m.arc) - glm::dot(dir_vec(*m.arc), d) * d + vec3(1e-4f)))
                                  : straight_path(d, len);
        if (m.path == sign::PathShape::wavy) path = with_modifier(path, PathModifier::Wavy);
        if (m.path == sign::PathShape::zigzag) path = with_modifier(path, PathModifier::Zigzag);
        if (m.spiral != sign::Spiral::none) path = with_modifier(path, PathModifier::Spiral);
        const Movement mv = make_movement(path, speed);
        duration = scaled(mv.duration);
        seg.paths.push_back(mv);
        break;
      }
      case MotionKind::circle: {
        vec3 axis = m.direction ? dir_vec(*m.direction) : vec3(0, 0, 1);
        if (alternate) axis = -axis;
        vec3 start = vec3(0, -1, 0) - glm::dot(vec3(0, -1, 0), axis) * axis;
        if (glm::length(start) < 1e-3f) start = vec3(0, 0, -1) - glm::dot(vec3(0, 0, -1), axis) * axis;
        const Movement mv = make_movement(circle_path(axis, circle_radius(size), glm::normalize(start)), speed);
        duration = scaled(mv.duration);
        seg.paths.push_back(mv);
        seg.linear_blend = true;
        break;
      }
      case MotionKind::stirring_cw:
      case MotionKind::stirring_ccw: {
        const vec3 axis = m.kind == MotionKind::stirring_cw ? vec3(0, -1, 0) : vec3(0, 1, 0);
        const Movement mv = make_movement(circle_path(axis, 0.025f, vec3(0, 0, 1)), speed);
        duration = scaled(mv.duration);
        seg.paths.push_back(mv);
        break;
      }
      case MotionKind::nodding:
      case MotionKind::swinging:
      case MotionKind::twisting:
        seg.oscillation = m.kind == MotionKind::nodding ? Oscillation::Nod : m.kind == MotionKind::swinging ? Oscillation::Swing : Oscillation::Twist;
        seg.oscillation_cycles = 2.0f;
        duration = scaled(kOscillationTime * speed_factor(speed));
        break;
      case MotionKind::finger_play:
        seg.oscillation = Oscillation::FingerPlay;
        seg.oscillation_cycles = 3.0f;
        seg.oscillating_fingers = m.fingers.empty() ? kAllFourFingers : static_cast<FingerSet>(m.fingers.bits & kAllFourFingers);
        duration = scaled(kFingerPlayTime * speed_factor(speed));
        break;
      case MotionKind::wrist_bend:
        seg.to.orientation = glm::normalize(seg.to.orientation * glm::angleAxis(0.6f, vec3(1, 0, 0)));
        duration = scaled(kReplacementTime);
        break;
      case MotionKind::replacement:
        if (m.target) seg.to.position = action_location(h, *m.target, seg.to, copy);
        duration = scaled(kReplacementTime * speed_factor(speed));
        break;
      case MotionKind::to_location:
        if (m.target) seg.to.position = action_location(h, *m.target, seg.to, copy);
        duration = scaled(straight_duration(glm::distance(seg.from.position, seg.to.position), speed));
        break;
      case MotionKind::none: duration = scaled(kHoldTime); break;
    }
    if (m.target_contact && has_site_[h]) seg.to.position = place_at_last_site(h, seg.to, gap_of(m.target_contact, sign::SiteRegion::face));
    return duration;
  }

  void perform_contact(const sign::Contact& c, int mask) {
    for (int h = 0; h < 2; ++h) {
      if (!(mask & (1 << h)) || !has_site_[h]) continue;
      HandState to = state_[h];
      to.position = place_at_last_site(h, to, gap_of(c.proximity, sign::SiteRegion::face));
      move_to(h, to, scaled(kContactTime));
    }
  }

  void perform_repetition(const sign::Repetition& r, int mask) {
    if (!last_action_) return;
    const Element* again = last_action_;
    const int again_mask = last_mask_;
    const int times = (r.kind == sign::RepetitionKind::from_start_several || r.kind == sign::RepetitionKind::continued_several) ? 2 : 1;
    (void)mask;
    for (int k = 0; k < times; ++k) {
      const HandState before[2] = {state_[0], state_[1]};
      if (r.kind == sign::RepetitionKind::from_start || r.kind == sign::RepetitionKind::from_start_several) {
        // Return to where the repeated action began, then do it again.
        for (int h = 0; h < 2; ++h)
          if (action_start_valid_[h]) move_to(h, action_start_[h], scaled(0.25f));
        sync();
      }
      if (r.kind == sign::RepetitionKind::reversed) {
        for (int h = 0; h < 2; ++h)
          if (action_start_valid_[h]) move_to(h, action_start_[h], scaled(0.45f));
        sync();
        for (int h = 0; h < 2; ++h) action_start_[h] = before[h];
        continue;
      }
      perform(*again, again_mask);
      sync();
    }
    last_action_ = again;
  }

  const SigningRig& rig_;
  PlanOptions options_;
  Pose scratch_;
  std::vector<vec3> body_site_points_;  // bind-pose positions of the body's own sites (near_a_body_site)
  HandTimeline detour_timeline_;  // scratch for detour_around_body
  SignPlan plan_;
  HandTimeline timeline_[2];
  HandState state_[2];
  float clock_[2] = {0.0f, 0.0f};
  sign::Symmetry symmetry_;
  SitePlace last_site_[2];
  bool has_site_[2] = {false, false};
  std::optional<sign::SitePoint> last_part_[2];  // the hand part the last location named
  const Element* last_action_ = nullptr;
  int last_mask_ = 1;
  const Element* last_hand_action_[2] = {nullptr, nullptr};
  HandState action_start_[2];
  bool action_start_valid_[2] = {false, false};
};

}  // namespace

SignPlan plan_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& options) {
  if (!(options.speed >= 0.25f && options.speed <= 4.0f))
    throw Error("speed must be between 0.25 and 4 (got " + std::to_string(options.speed) + ")");
  if (sign.segments.empty()) throw Error("the sign has no manual part");
  SignPlan plan = Planner(rig, options).run(sign);
  // The notation's caps (sign_limits.hpp) bound the actions; slow manners and a slow tempo still
  // multiply their time, so the planned duration has its own cap.
  sign::check_sign_duration(plan.duration());
  return plan;
}

}  // namespace gestura
