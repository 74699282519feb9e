#include "gestura/sign/hamnosys_parser.hpp"

#include <cstdio>
#include <iterator>
#include <string>
#include <type_traits>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"
#include "gestura/sign/sign_limits.hpp"

namespace gestura::sign {
namespace {

using S = Symbol;
using C = SymbolClass;

[[noreturn]] void fail(int index, const std::string& message) {
  SourceLocation where;
  where.index = index;
  throw Error(where, message);
}

std::string quoted(Symbol s) { return std::string(symbol_name(s)); }

// ---- symbol value tables ------------------------------------------------------------------------

BasicHandshape basic_handshape(Symbol s) {
  switch (s) {
    case S::fist: return BasicHandshape::Fist;
    case S::flathand: return BasicHandshape::Flat;
    case S::finger2: return BasicHandshape::Finger2;
    case S::finger23: return BasicHandshape::Finger23;
    case S::finger23spread: return BasicHandshape::Finger23Spread;
    case S::finger2345: return BasicHandshape::Finger2345;
    case S::pinch12: return BasicHandshape::Pinch12;
    case S::pinchall: return BasicHandshape::PinchAll;
    case S::pinch12open: return BasicHandshape::Pinch12Open;
    case S::cee12: return BasicHandshape::Cee12;
    case S::ceeall: return BasicHandshape::CeeAll;
    default: return BasicHandshape::Cee12Open;
  }
}

ThumbModifier thumb_position(Symbol s) {
  switch (s) {
    case S::thumboutmod: return ThumbModifier::Out;
    case S::thumbacrossmod: return ThumbModifier::Across;
    default: return ThumbModifier::Opposed;
  }
}

FingerBending finger_bending(Symbol s) {
  switch (s) {
    case S::fingerstraightmod: return FingerBending::Bent;
    case S::fingerbendmod: return FingerBending::Round;
    case S::fingerhookmod: return FingerBending::Hooked;
    case S::doublebent: return FingerBending::DoubleBent;
    default: return FingerBending::DoubleHooked;
  }
}

Finger finger(Symbol s) {
  switch (s) {
    case S::thumb: return Finger::Thumb;
    case S::indexfinger: return Finger::Index;
    case S::middlefinger: return Finger::Middle;
    case S::ringfinger: return Finger::Ring;
    default: return Finger::Pinky;
  }
}

FingerPart finger_part(Symbol s) {
  switch (s) {
    case S::fingertip: return FingerPart::tip;
    case S::fingernail: return FingerPart::nail;
    case S::fingerpad: return FingerPart::pad;
    case S::fingermidjoint: return FingerPart::mid_joint;
    case S::fingerbase: return FingerPart::base;
    default: return FingerPart::side;
  }
}

// The 18 direction symbols of each family share one order in the font: u ur r dr d dl l ul ol o
// or il i ir ui di do uo.
constexpr Direction kEighteen[18] = {
    Direction::U,       Direction::UR,  Direction::R,     Direction::DR,
    Direction::D,     Direction::DL, Direction::L,      Direction::UL,
    Direction::OL, Direction::O,       Direction::OR, Direction::IL,
    Direction::I,       Direction::IR,  Direction::UI,     Direction::DI,
    Direction::DO, Direction::UO};

constexpr int span_of(Symbol first, Symbol last) { return static_cast<int>(last) - static_cast<int>(first) + 1; }
static_assert(span_of(S::extfingeru, S::extfingeruo) == 18 && span_of(S::moveu, S::moveuo) == 18 &&
              span_of(S::circleo, S::circledi) == 18 && span_of(S::palmu, S::palmul) == 8 &&
              span_of(S::clocku, S::clockur) == 8, "direction symbol families must be contiguous");

Direction extended_finger_direction(Symbol s) { return kEighteen[static_cast<int>(s) - static_cast<int>(S::extfingeru)]; }
Direction straight_direction(Symbol s) { return kEighteen[static_cast<int>(s) - static_cast<int>(S::moveu)]; }

Direction palm_direction(Symbol s) {
  constexpr Direction eight[8] = {Direction::U,   Direction::UR,  Direction::R, Direction::DR,
                                  Direction::D, Direction::DL, Direction::L,  Direction::UL};
  return eight[static_cast<int>(s) - static_cast<int>(S::palmu)];
}

// Circles are named by the direction of their axis; font order o i d u l r ul dr ur dl ol ir or
// il ui do uo di.
Direction circle_axis(Symbol s) {
  constexpr Direction axes[18] = {
      Direction::O,      Direction::I,       Direction::D,      Direction::U,
      Direction::L,     Direction::R,    Direction::UL,   Direction::DR,
      Direction::UR, Direction::DL, Direction::OL, Direction::IR,
      Direction::OR, Direction::IL, Direction::UI,     Direction::DO,
      Direction::UO,   Direction::DI};
  return axes[static_cast<int>(s) - static_cast<int>(S::circleo)];
}

// Clock positions u ul l dl d dr r ur (then "full").
Direction clock_position(Symbol s) {
  constexpr Direction pos[8] = {Direction::U,   Direction::UL,    Direction::L,  Direction::DL,
                                Direction::D, Direction::DR, Direction::R, Direction::UR};
  return pos[static_cast<int>(s) - static_cast<int>(S::clocku)];
}

Direction arc_direction(Symbol s) {
  switch (s) {
    case S::arcl: return Direction::L;
    case S::arcu: return Direction::U;
    case S::arcr: return Direction::R;
    default: return Direction::D;
  }
}

Proximity proximity(Symbol s) {
  switch (s) {
    case S::close: return Proximity::close;
    case S::touch: return Proximity::touch;
    case S::interlock: return Proximity::interlocked;
    case S::cross: return Proximity::crossed;
    case S::armextended: return Proximity::far;
    case S::behind: return Proximity::behind;
    default: return Proximity::brushing;
  }
}

Site body_site(Symbol s) {
  switch (s) {
    case S::head: return Site::head;
    case S::headtop: return Site::head_top;
    case S::forehead: return Site::forehead;
    case S::eyebrows: return Site::eyebrows;
    case S::eyes: return Site::eyes;
    case S::nose: return Site::nose;
    case S::nostrils: return Site::nostrils;
    case S::ear: return Site::ear;
    case S::earlobe: return Site::earlobe;
    case S::cheek: return Site::cheek;
    case S::lips: return Site::lips;
    case S::tongue: return Site::tongue;
    case S::teeth: return Site::teeth;
    case S::chin: return Site::chin;
    case S::underchin: return Site::under_chin;
    case S::neck: return Site::neck;
    case S::shouldertop: return Site::shoulder_top;
    case S::shoulders: return Site::shoulders;
    case S::chest: return Site::chest;
    case S::stomach: return Site::stomach;
    case S::belowstomach: return Site::below_stomach;
    case S::neutralspace: return Site::neutral_space;
    case S::upperarm: return Site::upper_arm;
    case S::elbow: return Site::elbow;
    case S::elbowinside: return Site::elbow_inside;
    case S::lowerarm: return Site::lower_arm;
    case S::wristback: return Site::wrist_back;
    case S::wristpulse: return Site::wrist_pulse;
    case S::thumbball: return Site::thumb_ball;
    case S::palm: return Site::palm;
    case S::handback: return Site::hand_back;
    case S::thumbside: return Site::thumb_side;
    default: return Site::pinky_side;
  }
}

bool is_location_symbol(C c) {
  return c == C::location_site || c == C::finger || c == C::finger_part || c == C::location_side;
}

Symbol opener_of(Symbol closer) {
  switch (closer) {
    case S::parend: return S::parbegin;
    case S::seqend: return S::seqbegin;
    case S::fusionend: return S::fusionbegin;
    default: return S::altbegin;
  }
}

bool is_opener(Symbol s) { return s == S::parbegin || s == S::seqbegin || s == S::fusionbegin || s == S::altbegin; }
bool is_closer(Symbol s) { return s == S::parend || s == S::seqend || s == S::fusionend || s == S::altend; }

Symbol closer_of(Symbol opener) {
  switch (opener) {
    case S::parbegin: return S::parend;
    case S::seqbegin: return S::seqend;
    case S::fusionbegin: return S::fusionend;
    default: return S::altend;
  }
}

void apply_size(Size& size, Symbol s) { size = s == S::smallmod ? Size::small : Size::large; }

void apply_manner(Manner& m, Symbol s) {
  switch (s) {
    case S::fast: m.fast = true; break;
    case S::slow: m.slow = true; break;
    case S::tense: m.tense = true; break;
    case S::rest: m.rest = true; break;
    default: m.halt = true; break;
  }
}

// ---- parser -------------------------------------------------------------------------------------

// How a list of elements ended.
enum class Stop { end, closer, plus, metaalt };

class Parser {
 public:
  Parser(std::span<const Symbol> symbols, const ParseOptions& options) : sym_(symbols), options_(options) {}

