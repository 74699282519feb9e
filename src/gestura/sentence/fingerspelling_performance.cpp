#include "gestura/sentence/fingerspelling_performance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "gestura/body/body_sites.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/eye_gaze.hpp"
#include "gestura/face/face_action.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/sign_performer.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

namespace gestura {

namespace {

// ASL: the palm centre of the spelling hand relative to its shoulder (a little lower, 30 cm out).
constexpr vec3 kAslSpellingOffset{-0.05f, -0.08f, 0.30f};
// BSL: the non-dominant palm centre relative to the chest site: at the midline, 2 cm lower, 20 cm
// in front (elbows bent), where both hands meet comfortably.
constexpr vec3 kBslBaseOffset{0.0f, -0.02f, 0.20f};
// BSL: the non-dominant hand turned 30° about the vertical toward the dominant side, presenting its
// palm and fingers to the dominant hand; a dominant hand laid on that palm turns with it, so its
// forearm need not turn fully palm-out (on this avatar the IK then reaches the L of "DLGN" exactly
// instead of 3.3 cm short).
constexpr float kBslPresentDegrees = 30.0f;
constexpr float kContactGap = 0.008f;  // surface point of one finger to the other's: finger flesh
constexpr float kAslDip = 0.015f;      // a doubled moving letter dips this far on its way back
constexpr float kBslTapLift = 0.02f;   // a doubled BSL letter lifts off its site this far
constexpr float kGazeRampOut = 0.25f;  // seconds for the eyes to come back to the viewer

// Where a hand's parts are for a state: vectors from the palm centre, in the signer frame.
struct HandParts {
  std::array<vec3, 5> tips;      // thumb .. little finger
  std::array<vec3, 4> knuckles;  // index .. little finger MCP
  vec3 finger, palm, thumb_side;
  float half_width = 0.04f;      // palm centre to its radial / ulnar edge
  float half_thickness = 0.015f;
};

HandParts parts_of(const SigningRig& rig, Hand hand, const HandState& s, Pose& scratch) {
  const HandPoints points = planned_hand_points(rig, hand, s, scratch);
  HandParts p;
  std::copy_n(points.begin() + kTipPoints, 5, p.tips.begin());
  std::copy_n(points.begin() + kKnucklePoints, 4, p.knuckles.begin());
  p.finger = s.orientation * vec3(0, 1, 0);
  p.palm = s.orientation * vec3(0, 0, 1);
  p.thumb_side = hand_frame_from_vectors(p.finger, p.palm, hand).thumb_side;
  p.half_width = 0.5f * glm::length(p.knuckles[0] - p.knuckles[3]) + 0.01f;
  p.half_thickness = rig.hand(hand).palm_half_thickness;
  return p;
}

// A contact site on the non-dominant hand: the point (relative to its palm centre) and the side
// the dominant hand comes from.
SurfacePoint site_on(const HandParts& n, BslContactSite site) {
  const vec3 middle_of_index = 0.5f * (n.knuckles[0] + n.tips[1]);
  switch (site) {
    case BslContactSite::None: break;
    case BslContactSite::ThumbTip: return {n.tips[0], n.palm};
    case BslContactSite::IndexTip: return {n.tips[1], n.finger};
    case BslContactSite::MiddleTip: return {n.tips[2], n.palm};
    case BslContactSite::RingTip: return {n.tips[3], n.palm};
    case BslContactSite::PinkyTip: return {n.tips[4], n.palm};
    case BslContactSite::IndexFinger: return {middle_of_index, n.palm};
    case BslContactSite::IndexMiddle:  // across the backs of the two fingers
      return {0.25f * (n.knuckles[0] + n.knuckles[1] + n.tips[1] + n.tips[2]) - n.palm * 0.008f, -n.palm};
    case BslContactSite::Palm: return {n.palm * n.half_thickness, n.palm};
    case BslContactSite::PinkyEdge: return {-n.thumb_side * n.half_width, -n.thumb_side};
    case BslContactSite::ThumbIndexWeb: return {0.5f * (n.tips[0] + n.knuckles[0]) * 0.6f, n.palm};
    case BslContactSite::FistTop:
    case BslContactSite::ThumbIndexSide: return {n.thumb_side * n.half_width, n.thumb_side};
    case BslContactSite::LittleFinger: return {n.tips[4], n.finger};
    case BslContactSite::Fingers: return {n.finger * 0.06f, n.palm};
  }
  return {vec3(0.0f), vec3(0.0f, 0.0f, -1.0f)};  // no site: the dominant hand comes from in front
}

// The point of the dominant hand that makes the contact, relative to its palm centre.
vec3 part_of(const HandParts& d, BslDominantPart part) {
  switch (part) {
    case BslDominantPart::None: break;
    case BslDominantPart::IndexTip: return d.tips[1];
    case BslDominantPart::IndexPad: return 0.5f * (d.knuckles[0] + d.tips[1]) + d.palm * 0.008f;
    case BslDominantPart::FingerPads:
      return 0.25f * (d.knuckles[0] + d.knuckles[1] + d.tips[1] + d.tips[2]) + d.palm * 0.008f;
    case BslDominantPart::ThumbIndex: return 0.5f * (d.tips[0] + d.tips[1]);
    case BslDominantPart::FistSide: return -d.thumb_side * d.half_width;
    case BslDominantPart::LittleFinger: return d.tips[4];
    case BslDominantPart::Fingers: return d.finger * 0.06f;
    case BslDominantPart::PalmSurface: return d.palm * d.half_thickness;
  }
  return vec3(0.0f);
}

// What the two hands do for one letter: the configuration formed, the dominant hand's own
// movement after it (J, Z, BSL H and J), and where a doubled letter's bounce goes.
struct LetterPose {
  ByHand<HandState> formed;  // dominant (right), non-dominant (left)
  ByHand<HandState> after;   // after the letter's movement (= formed without one)
  std::optional<MovementPath> movement;
  vec3 bounce{0.0f};                // displacement at the bottom of a bounce
};

class LetterPoser {
 public:
  LetterPoser(const SigningRig& rig) : rig_(rig), scratch_(rig.rest) {
    const int shoulder = rig.hand(Hand::Right).shoulder;
    asl_origin_ = joint_position(rig.bind_model, shoulder) + kAslSpellingOffset;
    const BodySite* chest = find_site(rig.sites, "chest");
    const vec3 chest_point = chest ? site_position(*chest, rig.bind_model) : vec3(0.0f, 1.25f, 0.12f);
    bsl_base_ = chest_point + kBslBaseOffset;
  }

