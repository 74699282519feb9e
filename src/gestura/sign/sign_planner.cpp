#include "gestura/sign/sign_planner.hpp"

#include <optional>
#include <string>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/sign/body_repair.hpp"
#include "gestura/sign/place_resolver.hpp"
#include "gestura/sign/sign_limits.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

namespace gestura {

namespace {

// Every segment lasts at least a millisecond: a hold of no time still marks an instant.
constexpr float kMinSegment = 1e-3f;
// A segment's changes take at least this long.
constexpr float kMinStep = 0.05f;
// A base hand waits this far in from neutral space (toward the midline, lower, nearer the body).
const vec3 kBaseHandOffset(-0.06f, -0.02f, -0.03f);

vec3 mirror_x(vec3 v) { return vec3(-v.x, v.y, v.z); }

// The site a hand's location last named, to return to for a contact written after a movement.
struct LastSite {
  SurfacePoint place;
  std::optional<sign::SitePoint> part;  // the hand part the location named
};

// Lays a citation schedule out on a rig, one step at a time: each step's places found by the
// resolver, each new segment put through the body's rules, then appended to the timeline.
class Planner {
 public:
  Planner(const CitationSchedule& schedule, const SigningRig& rig)
      : schedule_(schedule), places_(rig), body_(rig),
        before_{{rest_hand_state(rig, Hand::Right), rest_hand_state(rig, Hand::Left)}} {}

  SignPlan run() {
    if (schedule_.steps.empty() || !std::holds_alternative<PostureStep>(schedule_.steps.front()))
      throw Error("a citation schedule starts with a posture");
    if (!(schedule_.speed > 0.0f)) throw Error("a citation schedule needs a tempo above 0");
    for (const ScheduleStep& step : schedule_.steps) std::visit([this](const auto& s) { take(s); }, step);
    return timeline_->finish(0.0f, timeline_->now());
  }

 private:
  float speed() const { return schedule_.speed; }
  // The hand's state now; before the first posture, at rest (which underspecified notation turns from).
  const HandState& state(Hand h) const { return timeline_ ? timeline_->state(h) : before_[h]; }

  // ---- segments ---------------------------------------------------------------------------------

  // A new segment for the hand (from its state), put through the body's rules.
  void add(Hand h, HandSegment segment) {
    body_.repair_end(h, segment);
    body_.repair_way(h, segment);
    timeline_->append(h, std::move(segment));
  }
  void move_to(Hand h, const HandState& to, float seconds) {
    HandSegment segment;
    segment.from = state(h);
    segment.to = to;
    segment.end = seconds;
    add(h, std::move(segment));
  }

  // ---- places -----------------------------------------------------------------------------------

  // Where a notated location puts the hand (in state `s`; the other hand in state `other`), and
  // the site remembered for a contact that may follow.
  vec3 location_position(Hand h, const sign::Location& loc, const HandState& s, const HandState& other) {
    SurfacePoint site = places_.site(h, loc.site, loc.side, loc.nondominant_hand, other, both_hands_);
    if (loc.between) {
      const SurfacePoint q = places_.site(h, loc.between->site, loc.between->side, loc.nondominant_hand, other, both_hands_);
      site.point = 0.5f * (site.point + q.point);
      site.normal = glm::normalize(site.normal + q.normal);
    }
    last_site_[h] = LastSite{site, loc.hand_part};
    const float gap = contact_gap(loc.proximity, sign::site_region(loc.site));
    return loc.hand_part ? places_.place_part_at(h, s, site, gap, *loc.hand_part) : places_.place_at(h, s, site, gap);
  }

  // A location an action moves the hand to. One on the other hand or forearm while that hand
  // rests at the hip is not a place to go (the hand would dive to the hip): the hand stays.
  vec3 action_location(Hand h, const sign::Location& loc, const HandState& s) {
    const sign::SiteRegion region = sign::site_region(loc.site);
    const bool on_other_forearm =
        loc.site == sign::Site::lower_arm || loc.site == sign::Site::wrist_back || loc.site == sign::Site::wrist_pulse;
    const bool on_other_hand = loc.nondominant_hand || region == sign::SiteRegion::hand ||
                               region == sign::SiteRegion::finger || on_other_forearm;
    const HandState& other = state(other_hand(h));
    if (on_other_hand && !other.active) return s.position;
    return location_position(h, loc, s, other);
  }

  vec3 at_last_site(Hand h, const HandState& s, float gap) {
    const LastSite& last = *last_site_[h];
    return last.part ? places_.place_part_at(h, s, last.place, gap, *last.part) : places_.place_at(h, s, last.place, gap);
  }

  // ---- steps ------------------------------------------------------------------------------------