  HamSign parse() {
    if (sym_.size() > kMaxSignSymbols)
      fail(static_cast<int>(kMaxSignSymbols),
           "sign too long: " + std::to_string(sym_.size()) + " symbols (limit " + std::to_string(kMaxSignSymbols) + ")");
    bool any = false;
    for (Symbol s : sym_) any = any || symbol_class(s) != C::punctuation;
    if (!any) fail(0, "empty sign: expected a handshape (e.g. hamflathand) or a symmetry operator");

    HamSign sign;
    for (;;) {
      ManualSign segment = parse_segment();
      sign.segments.push_back(std::move(segment));
      if (at_end()) break;
      const Symbol s = peek();
      if (s == S::plus) {
        ++pos_;
        if (at_end_ignoring_punctuation()) fail(index(), "expected a sign segment after hamplus, found end of input");
        note(index() - 1, "top-level hamplus read as a compound of two sign segments");
        continue;
      }
      if (is_closer(s)) fail(index(), quoted(s) + " without a matching opening bracket: expected " + quoted(opener_of(s)) + " before it");
      fail(index(), "hammetaalt outside hamaltbegin ... hamaltend");
    }
    sign.notes = std::move(notes_);
    sign.symbol_count = static_cast<int>(sym_.size());
    return sign;
  }

 private:
  std::span<const Symbol> sym_;
  ParseOptions options_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  std::vector<ParseNote> notes_;

  bool at_end() const { return pos_ >= sym_.size(); }
  bool at_end_ignoring_punctuation() const {
    for (std::size_t i = pos_; i < sym_.size(); ++i)
      if (symbol_class(sym_[i]) != C::punctuation) return false;
    return true;
  }
  Symbol peek(std::size_t ahead = 0) const { return sym_[pos_ + ahead]; }
  bool has(std::size_t ahead = 0) const { return pos_ + ahead < sym_.size(); }
  C peek_class(std::size_t ahead = 0) const { return symbol_class(sym_[pos_ + ahead]); }
  bool next_is(C c, std::size_t ahead = 0) const { return has(ahead) && peek_class(ahead) == c; }
  int index() const { return static_cast<int>(pos_); }

  void note(int at, std::string text) { notes_.push_back({at, std::move(text)}); }

  // Lenient accepts with a note saying what it did; strict rejects.
  void tolerate(int at, const std::string& problem, const std::string& lenient_action = {}) {
    if (options_.strict) fail(at, problem);
    note(at, lenient_action.empty() ? problem : problem + ": " + lenient_action);
  }

  std::string found() const { return at_end() ? "end of input" : quoted(peek()); }

  // ---- segment --------------------------------------------------------------------------------

  ManualSign parse_segment() {
    ManualSign segment;
    segment.first_symbol = index();
    parse_symmetry_prefix(segment);
    const int posture_start = index();
    std::vector<Element> elements;
    parse_list(elements);
    build_segment(segment, std::move(elements), posture_start);
    return segment;
  }