  // `previous_left`: the non-dominant hand before this letter (a one-handed BSL letter keeps it).
  LetterPose pose(ManualAlphabet alphabet, const LetterTarget& target, const HandState& previous_left) {
    return alphabet == ManualAlphabet::Asl ? asl(target) : bsl(target, previous_left);
  }

 private:
  LetterPose asl(const LetterTarget& target) const {
    const AslLetter& letter = *find_asl_letter(target.letter);
    LetterPose p;
    HandState& s = p.formed[Hand::Right];
    s.position = asl_origin_ + target.offset;
    s.orientation = letter_frame(letter, Hand::Right).rotation;
    s.shape = asl_handshape(letter.handshape);
    s.active = true;
    p.formed[Hand::Left] = rest_hand_state(rig_, Hand::Left);
    p.after = p.formed;
    p.movement = letter_movement(letter, Hand::Right);
    if (p.movement) {
      p.after[Hand::Right].position += path_end(*p.movement);
      if (letter.end_palm)
        p.after[Hand::Right].orientation =
            hand_frame_from_vectors(direction_vector(letter.finger), direction_vector(*letter.end_palm), Hand::Right)
                .rotation;
    }
    p.bounce = vec3(0.0f, -kAslDip, 0.0f);
    return p;
  }

  LetterPose bsl(const LetterTarget& target, const HandState& previous_left) {
    const BslLetter& letter = *find_bsl_letter(target.letter);
    LetterPose p;
    const quat present = glm::angleAxis(glm::radians(kBslPresentDegrees), vec3(0.0f, 1.0f, 0.0f));
    HandState& d = p.formed[Hand::Right];
    // The dominant hand turns with the base to lay itself on the base's palm; pointing at a
    // fingertip or an edge it turns the other way, forward into the presented hand (turned with the
    // base, a pointing hand had to reach round with its elbow out at shoulder height).
    d.orientation = dominant_frame(letter, Hand::Right).rotation;
    if (letter.site == BslContactSite::Palm) d.orientation = present * d.orientation;
    else d.orientation = glm::inverse(present) * d.orientation;
    d.shape = letter.dominant.posture;
    d.active = true;
    HandState& n = p.formed[Hand::Left];
    if (const std::optional<HandFrame> frame = non_dominant_frame(letter, Hand::Right)) {
      n.position = bsl_base_;
      n.orientation = present * frame->rotation;
      n.shape = letter.non_dominant->posture;
      n.active = true;
      const SurfacePoint site = site_on(parts_of(rig_, Hand::Left, n, scratch_), letter.site);
      const vec3 part = part_of(parts_of(rig_, Hand::Right, d, scratch_), letter.part);
      d.position = n.position + site.point + site.normal * kContactGap - part;
      p.bounce = site.normal * kBslTapLift;
    } else {
      // One-handed (C): formed beside the base, on the dominant side; the other hand stays.
      n = previous_left;
      d.position = bsl_base_ + vec3(-0.14f, 0.04f, 0.0f);
      p.bounce = vec3(0.0f, -kAslDip, 0.0f);
    }
    p.after = p.formed;
    if (letter.movement) {
      p.movement = letter.movement;
      p.after[Hand::Right].position += path_end(*letter.movement);
    }
    return p;
  }

