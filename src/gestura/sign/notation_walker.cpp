#include "gestura/sign/notation_walker.hpp"

#include <algorithm>

namespace gestura {

namespace {

using sign::Element;
using sign::ElementKind;
using sign::MotionKind;

// Durations of actions without a path (seconds, normal speed).
constexpr float kReplacementTime = 0.35f;
constexpr float kOscillationTime = 0.6f;
constexpr float kFingerPlayTime = 0.7f;
constexpr float kHoldTime = 0.3f;
constexpr float kContactTime = 0.25f;
constexpr float kReturnTime = 0.25f;   // a repetition from the start: back to where the action began
constexpr float kReverseTime = 0.45f;  // a repetition in reverse
constexpr float kOscillationCycles = 2.0f;
constexpr float kFingerPlayCycles = 3.0f;
constexpr float kStirRadius = 0.025f;   // metres: the wrist's small circle when stirring
constexpr float kWristBend = 0.6f;      // radians: hamwristto*
// Two hands at one central site keep this far (metres) on their own sides of the midline: a
// hand's width in front of the trunk or in space, less at the face.
constexpr float kSideBySideTrunk = 0.11f;
constexpr float kSideBySideFace = 0.07f;

MovementSize size_of(sign::Size s) {
  return s == sign::Size::small ? MovementSize::Small : s == sign::Size::large ? MovementSize::Large : MovementSize::Normal;
}
MovementSpeed speed_of(const sign::Manner& m) {
  return m.fast ? MovementSpeed::Fast : m.slow ? MovementSpeed::Slow : MovementSpeed::Normal;
}

bool is_leaf(const Element& e) {
  return e.kind == ElementKind::motion || e.kind == ElementKind::handshape || e.kind == ElementKind::orientation ||
         e.kind == ElementKind::location;
}
bool on_hand(const std::optional<sign::Location>& l) {
  return l && (sign::site_region(l->site) == sign::SiteRegion::hand || sign::site_region(l->site) == sign::SiteRegion::finger);
}
bool on_forearm(const std::optional<sign::Location>& l) {
  return l && (l->site == sign::Site::lower_arm || l->site == sign::Site::wrist_back || l->site == sign::Site::wrist_pulse);
}

class Walker {
 public:
  explicit Walker(const ScheduleOptions& options) : options_(options) { schedule_.speed = options.speed; }

  CitationSchedule run(const sign::HamSign& sign) {
    for (const sign::ManualSign& segment : sign.segments) {
      read_posture(segment);
      emit(HoldStep{scaled(options_.posture_hold)});
      for (const Element& e : segment.actions) {
        read_action(e, hands_for_action());
        emit(SyncStep{});
      }
    }
    emit(HoldStep{scaled(options_.final_hold)});
    return std::move(schedule_);
  }

 private:
  float scaled(float seconds) const { return seconds / options_.speed; }
  void emit(ScheduleStep step) { schedule_.steps.push_back(std::move(step)); }

  // ---- symmetry ---------------------------------------------------------------------------------

  bool mirrored() const { return symmetry_.kind == sign::SymmetryKind::mirrored_lr; }
  bool both_hands() const { return symmetry_.kind != sign::SymmetryKind::none; }
  // "The hand" of an action is both hands in a symmetric sign, the dominant one otherwise.
  Hands hands_for_action() const { return both_hands() ? Hands::Both : Hands::Dominant; }

  // A direction for hand `h`; the non-dominant copy of a mirror-symmetric sign mirrors it.
  Direction hand_direction(Hand h, Direction d, bool copy) const {
    return copy && mirrored() && h == Hand::Left ? mirror_left_right(d) : d;
  }
  vec3 direction(Hand h, Direction d, bool copy) const { return direction_vector(hand_direction(h, d, copy)); }

  TurnTarget turn_target(Hand h, const sign::Orientation& o, bool copy) const {
    TurnTarget t;
    if (o.extended_finger) {
      vec3 finger = direction(h, *o.extended_finger, copy);
      if (o.extended_finger_between) finger = glm::normalize(finger + direction(h, *o.extended_finger_between, copy));
      t.finger = finger;
    }
    if (o.palm) {
      t.palm = hand_direction(h, *o.palm, copy);
      if (o.palm_between) t.palm_between = direction(h, *o.palm_between, copy);
    }
    return t;
  }