  void parse_symmetry_prefix(ManualSign& segment) {
    Symmetry& sym = segment.symmetry;
    while (!at_end()) {
      const Symbol s = peek();
      const C c = peek_class();
      if (s == S::symmpar || s == S::symmlr) {
        if (sym.kind != SymmetryKind::none) note(index(), "second symmetry operator replaces the first");
        sym.kind = s == S::symmpar ? SymmetryKind::parallel : SymmetryKind::mirrored_lr;
      } else if (s == S::nonipsi) {
        sym.non_ipsilateral = true;
      } else if (s == S::alternatingmotion) {
        sym.alternating = true;
      } else if (c == C::size_modifier && sym.kind != SymmetryKind::none) {
        apply_size(sym.size, s);
      } else if (c == C::manner_modifier && sym.kind != SymmetryKind::none) {
        apply_manner(sym.manner, s);
      } else if (c == C::finger_bending && sym.kind != SymmetryKind::none && has(1) &&
                 peek_class(1) != C::handshape && peek_class(1) != C::finger_bending &&
                 peek_class(1) != C::thumb_modifier) {
        // Lexicons write a bending symbol right after the operator with no handshape to modify;
        // its meaning there is not defined by the standard, so it is kept as a note only.
        note(index(), quoted(s) + " after the symmetry operator ignored");
      } else if (s == S::version40 || c == C::punctuation) {
        // Version tag and stray punctuation carry nothing for the model.
      } else {
        break;
      }
      ++pos_;
    }
    if (!at_end() && peek() == S::nondominant) {
      segment.nondominant_only = true;
      ++pos_;
    }
  }

  // Reads elements until the end of input or a symbol that ends the enclosing construct
  // (closing bracket, hamplus, hammetaalt), which is left unconsumed.
  Stop parse_list(std::vector<Element>& out) {
    while (!at_end()) {
      const Symbol s = peek();
      const C c = peek_class();
      if (is_closer(s)) return Stop::closer;
      if (s == S::plus) return Stop::plus;
      if (s == S::metaalt) return Stop::metaalt;
      if (is_opener(s)) {
        out.push_back(parse_group());
        continue;
      }
      switch (c) {
        case C::thumb_modifier:
        case C::finger_bending:
          if (!modifiers_reach_handshape()) {
            std::size_t k = pos_;
            while (k < sym_.size() && (symbol_class(sym_[k]) == C::thumb_modifier || symbol_class(sym_[k]) == C::finger_bending)) ++k;
            tolerate(index(), "expected a handshape after " + quoted(s) + ", found " +
                                  (k < sym_.size() ? quoted(sym_[k]) : std::string("end of input")),
                     "modifier ignored");
            ++pos_;
            break;
          }
          out.push_back(leaf(read_handshape()));
          break;
        case C::handshape: out.push_back(leaf(read_handshape())); break;
        case C::extended_finger_direction:
        case C::palm_direction: out.push_back(leaf(read_orientation())); break;
        case C::location_site:
        case C::finger:
        case C::finger_part:
        case C::location_side: out.push_back(leaf(read_location())); break;
        case C::contact: out.push_back(read_contact()); break;
        case C::straight_motion:
        case C::circular_motion:
        case C::wrist_motion:
        case C::finger_play:
        case C::other_motion: out.push_back(leaf(read_motion())); break;
        case C::replacement: out.push_back(read_replacement()); break;
        case C::repetition: out.push_back(leaf(read_repetition())); break;
        case C::arc:
        case C::ellipse:
        case C::path_modifier:
        case C::spiral_modifier:
        case C::size_modifier:
        case C::manner_modifier:
        case C::circle_clock: attach_modifier(out); break;
        case C::coreference: {
          Element e;
          e.kind = ElementKind::coreference;
          e.symbol_index = index();
          ++pos_;
          out.push_back(std::move(e));
          break;
        }
        case C::two_handed: read_two_handed_inside(out); break;
        case C::annotation: read_annotation(out); break;
        case C::punctuation: ++pos_; break;
        case C::structure:
          if (s == S::between) {
            tolerate(index(), "hambetween not between two symbols of the same class", "ignored");
            ++pos_;
            break;
          }
          fail(index(), "unexpected " + quoted(s));
      }
    }
    return Stop::end;
  }

  template <class T>
  static Element leaf(T value) {
    Element e;
    if constexpr (std::is_same_v<T, Handshape>) e.kind = ElementKind::handshape;
    if constexpr (std::is_same_v<T, Orientation>) e.kind = ElementKind::orientation;
    if constexpr (std::is_same_v<T, Location>) e.kind = ElementKind::location;
    if constexpr (std::is_same_v<T, Motion>) e.kind = ElementKind::motion;
    if constexpr (std::is_same_v<T, Repetition>) e.kind = ElementKind::repetition;
    e.symbol_index = value.symbol_index;
    e.value = std::move(value);
    return e;
  }

  // ---- groups ---------------------------------------------------------------------------------

