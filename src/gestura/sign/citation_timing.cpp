#include "gestura/sign/citation_timing.hpp"

#include <algorithm>

namespace gestura {

namespace {

float size_factor(sign::Size s) {
  switch (s) {
    case sign::Size::small: return 0.75f;
    case sign::Size::large: return 1.3f;
    case sign::Size::normal: break;
  }
  return 1.0f;
}

float manner_factor(const sign::Manner& m) {
  float f = 1.0f;
  if (m.fast) f *= 0.7f;
  if (m.slow) f *= 1.5f;
  if (m.tense) f *= 1.2f;
  return f;
}

// One movement performed once: its kind, size and manner.
float motion_seconds(const sign::Motion& m, int& movements, float& contact) {
  using K = sign::MotionKind;
  float t = 0.0f;
  switch (m.kind) {
    case K::straight:
    case K::to_location:
    case K::crossing:
      t = kTimingStraight * size_factor(m.size);
      if (m.arc) t *= 1.1f;
      if (m.path != sign::PathShape::plain) t += 0.15f;  // wavy, zigzag: a few swings on the way
      break;
    case K::x_shaped: t = 2.0f * kTimingStraight * size_factor(m.size); break;
    case K::circle:
      t = kTimingCircle * size_factor(m.size);
      if (m.spiral != sign::Spiral::none) t *= 1.5f;
      break;
    case K::finger_play:
    case K::nodding:
    case K::swinging:
    case K::twisting:
    case K::stirring_cw:
    case K::stirring_ccw:
      t = kTimingLocal;
      break;
    case K::wrist_bend:
    case K::replacement:
      t = kTimingChange;
      break;
    case K::none: return 0.0f;
  }
  ++movements;
  if (m.target_contact) contact += kTimingContact;
  if (m.manner.halt) t += 0.1f;
  return t * manner_factor(m.manner);
}

struct Walk {
  int movements = 0;
  float contact = 0.0f;
  float repetition = 0.0f;
  std::vector<float> repeats;

  // The actions of a sequence, one after another: each repetition repeats what came before it in
  // this sequence (since the previous repetition).
  float sequence(const std::vector<sign::Element>& elements) {
    float total = 0.0f, since_repeat = 0.0f;
    for (const sign::Element& e : elements) {
      if (const sign::Repetition* r = e.repetition()) {
        const int count = r->kind == sign::RepetitionKind::from_start_several ||
                                  r->kind == sign::RepetitionKind::continued_several
                              ? 2
                              : 1;
        // A return to the start (from_start) is part of each repeat's stroke, not extra time.
        float repeat = since_repeat * kTimingRepeatShare;
        for (int k = 0; k < count; ++k) {
          repeats.push_back(repeat);
          repetition += repeat;
          repeat *= kTimingRepeatDecay;
        }
        since_repeat = 0.0f;
        continue;
      }
      const float t = element(e);
      total += t;
      since_repeat += t;
    }
    return total;
  }

  float element(const sign::Element& e) {
    using EK = sign::ElementKind;
    switch (e.kind) {
      case EK::motion: return motion_seconds(*e.motion(), movements, contact);
      case EK::contact:
        contact += kTimingContact;
        return 0.0f;
      case EK::sequence: return sequence(e.children);
      case EK::parallel:
      case EK::hand_pair:
      case EK::alternatives: {
        // At the same time (or either one): as long as the longest.
        float longest = 0.0f;
        for (const sign::Element& c : e.children) longest = std::max(longest, element(c));
        return longest;
      }
      case EK::fusion: {
        // Fused into one movement: a little longer than the longest part.
        float longest = 0.0f;
        for (const sign::Element& c : e.children) longest = std::max(longest, element(c));
        return longest * 1.1f;
      }
      default: return 0.0f;
    }
  }
};

}  // namespace

CitationTiming citation_timing(const sign::HamSign& sign) {
  CitationTiming out;
  const float share = sign.segments.size() > 1 ? kTimingCompoundShare : 1.0f;
  for (const sign::ManualSign& segment : sign.segments) {
    Walk walk;
    const float movement = walk.sequence(segment.actions);
    const float manner = manner_factor(segment.symmetry.manner);
    float holds = kTimingHolds;
    if (segment.posture.hands_contact) walk.contact += kTimingContact;
    const bool still = walk.movements == 0;
    if (still) holds = kTimingStaticMinimum;
    out.holds += share * holds;
    out.movement += share * movement * manner;
    out.repetition += share * walk.repetition * manner;
    out.contact += share * walk.contact;
    out.movements += walk.movements;
    for (float r : walk.repeats) out.repeats.push_back(share * r * manner);
  }
  out.is_static = out.movements == 0;
  out.seconds = out.holds + out.movement + out.repetition + out.contact;
  return out;
}

}  // namespace gestura