  void take(const PostureStep& p) {
    both_hands_ = p.both_hands;
    ByHand<HandState> target{{state(Hand::Right), state(Hand::Left)}};
    for (Hand h : kBothHands) {
      const PostureHand& hand = p.hands[h];
      if (!hand.posed) continue;
      target[h].active = true;
      target[h].shape = hand.shape;
      target[h].orientation = turn_hand(target[h].orientation, hand.turn, h);
    }
    if (p.constellation) {
      target[Hand::Left].active = true;
      target[Hand::Left].position = places_.neutral_space(Hand::Left, both_hands_).point + kBaseHandOffset;
      const SurfacePoint site =
          places_.other_hand_site(Hand::Left, target[Hand::Left], p.constellation->other_site).value_or(SurfacePoint{});
      target[Hand::Right].position =
          places_.place_part_at(Hand::Right, target[Hand::Right], site, p.constellation->gap, p.constellation->part);
    } else {
      // The non-dominant hand first: the dominant hand may be placed on it.
      for (Hand h : {Hand::Left, Hand::Right}) {
        if (!target[h].active) continue;
        const PostureHand& hand = p.hands[h];
        const HandState& other = h == Hand::Left ? state(Hand::Right) : target[Hand::Left];
        switch (hand.place) {
          case PosturePlace::BaseHand:
            target[h].position = places_.neutral_space(h, both_hands_).point + kBaseHandOffset;
            break;
          case PosturePlace::Site: target[h].position = location_position(h, *hand.location, target[h], other); break;
          case PosturePlace::DominantSite:
            target[h].position = location_position(h, *hand.location, target[h], other);
            if (hand.mirror_dominant) {
              // The dominant hand's place, mirrored across the body's midline.
              target[h].position = mirror_x(
                  location_position(Hand::Right, *hand.location, target[Hand::Right], state(Hand::Left)));
            }
            break;
          case PosturePlace::NeutralSpace: target[h].position = places_.neutral_space(h, both_hands_).point; break;
        }
      }
    }
    HandState& right = target[Hand::Right];
    HandState& left = target[Hand::Left];
    if (p.side_by_side && right.active && left.active) {
      right.position.x = std::min(right.position.x, -*p.side_by_side);
      left.position.x = -right.position.x;
    }
    if (p.hands_touch && right.active && left.active) {
      // The hands touch: the dominant hand's palm comes to the other hand.
      const SurfacePoint palm = places_.other_hand_site(Hand::Left, left, sign::Site::palm).value_or(SurfacePoint{});
      right.position = places_.place_at(Hand::Right, right, palm, *p.hands_touch);
    }
    body_.settle_together(target, ByHand<bool>{{p.hands[Hand::Right].posed, p.hands[Hand::Left].posed}});
    ByHand<HandState> to;
    for (Hand h : kBothHands) to[h] = target[h].active ? target[h] : state(h);
    if (!timeline_) {
      timeline_.emplace(to, 0.0f, kMinSegment);  // the schedule starts at its first posture
      return;
    }
    for (Hand h : kBothHands) move_to(h, to[h], transition_time(state(h), to[h], speed()));
    timeline_->sync();
  }

  void take(const HoldStep& s) { timeline_->hold_both(s.seconds); }
  void take(const SyncStep&) { timeline_->sync(); }

  void take(const MoveStep& m) {
    const float start = timeline_->now();
    for (Hand h : kBothHands) {
      if (!drives(m.hands, h)) continue;
      timeline_->hold_until(h, start);
      lay_out(h, m.steps[h]);
    }
    if (m.hands != Hands::Both) return;
    // Both hands moved: their ends settle in space together, so that hands held to each other stay so.
    ByHand<HandState> ends{{timeline_->state(Hand::Right), timeline_->state(Hand::Left)}};
    body_.settle_together(ends, ByHand<bool>{{true, true}});
    for (Hand h : kBothHands) timeline_->end_last_at(h, ends[h]);
  }

  void take(const HandPairStep& pair) {
    const float start = timeline_->now();
    for (Hand h : kBothHands) {
      const HandPairStep::Branch& branch = pair.branches[h];
      if (branch.waits) timeline_->hold_until(h, start);
      for (const HandStep& step : branch.steps) lay_out(h, step);
    }
  }

  void take(const ContactStep& c) {
    for (Hand h : kBothHands) {
      if (!drives(c.hands, h) || !last_site_[h]) continue;
      HandState to = state(h);
      to.position = at_last_site(h, to, c.gap);
      move_to(h, to, c.seconds);
    }
  }

  void take(const ActionBegins&) { started_.push_back(ByHand<HandState>{{state(Hand::Right), state(Hand::Left)}}); }
  void take(const ActionEnds& e) {
    if (e.keep) action_start_ = started_.back();
    started_.pop_back();
  }
  void take(const ReturnToStart& r) {
    if (!action_start_) return;
    for (Hand h : kBothHands) move_to(h, (*action_start_)[h], r.seconds);
  }
  void take(const Reverse& r) {
    const ByHand<HandState> before{{state(Hand::Right), state(Hand::Left)}};
    if (action_start_)
      for (Hand h : kBothHands) move_to(h, (*action_start_)[h], r.seconds);
    timeline_->sync();
    if (action_start_) action_start_ = before;
  }