  Element parse_group() {
    const int open_index = index();
    const Symbol opener = peek();
    if (++depth_ > kMaxGroupDepth) fail(open_index, "brackets nested deeper than " + std::to_string(kMaxGroupDepth));
    ++pos_;
    std::vector<std::vector<Element>> branches(1);
    std::vector<bool> branch_nondominant(1, false);
    for (;;) {
      if (!at_end() && peek() == S::nondominant) {
        branch_nondominant.back() = true;
        ++pos_;
      }
      const Stop stop = parse_list(branches.back());
      if (stop == Stop::end) {
        tolerate(open_index, quoted(opener) + " is never closed: expected " + quoted(closer_of(opener)), "closed at the end");
        break;
      }
      const Symbol s = peek();
      if (stop == Stop::closer) {
        if (s != closer_of(opener))
          tolerate(index(), quoted(opener) + " at symbol " + std::to_string(open_index) + " closed by " + quoted(s) +
                                ": expected " + quoted(closer_of(opener)));
        ++pos_;
        break;
      }
      if (stop == Stop::metaalt && opener != S::altbegin) fail(index(), "hammetaalt outside hamaltbegin ... hamaltend");
      if (stop == Stop::plus && opener == S::altbegin) fail(index(), "hamplus inside hamaltbegin: expected hammetaalt");
      ++pos_;
      branches.emplace_back();
      branch_nondominant.push_back(false);
    }
    --depth_;

    Element group;
    group.symbol_index = open_index;
    if (branches.size() > 1) {
      group.kind = opener == S::altbegin ? ElementKind::alternatives : ElementKind::hand_pair;
      if (opener != S::altbegin && opener != S::parbegin)
        tolerate(open_index, "hamplus inside " + quoted(opener), "read as a pair of hands");
      if (group.kind == ElementKind::hand_pair && branches.size() > 2)
        tolerate(open_index, "hand pair with " + std::to_string(branches.size()) + " branches: expected 2");
      for (std::size_t b = 0; b < branches.size(); ++b) {
        Element branch;
        branch.kind = ElementKind::sequence;
        branch.symbol_index = open_index;
        branch.nondominant = branch_nondominant[b];
        branch.children = std::move(branches[b]);
        group.children.push_back(std::move(branch));
      }
      return group;
    }
    group.kind = opener == S::parbegin ? ElementKind::parallel
                 : opener == S::seqbegin ? ElementKind::sequence
                 : opener == S::fusionbegin ? ElementKind::fusion
                                            : ElementKind::alternatives;
    group.nondominant = branch_nondominant[0];
    group.children = std::move(branches[0]);
    if (group.children.empty()) tolerate(open_index, "empty " + quoted(opener) + " group");
    return group;
  }

  // ---- handshape ------------------------------------------------------------------------------

  // True when the thumb / bending modifiers at the cursor are followed by a basic handshape.
  bool modifiers_reach_handshape() const {
    std::size_t k = pos_;
    while (k < sym_.size() && (symbol_class(sym_[k]) == C::thumb_modifier || symbol_class(sym_[k]) == C::finger_bending)) ++k;
    return k < sym_.size() && symbol_class(sym_[k]) == C::handshape;
  }

  HandshapeForm read_handshape_form() {
    HandshapeForm form;
    // Bending written before the basic form (seen in lexicons) applies to it.
    std::optional<FingerBending> early_bending;
    std::optional<ThumbModifier> early_thumb;
    while (!at_end() && (peek_class() == C::finger_bending || peek_class() == C::thumb_modifier)) {
      if (!next_is(C::handshape, 1) && !next_is(C::finger_bending, 1) && !next_is(C::thumb_modifier, 1))
        fail(index(), "expected a handshape after " + quoted(peek()) + ", found " +
                          (has(1) ? quoted(peek(1)) : std::string("end of input")));
      note(index(), quoted(peek()) + " written before the basic handshape");
      if (peek_class() == C::finger_bending) early_bending = finger_bending(peek());
      else early_thumb = thumb_position(peek());
      ++pos_;
    }
    if (at_end() || peek_class() != C::handshape) fail(index(), "expected a handshape, found " + found());
    form.basic = basic_handshape(peek());
    ++pos_;
    form.bending = early_bending;
    if (early_thumb) form.thumb = *early_thumb;
    while (!at_end()) {
      const C c = peek_class();
      const Symbol s = peek();
      if (c == C::thumb_modifier) {
        form.thumb = thumb_position(s);
      } else if (c == C::finger_bending) {
        if (!form.finger_modifiers.empty() && !form.finger_modifiers.back().bending)
          form.finger_modifiers.back().bending = finger_bending(s);
        else if (!form.bending)
          form.bending = finger_bending(s);
        else
          form.finger_modifiers.push_back({FingerSet{}, finger_bending(s), std::nullopt});
      } else if (c == C::finger) {
        // A finger after a bending or part opens a new finger modifier; consecutive fingers group.
        if (form.finger_modifiers.empty() || form.finger_modifiers.back().bending ||
            form.finger_modifiers.back().part)
          form.finger_modifiers.emplace_back();
        form.finger_modifiers.back().fingers.add(finger(s));
      } else if (c == C::finger_part && !form.finger_modifiers.empty() && !form.finger_modifiers.back().part) {
        form.finger_modifiers.back().part = finger_part(s);
      } else {
        break;
      }
      ++pos_;
    }
    return form;
  }

  Handshape read_handshape() {
    Handshape hs;
    hs.symbol_index = index();
    hs.form = read_handshape_form();
    if (has(1) && peek() == S::between &&
        (next_is(C::handshape, 1) || next_is(C::finger_bending, 1) || next_is(C::thumb_modifier, 1))) {
      ++pos_;
      hs.between = read_handshape_form();
    } else if (has(1) && peek() == S::between && next_is(C::finger, 1)) {
      // "between thumb ceeall": the in-between shape names its selected fingers first.
      std::size_t k = pos_ + 1;
      while (k < sym_.size() && symbol_class(sym_[k]) == C::finger) ++k;
      if (k < sym_.size() && symbol_class(sym_[k]) == C::handshape) {
        FingerModifier selected;
        for (std::size_t f = pos_ + 1; f < k; ++f) selected.fingers.add(finger(sym_[f]));
        pos_ = k;
        hs.between = read_handshape_form();
        hs.between->finger_modifiers.insert(hs.between->finger_modifiers.begin(), selected);
      }
    }
    return hs;
  }

  // ---- orientation ----------------------------------------------------------------------------

