#include "gestura/sign/hamnosys_describe.hpp"

namespace gestura::sign {
namespace {

std::string_view basic_name(BasicHandshape b) {
  constexpr std::string_view names[] = {"fist",     "flat",     "finger2",     "finger23", "finger23spread", "finger2345",
                                        "pinch12",  "pinchall", "pinch12open", "cee12",    "ceeall",         "cee12open"};
  return names[static_cast<int>(b)];
}

std::string_view bending_name(FingerBending b) {
  constexpr std::string_view names[] = {"bent", "round", "hooked", "double-bent", "double-hooked", "half-bent"};
  return names[static_cast<int>(b)];
}

std::string_view proximity_name(Proximity p) {
  constexpr std::string_view names[] = {"close", "touch", "interlocked", "crossed", "far", "behind", "brushing"};
  return names[static_cast<int>(p)];
}

std::string fingers_name(FingerSet f) {
  constexpr std::string_view names[] = {"thumb", "index", "middle", "ring", "pinky"};
  std::string out;
  for (int i = 0; i < 5; ++i)
    if (f.contains(static_cast<Finger>(i))) out.append(out.empty() ? "" : "+").append(names[i]);
  return out;
}

std::string_view part_name(FingerPart p) {
  constexpr std::string_view names[] = {"tip", "nail", "pad", "mid-joint", "base", "side"};
  return names[static_cast<int>(p)];
}

std::string form_name(const HandshapeForm& f) {
  std::string out(basic_name(f.basic));
  if (f.thumb != ThumbModifier::Default)
    out += f.thumb == ThumbModifier::Out ? " thumb-out" : f.thumb == ThumbModifier::Across ? " thumb-across" : " thumb-open";
  if (f.bending) out.append(" ").append(std::string(bending_name(*f.bending)));
  for (const FingerModifier& m : f.finger_modifiers) {
    out.append(" [").append(fingers_name(m.fingers));
    if (m.part) out.append(" ").append(std::string(part_name(*m.part)));
    if (m.bending) out.append(m.fingers.empty() ? "" : " ").append(bending_name(*m.bending));
    out += "]";
  }
  return out;
}

std::string point_name(Site site, FingerSet fingers, std::optional<FingerPart> part, Side side) {
  std::string out;
  if (side == Side::dominant_side) out += "dominant-side ";
  if (side == Side::beside) out += "beside ";
  if (site != Site::fingers) out.append(site_name(site));
  else out.append(fingers.empty() ? "fingers" : fingers_name(fingers));
  if (site != Site::fingers && !fingers.empty()) out.append(" ").append(fingers_name(fingers));
  if (part) out.append(" ").append(std::string(part_name(*part)));
  return out;
}

std::string dir(std::optional<Direction> d) { return d ? std::string(to_string(*d)) : "?"; }

std::string children(const Element& e, std::string_view separator) {
  std::string out;
  for (const Element& c : e.children) out.append(out.empty() ? std::string_view() : separator).append(describe(c));
  return out;
}

}  // namespace

std::string describe(const Handshape& h) {
  std::string out = form_name(h.form);
  if (h.between) out.append(" ~ ").append(form_name(*h.between));
  return out;
}

std::string describe(const Orientation& o) {
  std::string out;
  if (o.extended_finger) {
    out.append("fingers ").append(dir(o.extended_finger));
    if (o.extended_finger_between) out.append("~").append(dir(o.extended_finger_between));
    if (o.extended_finger_relative) out += " (relative)";
  }
  if (o.palm) {
    out.append(out.empty() ? "palm " : ", palm ").append(dir(o.palm));
    if (o.palm_between) out.append("~").append(dir(o.palm_between));
    if (o.palm_relative) out += " (relative)";
  }
  return out;
}

std::string describe(const Location& l) {
  std::string out = point_name(l.site, l.fingers, l.finger_part, l.side);
  if (l.between) out.append(" ~ ").append(point_name(l.between->site, l.between->fingers, l.between->finger_part, l.between->side));
  if (l.hand_part) out.append(" with ").append(point_name(l.hand_part->site, l.hand_part->fingers, l.hand_part->finger_part, l.hand_part->side));
  if (l.proximity) out.append(" ").append(std::string(proximity_name(*l.proximity)));
  return out;
}

std::string describe(const Motion& m) {
  std::string_view kind;
  switch (m.kind) {
    case MotionKind::straight: kind = "move"; break;
    case MotionKind::circle: kind = "circle"; break;
    case MotionKind::finger_play: kind = "finger play"; break;
    case MotionKind::nodding: kind = "nod"; break;
    case MotionKind::swinging: kind = "swing"; break;
    case MotionKind::twisting: kind = "twist"; break;
    case MotionKind::stirring_cw: kind = "stir cw"; break;
    case MotionKind::stirring_ccw: kind = "stir ccw"; break;
    case MotionKind::wrist_bend: kind = "wrist bend"; break;
    case MotionKind::replacement: kind = "replace"; break;
    case MotionKind::to_location: kind = "to"; break;
    case MotionKind::crossing: kind = "cross"; break;
    case MotionKind::x_shaped: kind = "X"; break;
    case MotionKind::none: kind = "still"; break;
  }
  std::string out(kind);
  if (m.kind == MotionKind::straight || m.kind == MotionKind::circle) out.append(" ").append(dir(m.direction));
  if (m.direction_between) out.append("~").append(dir(m.direction_between));
  if (m.arc) out.append(" arc ").append(dir(m.arc));
  if (m.path == PathShape::wavy) out += " wavy";
  if (m.path == PathShape::zigzag) out += " zigzag";
  if (m.ellipse != Ellipse::none) out += " ellipse";
  if (m.spiral == Spiral::increasing) out += " increasing";
  if (m.spiral == Spiral::decreasing) out += " decreasing";
  if (m.size == Size::small) out += " small";
  if (m.size == Size::large) out += " large";
  if (m.manner.fast) out += " fast";
  if (m.manner.slow) out += " slow";
  if (m.manner.tense) out += " tense";
  if (m.manner.rest) out += " rest";
  if (m.manner.halt) out += " halt";
  if (m.alternating) out += " alternating";
  if (!m.fingers.empty()) out.append(" ").append(fingers_name(m.fingers));
  if (m.new_handshape) out.append(" handshape ").append(describe(*m.new_handshape));
  if (m.new_orientation) out.append(" ").append(describe(*m.new_orientation));
  if (m.target) out.append(" ").append(describe(*m.target));
  else if (m.target_contact) out.append(" ").append(std::string(proximity_name(*m.target_contact)));
  return out;
}

std::string describe(const Element& e) {
  switch (e.kind) {
    case ElementKind::handshape: return std::string("handshape ").append(describe(*e.handshape()));
    case ElementKind::orientation: return describe(*e.orientation());
    case ElementKind::location: return std::string("at ").append(describe(*e.location()));
    case ElementKind::contact: return std::string(proximity_name(e.contact()->proximity));
    case ElementKind::motion: {
      std::string out = describe(*e.motion());
      if (!e.children.empty()) out.append(" ").append(children(e, " "));
      return out;
    }
    case ElementKind::repetition: {
      const Repetition& r = *e.repetition();
      constexpr std::string_view kinds[] = {"repeat", "repeat several", "continue", "continue several", "reverse"};
      std::string out(kinds[static_cast<int>(r.kind)]);
      if (r.offset) out.append(" offset ").append(describe(*r.offset));
      if (r.alternating) out += " alternating";
      return out;
    }
    case ElementKind::sequence: return std::string("seq(").append(children(e, ", ")).append(")");
    case ElementKind::parallel: return std::string("par(").append(children(e, " & ")).append(")");
    case ElementKind::fusion: return std::string("fused(").append(children(e, " & ")).append(")");
    case ElementKind::hand_pair: return std::string("hands(").append(children(e, " | ")).append(")");
    case ElementKind::alternatives: return std::string("either(").append(children(e, " / ")).append(")");
    case ElementKind::unspecified: return "etc";
    case ElementKind::coreference: return "coref";
  }
  return "?";
}

std::string describe(const HamSign& sign) {
  std::string out;
  for (const ManualSign& m : sign.segments) {
    if (!out.empty()) out += " ++ ";
    if (m.symmetry.kind == SymmetryKind::parallel) out += "symmetric-parallel; ";
    if (m.symmetry.kind == SymmetryKind::mirrored_lr) out += "symmetric-lr; ";
    if (m.nondominant_only) out += "non-dominant hand; ";
    const Posture& p = m.posture;
    auto hand = [&](const char* label, const std::optional<Handshape>& h, const std::optional<Orientation>& o,
                    const std::optional<Location>& l) {
      if (!h && !o && !l) return;
      std::string parts;
      if (h) parts.append(describe(*h));
      if (o) parts.append(parts.empty() ? "" : ", ").append(describe(*o));
      if (l) parts.append(parts.empty() ? "at " : ", at ").append(describe(*l));
      out.append(label).append(" ").append(parts).append("; ");
    };
    hand("dominant:", p.handshape.dominant, p.orientation.dominant, p.location.dominant);
    hand("non-dominant:", p.handshape.nondominant, p.orientation.nondominant, p.location.nondominant);
    if (p.nondominant_unspecified) out += "non-dominant shape open; ";
    if (p.hands_contact) out.append("hands ").append(proximity_name(*p.hands_contact)).append("; ");
    std::string actions;
    for (const Element& e : m.actions) actions.append(actions.empty() ? "" : ", ").append(describe(e));
    out += actions.empty() ? "no movement" : actions;
  }
  return out;
}

}  // namespace gestura::sign