  // ---- the posture ------------------------------------------------------------------------------

  void read_posture(const sign::ManualSign& m) {
    symmetry_ = m.symmetry;
    const sign::Posture& p = m.posture;
    PostureStep step;
    step.both_hands = both_hands();
    const bool dominant_signs = !m.nondominant_only;
    // The dominant hand placed at a part of the other hand (its palm, back, fingers) or of its
    // forearm or wrist makes the other hand the base: it comes up in front, near the midline, even
    // when nothing else is written for it, instead of being met hanging at the hip.
    const bool base_hand =
        dominant_signs && (on_hand(p.location.dominant) || on_forearm(p.location.dominant)) && !p.location.nondominant;
    const bool other_signs = m.nondominant_only || both_hands() || base_hand || p.handshape.nondominant.has_value() ||
                             p.location.nondominant.has_value() || p.orientation.nondominant.has_value();
    auto shape_for = [&](Hand h) -> HandPosture {
      const auto& own = h == Hand::Right ? p.handshape.dominant : p.handshape.nondominant;
      if (own) return hand_posture_of(*own);
      if (h == Hand::Left && p.handshape.dominant && (both_hands() || !m.nondominant_only))
        return hand_posture_of(*p.handshape.dominant);
      return make_handshape(BasicHandshape::Flat);
    };
    for (Hand h : kBothHands) {
      PostureHand& hand = step.hands[h];
      hand.posed = h == Hand::Right ? dominant_signs : other_signs;
      if (!hand.posed) continue;
      hand.shape = shape_for(h);
      // Orientation: the hand's own notation, or the dominant one copied (mirrored) by symmetry.
      const auto& own = h == Hand::Right ? p.orientation.dominant : p.orientation.nondominant;
      const bool copied = !own && h == Hand::Left;
      const sign::Orientation unwritten{Direction::UO, std::nullopt, false, h == Hand::Right ? Direction::L : Direction::R};
      // A base hand written with nothing of its own is a flat hand: palm up and fingers forward to
      // be touched on the hand, palm down and fingers across the body on the forearm or wrist.
      const bool plain_base = h == Hand::Left && base_hand && !both_hands() && !own && !p.handshape.nondominant;
      const sign::Orientation base = on_forearm(p.location.dominant)
                                         ? sign::Orientation{Direction::R, std::nullopt, false, Direction::D}
                                         : sign::Orientation{Direction::O, std::nullopt, false, Direction::U};
      if (plain_base) hand.shape = make_handshape(BasicHandshape::Flat);
      const sign::Orientation& o = plain_base ? base
                                   : own      ? *own
                                              : (p.orientation.dominant && h == Hand::Left ? *p.orientation.dominant : unwritten);
      hand.turn = turn_target(h, o, !plain_base && (copied || (h == Hand::Left && !own && both_hands())));
    }
    // A hand constellation names a part of each hand or wrist (the dominant hand's pinky side on
    // the other hand's palm, a wrist on the back of the other hand): the non-dominant hand waits in
    // front, near the midline, and the dominant hand brings its part to the named part of the other.
    auto on_hand_or_wrist = [](const std::optional<sign::Location>& l) { return on_hand(l) || on_forearm(l); };
    if (on_hand_or_wrist(p.location.dominant) && on_hand_or_wrist(p.location.nondominant)) {
      const sign::Location& own = *p.location.dominant;  // the dominant hand's part that touches
      step.constellation = Constellation{
          p.location.nondominant->site, static_cast<const sign::SitePoint&>(own),
          contact_gap(p.hands_contact ? p.hands_contact : own.proximity, sign::SiteRegion::hand)};
    }
    // Places, for each hand that signs in the posture (or still signs from the segment before).
    for (Hand h : kBothHands) {
      PostureHand& hand = step.hands[h];
      const auto& own = h == Hand::Right ? p.location.dominant : p.location.nondominant;
      if (h == Hand::Left && base_hand) {
        hand.place = PosturePlace::BaseHand;
      } else if (own) {
        hand.place = PosturePlace::Site;
        hand.location = *own;
      } else if (h == Hand::Left && p.location.dominant && both_hands()) {
        hand.place = PosturePlace::DominantSite;
        hand.location = *p.location.dominant;
        hand.mirror_dominant = mirrored() || symmetry_.kind == sign::SymmetryKind::parallel;
      } else {
        hand.place = PosturePlace::NeutralSpace;
      }
    }
    const auto& at = p.location.dominant;
    if (both_hands() && at && !p.location.nondominant && !p.hands_contact && at->side == sign::Side::centre &&
        sign::site_region(at->site) != sign::SiteRegion::hand && sign::site_region(at->site) != sign::SiteRegion::finger)
      step.side_by_side = sign::site_region(at->site) == sign::SiteRegion::trunk || at->site == sign::Site::neutral_space
                              ? kSideBySideTrunk
                              : kSideBySideFace;
    if (p.hands_contact && !step.constellation) step.hands_touch = contact_gap(p.hands_contact, sign::SiteRegion::hand);
    emit(std::move(step));
  }