  // Reads one direction of a family, merging an adjacent symbol into a three-axis diagonal.
  Direction read_merged_direction(C family, Direction (*decode)(Symbol), bool& relative) {
    Direction d = decode(peek());
    ++pos_;
    for (;;) {
      if (!at_end() && peek() == S::orirelative) {
        relative = true;
        ++pos_;
        continue;
      }
      if (next_is(family)) {
        if (auto merged = merge_directions(d, decode(peek()))) {
          d = *merged;
          ++pos_;
          continue;
        }
      }
      return d;
    }
  }

  Orientation read_orientation() {
    Orientation o;
    o.symbol_index = index();
    if (peek_class() == C::extended_finger_direction) {
      o.extended_finger = read_merged_direction(C::extended_finger_direction, extended_finger_direction,
                                                o.extended_finger_relative);
      if (has(1) && peek() == S::between && next_is(C::extended_finger_direction, 1)) {
        ++pos_;
        o.extended_finger_between =
            read_merged_direction(C::extended_finger_direction, extended_finger_direction, o.extended_finger_relative);
      } else if (next_is(C::extended_finger_direction)) {
        note(index(), "second extended finger direction read as an in-between direction");
        o.extended_finger_between =
            read_merged_direction(C::extended_finger_direction, extended_finger_direction, o.extended_finger_relative);
      }
    }
    if (next_is(C::palm_direction)) {
      o.palm = palm_direction(peek());
      ++pos_;
      if (!at_end() && peek() == S::orirelative) {
        o.palm_relative = true;
        ++pos_;
      }
      if (has(1) && peek() == S::between && next_is(C::palm_direction, 1)) {
        pos_ += 2;
        o.palm_between = palm_direction(sym_[pos_ - 1]);
        if (!at_end() && peek() == S::orirelative) {
          o.palm_relative = true;
          ++pos_;
        }
      }
    }
    return o;
  }

  // ---- location -------------------------------------------------------------------------------

  // Reads site, fingers, finger part and side symbols (any order) into one point.
  SitePoint read_site_point(int start) {
    SitePoint point;
    bool have_site = false;
    while (!at_end()) {
      const C c = peek_class();
      const Symbol s = peek();
      if (c == C::location_site) {
        if (have_site) break;  // a second site starts a new location
        point.site = body_site(s);
        have_site = true;
      } else if (c == C::finger) {
        if (!have_site) {
          point.site = Site::fingers;
          have_site = true;
        }
        point.fingers.add(finger(s));
      } else if (c == C::finger_part) {
        if (point.finger_part) break;
        if (!have_site) {
          point.site = Site::fingers;
          have_site = true;
        }
        point.finger_part = finger_part(s);
      } else if (c == C::location_side) {
        point.side = s == S::lrbeside ? Side::beside : Side::dominant_side;
      } else {
        break;
      }
      ++pos_;
    }
    if (!have_site) fail(start, "expected a location site (e.g. hamchest) with " + quoted(sym_[static_cast<std::size_t>(start)]));
    return point;
  }

  Location read_location() {
    Location loc;
    loc.symbol_index = index();
    const SitePoint point = read_site_point(index());
    loc.site = point.site;
    loc.fingers = point.fingers;
    loc.finger_part = point.finger_part;
    loc.side = point.side;
    if (has(1) && peek() == S::between && is_location_symbol(peek_class(1))) {
      ++pos_;
      loc.between = read_site_point(index());
    }
    return loc;
  }

  Element read_contact() {
    Element e;
    e.kind = ElementKind::contact;
    e.symbol_index = index();
    e.value = Contact{proximity(peek()), index()};
    ++pos_;
    return e;
  }

  // ---- motion ---------------------------------------------------------------------------------

  void read_motion_modifiers(Motion& m) {
    while (!at_end()) {
      const Symbol s = peek();
      const C c = peek_class();
      if (c == C::arc) m.arc = arc_direction(s);
      else if (s == S::wavy) m.path = PathShape::wavy;
      else if (s == S::zigzag) m.path = PathShape::zigzag;
      else if (c == C::ellipse)
        m.ellipse = s == S::ellipseh ? Ellipse::horizontal
                    : s == S::ellipsev ? Ellipse::vertical
                    : s == S::ellipseur ? Ellipse::up_right
                                        : Ellipse::up_left;
      else if (c == C::spiral_modifier) m.spiral = s == S::increasing ? Spiral::increasing : Spiral::decreasing;
      else if (c == C::size_modifier) apply_size(m.size, s);
      else if (c == C::manner_modifier) apply_manner(m.manner, s);
      else if (s == S::clockfull) m.clock_full = true;
      else if (c == C::circle_clock) {
        if (!m.clock_start) m.clock_start = clock_position(s);
        else m.clock_end = clock_position(s);
      } else break;
      ++pos_;
    }
  }

  Motion read_motion() {
    Motion m;
    m.symbol_index = index();
    const Symbol s = peek();
    const C c = peek_class();
    if (c == C::straight_motion) {
      bool unused_relative = false;
      m.direction = read_merged_direction(C::straight_motion, straight_direction, unused_relative);
      if (unused_relative) note(m.symbol_index, "hamorirelative after a movement ignored");
      if (has(1) && peek() == S::between && next_is(C::straight_motion, 1)) {
        ++pos_;
        m.direction_between = read_merged_direction(C::straight_motion, straight_direction, unused_relative);
      }
    } else if (c == C::circular_motion) {
      m.kind = MotionKind::circle;
      m.direction = circle_axis(s);
      ++pos_;
      if (has(1) && peek() == S::between && next_is(C::circular_motion, 1)) {
        m.direction_between = circle_axis(peek(1));
        pos_ += 2;
      }
    } else if (c == C::finger_play) {
      m.kind = MotionKind::finger_play;
      ++pos_;
      while (next_is(C::finger)) {
        m.fingers.add(finger(peek()));
        ++pos_;
      }
    } else {
      switch (s) {
        case S::nodding: m.kind = MotionKind::nodding; break;
        case S::swinging: m.kind = MotionKind::swinging; break;
        case S::twisting: m.kind = MotionKind::twisting; break;
        case S::stircw: m.kind = MotionKind::stirring_cw; break;
        case S::stirccw: m.kind = MotionKind::stirring_ccw; break;
        case S::nomotion: m.kind = MotionKind::none; break;
        case S::movecross: m.kind = MotionKind::crossing; break;
        case S::moveX: m.kind = MotionKind::x_shaped; break;
        default: m.kind = MotionKind::wrist_bend; break;
      }
      ++pos_;
    }
    read_motion_modifiers(m);
    if (m.kind == MotionKind::straight && !m.direction_between && has(1) && peek() == S::between &&
        next_is(C::straight_motion, 1)) {
      ++pos_;
      bool unused_relative = false;
      m.direction_between = read_merged_direction(C::straight_motion, straight_direction, unused_relative);
      read_motion_modifiers(m);
    }
    read_motion_target(m);
    return m;
  }