  const SigningRig& rig_;
  Pose scratch_;
  vec3 asl_origin_{0.0f}, bsl_base_{0.0f};
};

Movement timed(const MovementPath& path, float duration) {
  Movement m;
  m.path = path;
  m.profile = default_profile(path);
  m.duration = duration;
  return m;
}

void check_speed(float speed) {
  if (!(speed >= 0.25f && speed <= 4.0f)) throw Error("fingerspelling speed " + std::to_string(speed) + " is outside 0.25–4");
}

}  // namespace

SpelledHands spell_with_hands(const SpellingPlan& plan, const SigningRig& rig, float speed) {
  if (plan.letters.empty()) throw Error("cannot perform an empty fingerspelling plan");
  check_speed(speed);
  const float origin = plan.letters.front().reached;
  auto clock = [&](float t) { return std::max(0.0f, (t - origin) / speed); };

  SpelledHands out;
  LetterPoser poser(rig);
  // Time 0 is the first letter formed: the timeline starts there.
  const LetterPose first = poser.pose(plan.alphabet, plan.letters.front(), rest_hand_state(rig, Hand::Left));
  TwoHandTimeline timeline(first.formed);
  for (std::size_t k = 0; k < plan.letters.size(); ++k) {
    const LetterTarget& target = plan.letters[k];
    const LetterPose pose = k == 0 ? first : poser.pose(plan.alphabet, target, timeline.state(Hand::Left));
    LetterTarget timed_target = target;
    timed_target.start = 0.0f;
    if (k > 0) {
      // The pause between words: the last letter is held.
      const float transition_start = std::max(timeline.now(), clock(target.start));
      for (Hand h : kBothHands) timeline.hold_until(h, transition_start);
      const float reached = std::max(transition_start + 1e-3f, clock(target.reached));
      for (Hand h : kBothHands) {
        HandSegment to_letter;
        to_letter.from = timeline.state(h);
        to_letter.to = pose.formed[h];
        to_letter.end = reached - transition_start;
        if (h == Hand::Right && target.doubled == DoubleMark::Bounce)
          to_letter.paths.push_back(timed(polyline_path({vec3(0.0f), pose.bounce, vec3(0.0f)}, true), to_letter.end));
        timeline.append(h, std::move(to_letter));
      }
      timed_target.start = transition_start;
    }
    timed_target.reached = timeline.now();
    if (pose.movement) {
      const float moved = std::max(timeline.now() + 1e-3f, clock(target.movement_end));
      HandSegment traced;
      traced.from = timeline.state(Hand::Right);
      traced.to = pose.after[Hand::Right];
      traced.end = moved - timeline.now();
      traced.paths.push_back(timed(*pose.movement, traced.end));
      timeline.append(Hand::Right, std::move(traced));
      timeline.move_to(Hand::Left, pose.after[Hand::Left], moved - timeline.clock(Hand::Left));
    }
    timed_target.movement_end = timeline.now();
    const bool last = k + 1 == plan.letters.size();
    const float end = std::max(timeline.now(), clock(target.end));
    if (end > timeline.now() || last) {
      const float held = std::max(end, timeline.now() + 1e-3f);
      for (Hand h : kBothHands) timeline.hold_until(h, held);
    }
    timed_target.end = timeline.now();
    out.letters.push_back(timed_target);
  }
  out.duration = timeline.now();
  SignPlan hands = timeline.finish(0.0f, out.duration);
  out.right = std::move(hands.right);
  out.left = std::move(hands.left);
  return out;
}

FingerspellingPerformance perform_fingerspelling(const SpellingPlan& plan, const SigningRig& rig,
                                                 const FingerspellingOptions& options) {
  check_speed(options.speed);
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("fps " + std::to_string(options.fps) + " is outside 1–240");
  const SpelledHands hands = spell_with_hands(plan, rig, options.speed);
  const ByHand<HandState> rest{{rest_hand_state(rig, Hand::Right), rest_hand_state(rig, Hand::Left)}};

  // Approach from rest and return to rest as a single sign's would (sign_planner), both hands
  // together, as long as the longer path needs.
  float approach = 0.0f, back = 0.0f;
  for (Hand h : kBothHands) {
    approach = std::max(approach, transition_time(rest[h], hands.first(h), options.speed));
    back = std::max(back, transition_time(hands.hand(h).final_state(), rest[h], options.speed));
  }
  TwoHandTimeline timeline(rest);
  timeline.move_both_to(ByHand<HandState>{{hands.first(Hand::Right), hands.first(Hand::Left)}}, approach);
  for (Hand h : kBothHands) timeline.append_shifted(h, hands.hand(h), approach);
  timeline.move_both_to(rest, back);
  const SignPlan motion = timeline.finish(approach, approach + hands.duration);

  FingerspellingPerformance result;
  result.clip = perform_plan(motion, rig, PerformOptions{options.fps});
  result.clip.name = "fingerspell";
  result.spelling_start = motion.sign_start;
  result.spelling_end = motion.sign_end;
  for (LetterTarget t : hands.letters) {
    t.start += approach;
    t.reached += approach;
    t.movement_end += approach;
    t.end += approach;
    result.letters.push_back(t);
  }
  result.letters.front().start = 0.0f;  // the approach from rest is the first letter's transition
  if (options.gaze) {
    // The eyes go to the hand as it arrives (a glance, over the second half of the approach) and
    // come back to the viewer as the last letter is released.
    const float ramp_in = 0.5f * approach;
    const face::FaceAction look{face::kGazeHands, approach - ramp_in, motion.sign_end + kGazeRampOut, 1.0f, ramp_in,
                                kGazeRampOut};
    face::write_face_channels(std::span<const face::FaceAction>(&look, 1), result.clip);
    face::write_eye_gaze(rig.skeleton(), result.clip, options.fps);
  }
  result.clip.duration = std::max(result.clip.duration, result.clip.end_time());
  return result;
}

}  // namespace gestura