  // ---- actions ----------------------------------------------------------------------------------

  void read_action(const Element& e, Hands hands) {
    emit(ActionBegins{});
    read_element(e, hands);
    emit(ActionEnds{e.kind != ElementKind::repetition && e.kind != ElementKind::contact});
  }

  void remember_last(const Element& e, Hands hands) {
    last_action_ = &e;
    last_hands_ = hands;
  }

  void read_element(const Element& e, Hands hands) {
    switch (e.kind) {
      case ElementKind::handshape:
      case ElementKind::orientation:
      case ElementKind::location:
      case ElementKind::motion:
        read_together({&e}, hands);
        remember_last(e, hands);
        break;
      case ElementKind::contact:
        emit(ContactStep{hands, contact_gap(e.contact()->proximity, sign::SiteRegion::face), scaled(kContactTime)});
        break;
      case ElementKind::repetition: read_repetition(*e.repetition()); break;
      case ElementKind::sequence:
        for (const Element& c : e.children) {
          read_action(c, c.nondominant ? Hands::NonDominant : hands);
          emit(SyncStep{});
        }
        remember_last(e, hands);
        break;
      case ElementKind::parallel:
      case ElementKind::fusion: {
        std::vector<const Element*> leaves;
        bool flat = true;
        for (const Element& c : e.children) {
          if (is_leaf(c)) leaves.push_back(&c);
          else flat = false;
        }
        if (flat && !leaves.empty()) {
          read_together(leaves, hands);
        } else {
          for (const Element& c : e.children) read_action(c, hands);  // nested groups: one after another
        }
        remember_last(e, hands);
        break;
      }
      case ElementKind::hand_pair: {
        // Each branch drives its own hand, at the same time.
        HandPairStep pair;
        for (std::size_t b = 0; b < e.children.size() && b < 2; ++b) {
          const Hand h = b == 0 ? Hand::Right : Hand::Left;
          HandPairStep::Branch& branch = pair.branches[h];
          const Element& written = e.children[b];
          if (written.children.empty()) {
            branch.waits = true;
            read_for_one_hand(written, h, branch.steps);
          }
          for (const Element& c : written.children) {
            branch.waits = true;
            read_for_one_hand(c, h, branch.steps);
          }
        }
        emit(std::move(pair));
        emit(SyncStep{});
        remember_last(e, hands);
        break;
      }
      case ElementKind::alternatives:
        if (!e.children.empty()) read_action(e.children.front(), hands);
        break;
      case ElementKind::unspecified:
      case ElementKind::coreference: break;
    }
  }

  // The steps of `e` for one hand alone (a hand pair's branch).
  void read_for_one_hand(const Element& e, Hand h, std::vector<HandStep>& out) {
    if (is_leaf(e)) {
      out.push_back(hand_step({&e}, h, false, true));
    } else if (e.kind == ElementKind::sequence || e.kind == ElementKind::parallel || e.kind == ElementKind::fusion) {
      for (const Element& c : e.children) read_for_one_hand(c, h, out);
    } else if (e.kind == ElementKind::repetition && last_hand_action_[h]) {
      read_for_one_hand(*last_hand_action_[h], h, out);
    }
  }