  // A location and/or contact written right after a motion is where it ends.
  void read_motion_target(Motion& m) {
    if (m.kind == MotionKind::none) return;
    if (!at_end() && is_location_symbol(peek_class())) m.target = read_location();
    if (next_is(C::contact)) {
      m.target_contact = proximity(peek());
      ++pos_;
    }
  }

  Element read_replacement() {
    Motion m;
    m.kind = MotionKind::replacement;
    m.symbol_index = index();
    ++pos_;
    read_motion_modifiers(m);  // e.g. "hamreplace hamincreasing": the change grows
    if (!at_end() && is_opener(peek())) {
      // New values given per hand (or in sequence) in a group after the symbol.
      Element e = leaf(std::move(m));
      e.children.push_back(parse_group());
      return e;
    }
    bool any = false;
    for (;;) {
      if (at_end()) break;
      const C c = peek_class();
      if (!m.new_handshape && (c == C::handshape || c == C::thumb_modifier || c == C::finger_bending)) {
        m.new_handshape = read_handshape();
      } else if (!m.new_orientation && (c == C::extended_finger_direction || c == C::palm_direction)) {
        m.new_orientation = read_orientation();
      } else if (!m.target && is_location_symbol(c)) {
        m.target = read_location();
      } else {
        break;
      }
      any = true;
    }
    if (!any)
      fail(index(), "expected a handshape, orientation or location after hamreplace, found " + found());
    read_motion_modifiers(m);
    if (next_is(C::contact)) {
      m.target_contact = proximity(peek());
      ++pos_;
    }
    return leaf(std::move(m));
  }

  Repetition read_repetition() {
    Repetition r;
    r.symbol_index = index();
    switch (peek()) {
      case S::repeatfromstart: r.kind = RepetitionKind::from_start; break;
      case S::repeatfromstartseveral: r.kind = RepetitionKind::from_start_several; break;
      case S::repeatcontinue: r.kind = RepetitionKind::continued; break;
      case S::repeatcontinueseveral: r.kind = RepetitionKind::continued_several; break;
      default: r.kind = RepetitionKind::reversed; break;
    }
    ++pos_;
    if (!at_end() && peek() == S::alternatingmotion) {
      r.alternating = true;
      ++pos_;
    }
    if (next_is(C::straight_motion)) r.offset = read_motion();
    return r;
  }

  // Size, speed, arc ... written after a group or contact modify the last motion before them.
  void attach_modifier(std::vector<Element>& out) {
    const int at = index();
    for (auto it = out.rbegin(); it != out.rend(); ++it) {
      if (Motion* m = std::get_if<Motion>(&it->value)) {
        read_motion_modifiers(*m);
        return;
      }
      if (Repetition* r = std::get_if<Repetition>(&it->value); r && r->offset) {
        read_motion_modifiers(*r->offset);
        return;
      }
      if (Motion* m = last_motion_in(*it)) {
        note(at, quoted(peek()) + " after a group applies to its last motion");
        read_motion_modifiers(*m);
        return;
      }
    }
    tolerate(at, "expected a motion before the " + std::string(symbol_class_name(peek_class())) + " " + quoted(peek()),
             "modifier ignored");
    ++pos_;
  }

  static Motion* last_motion_in(Element& e) {
    for (auto it = e.children.rbegin(); it != e.children.rend(); ++it) {
      if (Motion* m = std::get_if<Motion>(&it->value)) return m;
      if (Motion* m = last_motion_in(*it)) return m;
    }
    return nullptr;
  }

  void read_two_handed_inside(std::vector<Element>& out) {
    const Symbol s = peek();
    if (s == S::alternatingmotion) {
      // Applies to the repetition or motion it follows (searching into a group just closed).
      for (auto it = out.rbegin(); it != out.rend(); ++it) {
        if (Repetition* r = std::get_if<Repetition>(&it->value)) {
          r->alternating = true;
          ++pos_;
          return;
        }
        Motion* m = std::get_if<Motion>(&it->value);
        if (!m) m = last_motion_in(*it);
        if (m) {
          m->alternating = true;
          ++pos_;
          return;
        }
      }
      note(index(), "hamalternatingmotion without a motion before it");
      ++pos_;
      return;
    }
    if (s == S::nondominant && next_is(C::annotation, 1) && peek(1) == S::etc) {
      // "hamnondominant hametc": the other hand's shape is left open.
      Element e;
      e.kind = ElementKind::unspecified;
      e.nondominant = true;
      e.symbol_index = index();
      pos_ += 2;
      out.push_back(std::move(e));
      return;
    }
    fail(index(), quoted(s) + " must stand at the start of a sign or of a hand-pair branch");
  }

  void read_annotation(std::vector<Element>& out) {
    const Symbol s = peek();
    if (s == S::etc) {
      Element e;
      e.kind = ElementKind::unspecified;
      e.symbol_index = index();
      out.push_back(std::move(e));
    } else if (s == S::orirelative) {
      Orientation* o = out.empty() ? nullptr : std::get_if<Orientation>(&out.back().value);
      if (!o) fail(index(), "expected an extended finger direction or palm orientation before hamorirelative");
      (o->palm ? o->palm_relative : o->extended_finger_relative) = true;
    } else {
      note(index(), quoted(s) + " ignored");
    }
    ++pos_;
  }