  // One hand's step: one segment from the hand's state with all its changes.
  void lay_out(Hand h, const HandStep& step) {
    HandSegment seg;
    seg.from = state(h);
    seg.to = seg.from;
    seg.to.active = true;
    float seconds = step.seconds;
    for (const HandChange& change : step.changes) {
      if (const auto* c = std::get_if<Reshape>(&change)) {
        seg.to.shape = c->shape;
      } else if (const auto* c = std::get_if<Turn>(&change)) {
        seg.to.orientation = turn_hand(seg.to.orientation, c->turn, h);
      } else if (const auto* c = std::get_if<MoveTo>(&change)) {
        if (c->place) seg.to.position = action_location(h, *c->place, seg.to);
        if (c->travel == Travel::Transition) seconds = std::max(seconds, transition_time(seg.from, seg.to, speed()));
        if (c->travel == Travel::Straight)
          seconds = std::max(seconds, straight_duration(glm::distance(seg.from.position, seg.to.position), c->speed) / speed());
      } else if (const auto* c = std::get_if<FollowPath>(&change)) {
        seg.paths.push_back(c->movement);
        seg.linear_blend |= c->constant_speed;
      } else if (const auto* c = std::get_if<Oscillate>(&change)) {
        seg.oscillation = c->kind;
        seg.oscillation_cycles = c->cycles;
        seg.oscillating_fingers = c->fingers;
      } else if (const auto* c = std::get_if<BendWrist>(&change)) {
        seg.to.orientation = glm::normalize(seg.to.orientation * glm::angleAxis(c->radians, vec3(1, 0, 0)));
      } else if (const auto* c = std::get_if<TouchLastSite>(&change)) {
        if (last_site_[h]) seg.to.position = at_last_site(h, seg.to, c->gap);
      }
    }
    seg.end = std::max(seconds, kMinStep);
    // Paths are timed by their own length; they are stretched to the segment's, and the hand ends
    // where they take it.
    for (Movement& path : seg.paths) {
      path.duration = seg.end;
      seg.to.position += sample(path, path.duration).position;
    }
    if (step.settle) body_.settle_in_space(h, seg.to, state(other_hand(h)), seg.to.position - seg.from.position);
    add(h, std::move(seg));
  }

  const CitationSchedule& schedule_;
  PlaceResolver places_;
  BodyRepair body_;
  ByHand<HandState> before_;  // the hands before the first posture: at rest
  std::optional<TwoHandTimeline> timeline_;  // from the first posture on
  bool both_hands_ = false;   // the current segment is symmetric
  ByHand<std::optional<LastSite>> last_site_;
  std::vector<ByHand<HandState>> started_;         // where the actions under way started
  std::optional<ByHand<HandState>> action_start_;  // where the last finished action started
};

void check(const sign::HamSign& sign, float speed) {
  if (!(speed >= 0.25f && speed <= 4.0f)) throw Error("speed must be between 0.25 and 4 (got " + std::to_string(speed) + ")");
  if (sign.segments.empty()) throw Error("the sign has no manual part");
}

}  // namespace

SignPlan plan_schedule(const CitationSchedule& schedule, const SigningRig& rig) {
  SignPlan plan = Planner(schedule, rig).run();
  // The notation's caps (sign_limits.hpp) bound the actions; slow manners and a slow tempo still
  // multiply their time, so the planned citation form has its own cap.
  sign::check_sign_duration(plan.duration());
  return plan;
}

SignPlan plan_citation(const sign::HamSign& sign, const SigningRig& rig, const ScheduleOptions& options) {
  check(sign, options.speed);
  return plan_schedule(read_citation_schedule(sign, options), rig);
}

SignPlan from_rest_to_rest(const SignPlan& citation, const SigningRig& rig, float speed, bool from_rest, bool to_rest) {
  BodyRepair body(rig);
  const ByHand<HandState> rest{{rest_hand_state(rig, Hand::Right), rest_hand_state(rig, Hand::Left)}};
  ByHand<HandState> first;
  for (Hand h : kBothHands) first[h] = citation.hand(h).segments.front().from;
  TwoHandTimeline timeline(from_rest ? rest : first, 0.0f, kMinSegment);
  auto travel = [&](Hand h, const HandState& to) {
    HandSegment way;
    way.from = timeline.state(h);
    way.to = to;
    way.end = transition_time(way.from, way.to, speed);
    body.repair_way(h, way);
    timeline.append(h, std::move(way));
  };
  if (from_rest) {
    for (Hand h : kBothHands) travel(h, first[h]);
    timeline.sync();
  }
  const float start = timeline.now();
  for (Hand h : kBothHands) timeline.append_shifted(h, citation.hand(h), start);
  if (to_rest) {
    for (Hand h : kBothHands) travel(h, rest[h]);
    timeline.sync();
  }
  return timeline.finish(start + citation.sign_start, start + citation.sign_end);
}

SignPlan plan_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& options) {
  const SignPlan citation = plan_citation(sign, rig, ScheduleOptions{options.speed, options.initial_hold, options.final_hold});
  if (!options.from_rest && !options.to_rest) return citation;
  return from_rest_to_rest(citation, rig, options.speed, options.from_rest, options.to_rest);
}

}  // namespace gestura