  // One step combining all `leaves` for each hand `hands` drives: paths add up, changes happen
  // together; the non-dominant hand's is a copy of the dominant one's when both move.
  void read_together(const std::vector<const Element*>& leaves, Hands hands) {
    MoveStep step;
    step.hands = hands;
    for (Hand h : kBothHands) {
      if (!drives(hands, h)) continue;
      const bool copy = h == Hand::Left && drives(hands, Hand::Right);
      step.steps[h] = hand_step(leaves, h, copy, hands != Hands::Both);
    }
    emit(std::move(step));
  }

  HandStep hand_step(const std::vector<const Element*>& leaves, Hand h, bool copy, bool settle) {
    HandStep step;
    step.settle = settle;
    const bool alternate = copy && symmetry_.alternating;
    for (const Element* e : leaves) {
      if (const sign::Handshape* hs = e->handshape()) {
        step.changes.push_back(Reshape{hand_posture_of(*hs)});
        step.seconds = std::max(step.seconds, scaled(kReplacementTime));
      } else if (const sign::Orientation* o = e->orientation()) {
        step.changes.push_back(Turn{turn_target(h, *o, copy)});
        step.seconds = std::max(step.seconds, scaled(kReplacementTime));
      } else if (const sign::Location* l = e->location()) {
        step.changes.push_back(MoveTo{*l, Travel::Transition});
      } else if (const sign::Motion* m = e->motion()) {
        step.seconds = std::max(step.seconds, read_motion(*m, h, copy, alternate, step));
      }
    }
    last_hand_action_[h] = leaves.empty() ? nullptr : leaves.front();
    return step;
  }

  // Adds a motion's changes to a step; returns its seconds (travel to a place adds its own).
  float read_motion(const sign::Motion& m, Hand h, bool copy, bool alternate, HandStep& step) {
    const MovementSpeed speed = speed_of(m.manner);
    const MovementSize size = size_of(m.size);
    auto dir = [&](Direction d) { return direction(h, d, copy); };
    float seconds = 0.0f;
    if (m.new_handshape) step.changes.push_back(Reshape{hand_posture_of(*m.new_handshape)});
    if (m.new_orientation) step.changes.push_back(Turn{turn_target(h, *m.new_orientation, copy)});
    switch (m.kind) {
      case MotionKind::straight:
      case MotionKind::crossing:
      case MotionKind::x_shaped: {
        if (m.target) {
          step.changes.push_back(MoveTo{*m.target, Travel::Straight, speed});
          break;
        }
        // Without a direction the hand moves across to the other side.
        vec3 d = m.direction ? dir(*m.direction) : vec3(h == Hand::Right ? 1.0f : -1.0f, 0, 0);
        if (m.direction && m.direction_between) d = glm::normalize(d + dir(*m.direction_between));
        if (alternate) d = -d;
        const float length = straight_length(size);
        MovementPath path =
            m.arc ? arc_path(d, length, glm::normalize(dir(*m.arc) - glm::dot(dir(*m.arc), d) * d + vec3(1e-4f)))
                  : straight_path(d, length);
        if (m.path == sign::PathShape::wavy) path = with_modifier(path, PathModifier::Wavy);
        if (m.path == sign::PathShape::zigzag) path = with_modifier(path, PathModifier::Zigzag);
        if (m.spiral != sign::Spiral::none) path = with_modifier(path, PathModifier::Spiral);
        const Movement movement = make_movement(path, speed);
        seconds = scaled(movement.duration);
        step.changes.push_back(FollowPath{movement});
        break;
      }
      case MotionKind::circle: {
        vec3 axis = m.direction ? dir(*m.direction) : vec3(0, 0, 1);
        if (alternate) axis = -axis;
        // The circle starts below its centre (or behind it, about a vertical axis).
        vec3 start = vec3(0, -1, 0) - glm::dot(vec3(0, -1, 0), axis) * axis;
        if (glm::length(start) < 1e-3f) start = vec3(0, 0, -1) - glm::dot(vec3(0, 0, -1), axis) * axis;
        const Movement movement = make_movement(circle_path(axis, circle_radius(size), glm::normalize(start)), speed);
        seconds = scaled(movement.duration);
        step.changes.push_back(FollowPath{movement, true});
        break;
      }
      case MotionKind::stirring_cw:
      case MotionKind::stirring_ccw: {
        const vec3 axis = m.kind == MotionKind::stirring_cw ? vec3(0, -1, 0) : vec3(0, 1, 0);
        const Movement movement = make_movement(circle_path(axis, kStirRadius, vec3(0, 0, 1)), speed);
        seconds = scaled(movement.duration);
        step.changes.push_back(FollowPath{movement});
        break;
      }
      case MotionKind::nodding:
      case MotionKind::swinging:
      case MotionKind::twisting:
        step.changes.push_back(Oscillate{m.kind == MotionKind::nodding    ? Oscillation::Nod
                                         : m.kind == MotionKind::swinging ? Oscillation::Swing
                                                                          : Oscillation::Twist,
                                         kOscillationCycles});
        seconds = scaled(kOscillationTime * speed_factor(speed));
        break;
      case MotionKind::finger_play:
        step.changes.push_back(Oscillate{Oscillation::FingerPlay, kFingerPlayCycles,
                                         m.fingers.empty() ? kAllFourFingers
                                                           : static_cast<FingerSet>(m.fingers.bits & kAllFourFingers)});
        seconds = scaled(kFingerPlayTime * speed_factor(speed));
        break;
      case MotionKind::wrist_bend:
        step.changes.push_back(BendWrist{kWristBend});
        seconds = scaled(kReplacementTime);
        break;
      case MotionKind::replacement:
        if (m.target) step.changes.push_back(MoveTo{*m.target, Travel::None});
        seconds = scaled(kReplacementTime * speed_factor(speed));
        break;
      case MotionKind::to_location: step.changes.push_back(MoveTo{m.target, Travel::Straight, speed}); break;
      case MotionKind::none: seconds = scaled(kHoldTime); break;
    }
    if (m.target_contact) step.changes.push_back(TouchLastSite{contact_gap(m.target_contact, sign::SiteRegion::face)});
    return seconds;
  }