  // ---- segment assembly -----------------------------------------------------------------------

  static bool is_posture_kind(ElementKind k) {
    return k == ElementKind::handshape || k == ElementKind::orientation || k == ElementKind::location ||
           k == ElementKind::contact || k == ElementKind::unspecified;
  }

  // A group belongs to the posture when every leaf in it is a handshape, orientation, location,
  // contact or left open.
  static bool is_posture_group(const Element& e) {
    if (e.kind != ElementKind::hand_pair && e.kind != ElementKind::alternatives && e.kind != ElementKind::sequence)
      return false;
    for (const Element& child : e.children) {
      if (child.kind == ElementKind::sequence || child.kind == ElementKind::alternatives ||
          child.kind == ElementKind::hand_pair) {
        if (!is_posture_group(child)) return false;
      } else if (!is_posture_kind(child.kind)) {
        return false;
      }
    }
    return true;
  }

  // "hamseqbegin [contact] location hamseqend" after a location: which part of the hand is there.
  static bool is_hand_part_sequence(const Element& e) {
    if (e.kind != ElementKind::sequence || e.children.empty() || e.children.size() > 2) return false;
    if (e.children.size() == 2 && e.children[0].kind != ElementKind::contact) return false;
    return e.children.back().kind == ElementKind::location;
  }

  static void apply_hand_part(Location& at, const Element& seq) {
    const Location& part = *seq.children.back().location();
    at.hand_part = static_cast<const SitePoint&>(part);
    if (seq.children.size() == 2) at.proximity = seq.children[0].contact()->proximity;
  }

  // Fills one hand's fields from a posture branch; a field already set is kept.
  void fill_hand(Posture& p, const Element& e, bool dominant, std::optional<Proximity>& pending) {
    auto set = [&](auto& per_hand, const auto& v) {
      auto& slot = dominant ? per_hand.dominant : per_hand.nondominant;
      if (!slot) slot = v;
      else note(e.symbol_index, "second value for the same hand in the posture ignored");
    };
    switch (e.kind) {
      case ElementKind::handshape: set(p.handshape, *e.handshape()); break;
      case ElementKind::orientation: {
        // A palm-only orientation completes one written with only the finger direction
        // ("hamextfingerdo hamparbegin hampalml hamplus hampalmr hamparend").
        auto& slot = dominant ? p.orientation.dominant : p.orientation.nondominant;
        const Orientation& o = *e.orientation();
        if (slot && !slot->palm && o.palm && !o.extended_finger) {
          slot->palm = o.palm;
          slot->palm_between = o.palm_between;
          slot->palm_relative = o.palm_relative;
        } else {
          set(p.orientation, o);
        }
        break;
      }
      case ElementKind::location: {
        Location loc = *e.location();
        if (pending) {
          loc.proximity = pending;
          loc.contact_before = true;
          pending.reset();
        }
        set(p.location, loc);
        break;
      }
      case ElementKind::contact: {
        auto& slot = dominant ? p.location.dominant : p.location.nondominant;
        if (slot && !slot->proximity) slot->proximity = e.contact()->proximity;
        else pending = e.contact()->proximity;
        break;
      }
      case ElementKind::unspecified:
        if (!dominant || e.nondominant) p.nondominant_unspecified = true;
        break;
      case ElementKind::alternatives:
        note(e.symbol_index, "alternatives in the posture: the first one is used");
        if (!e.children.empty()) fill_hand(p, e.children.front(), dominant, pending);
        break;
      case ElementKind::sequence: {
        auto& slot = dominant ? p.location.dominant : p.location.nondominant;
        if (slot && !slot->hand_part && is_hand_part_sequence(e)) {
          apply_hand_part(*slot, e);
          break;
        }
        for (const Element& child : e.children) fill_hand(p, child, dominant, pending);
        break;
      }
      default: break;
    }
  }

  void build_segment(ManualSign& segment, std::vector<Element> elements, int posture_start) {
    Posture& p = segment.posture;
    std::optional<Proximity> pending;
    std::size_t i = 0;
    for (; i < elements.size(); ++i) {
      const Element& e = elements[i];
      if (e.kind == ElementKind::hand_pair && is_posture_group(e)) {
        const bool first_is_nondominant = e.children.front().nondominant;
        for (std::size_t b = 0; b < e.children.size() && b < 2; ++b) {
          const bool dominant = (b == 0) != first_is_nondominant;
          fill_hand(p, e.children[b], dominant, pending);
        }
        continue;
      }
      if (p.location.dominant && !p.location.dominant->hand_part && is_hand_part_sequence(e)) {
        apply_hand_part(*p.location.dominant, e);
        continue;
      }
      if (e.kind == ElementKind::alternatives && is_posture_group(e)) {
        fill_hand(p, e, true, pending);
        continue;
      }
      if (!is_posture_kind(e.kind)) break;
      // A second handshape (or orientation) after the posture's own starts the actions.
      if (e.kind == ElementKind::handshape && p.handshape.dominant) break;
      if (e.kind == ElementKind::orientation && p.orientation.dominant) break;
      if (e.kind == ElementKind::location && p.location.dominant && p.location.nondominant) break;
      if (e.kind == ElementKind::contact) {
        const bool pair_location = p.location.dominant && p.location.nondominant;
        const bool has_location = p.location.dominant.has_value();
        const bool location_follows = i + 1 < elements.size() && elements[i + 1].kind == ElementKind::location;
        if (pair_location || (!has_location && !location_follows && p.handshape.nondominant)) {
          p.hands_contact = e.contact()->proximity;
          continue;
        }
        if (has_location && p.location.dominant->proximity && !location_follows) break;
      }
      if (e.kind == ElementKind::location && p.location.dominant) {
        // A second site names where on the other hand (hand constellation).
        Location other = *e.location();
        other.nondominant_hand = true;
        if (pending) {
          other.proximity = pending;
          other.contact_before = true;
          pending.reset();
        }
        p.location.nondominant = other;
        continue;
      }
      fill_hand(p, e, true, pending);
    }
    if (pending) p.hands_contact = pending;
    // A finger direction written once before per-hand palms holds for both hands.
    if (p.orientation.dominant && p.orientation.nondominant && !p.orientation.nondominant->extended_finger)
      p.orientation.nondominant->extended_finger = p.orientation.dominant->extended_finger;
    // Lexicons omit the handshape when it carries over (an orientation is then still written);
    // a segment with neither is not a sign.
    if (!p.handshape.dominant && !p.handshape.nondominant) {
      if (!p.orientation.dominant && !p.orientation.nondominant)
        fail(posture_start, "expected a handshape (e.g. hamflathand) at the start of the sign, found " +
                                (posture_start < static_cast<int>(sym_.size())
                                     ? quoted(sym_[static_cast<std::size_t>(posture_start)])
                                     : std::string("end of input")));
      tolerate(posture_start, "sign without a handshape: expected one before the orientation");
    }
    segment.actions.assign(std::make_move_iterator(elements.begin() + static_cast<std::ptrdiff_t>(i)),
                           std::make_move_iterator(elements.end()));
    attach_hand_parts(segment.actions);
    for (Element& e : segment.actions) locations_to_targets(e);
  }