  void read_repetition(const sign::Repetition& r) {
    if (!last_action_) return;
    const Element* again = last_action_;
    const Hands hands = last_hands_;
    const bool several = r.kind == sign::RepetitionKind::from_start_several || r.kind == sign::RepetitionKind::continued_several;
    for (int k = 0; k < (several ? 2 : 1); ++k) {
      if (r.kind == sign::RepetitionKind::from_start || r.kind == sign::RepetitionKind::from_start_several) {
        // Back to where the repeated action began, then again.
        emit(ReturnToStart{scaled(kReturnTime)});
        emit(SyncStep{});
      }
      if (r.kind == sign::RepetitionKind::reversed) {
        emit(Reverse{scaled(kReverseTime)});
        continue;
      }
      read_action(*again, hands);
      emit(SyncStep{});
    }
    last_action_ = again;
  }

  ScheduleOptions options_;
  CitationSchedule schedule_;
  sign::Symmetry symmetry_;
  const Element* last_action_ = nullptr;  // what a repetition repeats, and for which hands
  Hands last_hands_ = Hands::Dominant;
  ByHand<const Element*> last_hand_action_{};  // … in a hand pair's branch
};

}  // namespace

HandPosture hand_posture_of(const sign::HandshapeForm& form) {
  HandPosture p = make_handshape(form.basic, form.thumb, form.bending);
  for (const sign::FingerModifier& m : form.finger_modifiers)
    if (m.bending && !m.fingers.empty()) apply_bending(p, static_cast<FingerSet>(m.fingers.bits & kAllFourFingers), *m.bending);
  return p;
}

HandPosture hand_posture_of(const sign::Handshape& handshape) {
  const HandPosture a = hand_posture_of(handshape.form);
  return handshape.between ? mix(a, hand_posture_of(*handshape.between), 0.5f) : a;
}

CitationSchedule read_citation_schedule(const sign::HamSign& sign, const ScheduleOptions& options) {
  return Walker(options).run(sign);
}

}  // namespace gestura