  // In the actions too, "hamseqbegin [contact] location hamseqend" right after a location (or a
  // movement to one) names the part of the hand that gets there, as in the posture; read alone it
  // would be a place on the other hand ("…, hamchin, (touch, thumb tip)" sent the hand to the
  // resting hand's thumb at the hip).
  static void attach_hand_parts(std::vector<Element>& list) {
    for (std::size_t k = 0; k < list.size(); ++k) {
      attach_hand_parts(list[k].children);
      if (k + 1 >= list.size() || !is_hand_part_sequence(list[k + 1])) continue;
      Location* at = std::get_if<Location>(&list[k].value);
      Motion* motion = std::get_if<Motion>(&list[k].value);
      if (!at && motion && motion->target) at = &*motion->target;
      if (!at || at->hand_part) continue;
      apply_hand_part(*at, list[k + 1]);
      if (motion && at->proximity) motion->target_contact = at->proximity;
      list.erase(list.begin() + static_cast<std::ptrdiff_t>(k + 1));
    }
  }

  // In the action part a bare location means "move the hand there".
  static void locations_to_targets(Element& e) {
    if (e.kind == ElementKind::location) {
      Motion m;
      m.kind = MotionKind::to_location;
      m.symbol_index = e.symbol_index;
      m.target = *e.location();
      m.target_contact = m.target->proximity;
      e.kind = ElementKind::motion;
      e.value = std::move(m);
      return;
    }
    for (Element& child : e.children) locations_to_targets(child);
  }
};

}  // namespace

std::vector<Symbol> symbols_from_unicode(std::string_view text) {
  std::vector<Symbol> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const int at = static_cast<int>(out.size());
    if (out.size() >= kMaxSignSymbols)
      fail(at, "sign too long: more than " + std::to_string(kMaxSignSymbols) + " symbols");
    char32_t cp = 0;
    if (!utf8::decode(text, i, cp)) fail(at, "invalid UTF-8 at byte " + std::to_string(i) + ": expected a HamNoSys symbol");
    // Tabs and line breaks separate like spaces.
    if (cp == U'\t' || cp == U'\n' || cp == U'\r') continue;
    const auto symbol = symbol_from_codepoint(cp);
    if (!symbol) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(cp));
      fail(at, std::string("unknown code point ") + hex + ": expected a HamNoSys symbol");
    }
    out.push_back(*symbol);
  }
  return out;
}

std::vector<Symbol> symbols_from_names(std::string_view names) {
  std::vector<Symbol> out;
  std::size_t i = 0;
  auto is_sep = [](char c) { return c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (i < names.size()) {
    while (i < names.size() && is_sep(names[i])) ++i;
    std::size_t j = i;
    while (j < names.size() && !is_sep(names[j])) ++j;
    if (j == i) break;
    const int at = static_cast<int>(out.size());
    if (out.size() >= kMaxSignSymbols)
      fail(at, "sign too long: more than " + std::to_string(kMaxSignSymbols) + " symbols");
    const std::string_view name = names.substr(i, j - i);
    const auto symbol = symbol_from_name(name);
    if (!symbol) {
      const std::string shown = name.size() > 40 ? std::string(name.substr(0, 40)) + "..." : std::string(name);
      fail(at, "unknown symbol name '" + shown + "': expected a HamNoSys symbol name such as hamflathand");
    }
    out.push_back(*symbol);
    i = j;
  }
  return out;
}

std::optional<Site> site_of_symbol(Symbol symbol) {
  if (symbol_class(symbol) != SymbolClass::location_site) return std::nullopt;
  return body_site(symbol);
}

HamSign parse_hamnosys(std::span<const Symbol> symbols, const ParseOptions& options) {
  HamSign sign = Parser(symbols, options).parse();
  check_sign_limits(sign);  // no later stage sees a sign that asks for unbounded work
  return sign;
}

HamSign parse_hamnosys_unicode(std::string_view utf8, const ParseOptions& options) {
  const std::vector<Symbol> symbols = symbols_from_unicode(utf8);
  return parse_hamnosys(symbols, options);
}

HamSign parse_hamnosys_names(std::string_view names, const ParseOptions& options) {
  const std::vector<Symbol> symbols = symbols_from_names(names);
  return parse_hamnosys(symbols, options);
}

}  // namespace gestura::sign
