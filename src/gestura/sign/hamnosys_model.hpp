#pragma once
// The typed model of a HamNoSys 4 manual sign. A parsed sign is a posture (the hands' initial
// handshape, orientation and location, per hand) followed by a tree of actions (motions,
// replacements, contacts, repetitions, sequential / parallel / fused groups). Every element keeps
// the index of the symbol it came from so later stages can report errors against the notation.
//
// Frames: directions are the signer's (u = up, l = signer's left, o = out, away from the body).
// direction_vector() (phonology_direction.hpp) maps them to the avatar frame (+Y up, the avatar
// faces +Z, its left is +X).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura::sign {

// ---- directions -------------------------------------------------------------------------------

// Directions, handshapes, thumb positions, bendings and fingers are the phonology's own
// (phonology_direction.hpp, phonology_handshape.hpp): one vocabulary from the parser to the
// performer. The 26 directions: 6 axes, 12 two-axis diagonals, 8 three-axis diagonals; the font
// has symbols for 18 of them, and the 8 three-axis ones are written as two adjacent symbols
// (e.g. hamextfingeruo + hamextfingerol = up-out-left).
using gestura::BasicHandshape;
using gestura::Direction;
using gestura::Finger;
using gestura::FingerBending;
using gestura::ThumbModifier;

using gestura::DirectionComponents;
// Two adjacent direction symbols that share an axis and differ in the others merge into one
// three-axis diagonal (uo + ol = uol); anything else does not merge.
std::optional<Direction> merge_directions(Direction a, Direction b);

// ---- handshape --------------------------------------------------------------------------------

// A set of fingers as bits (1 << Finger): the layout of the phonology's FingerSet (finger_bit).
struct FingerSet {
  std::uint8_t bits = 0;
  bool empty() const { return bits == 0; }
  bool contains(Finger f) const { return (bits >> static_cast<int>(f)) & 1U; }
  void add(Finger f) { bits = static_cast<std::uint8_t>(bits | (1U << static_cast<int>(f))); }
  bool operator==(const FingerSet&) const = default;
};

enum class FingerPart : std::uint8_t { tip, nail, pad, mid_joint, base, side };

// Bending (or just selection, when bending is empty) of particular fingers.
struct FingerModifier {
  FingerSet fingers;
  std::optional<FingerBending> bending;
  std::optional<FingerPart> part;  // e.g. thumb contacting the index pad in pinch forms
};

struct HandshapeForm {
  BasicHandshape basic = BasicHandshape::Fist;
  ThumbModifier thumb = ThumbModifier::Default;
  std::optional<FingerBending> bending;          // bending of all selected fingers
  std::vector<FingerModifier> finger_modifiers;  // per-finger bending / selection, in order
};

struct Handshape {
  HandshapeForm form;
  std::optional<HandshapeForm> between;  // hambetween: a shape between form and this one
  int symbol_index = -1;
};

// ---- orientation ------------------------------------------------------------------------------

// Extended finger direction plus palm orientation. Either may be absent (e.g. a replacement that
// changes only the palm). Palm orientation uses the 8 directions of the frontal plane.
struct Orientation {
  std::optional<Direction> extended_finger;
  std::optional<Direction> extended_finger_between;
  bool extended_finger_relative = false;  // hamorirelative: relative to the forearm
  std::optional<Direction> palm;
  std::optional<Direction> palm_between;
  bool palm_relative = false;
  int symbol_index = -1;
};

// ---- location ---------------------------------------------------------------------------------

enum class Site : std::uint8_t {
  // head and face
  head, head_top, forehead, eyebrows, eyes, nose, nostrils, ear, earlobe, cheek, lips, tongue,
  teeth, chin, under_chin, neck,
  // trunk
  shoulder_top, shoulders, chest, stomach, below_stomach,
  neutral_space,
  // arm
  upper_arm, elbow, elbow_inside, lower_arm, wrist_back, wrist_pulse,
  // hand
  thumb_ball, palm, hand_back, thumb_side, pinky_side,
  // fingers (with an optional finger part)
  fingers,
};

enum class SiteRegion : std::uint8_t { head, face, trunk, space, arm, hand, finger };
SiteRegion site_region(Site s);
std::string_view site_name(Site s);

// Left/right placement relative to a site. Centre is the default; hamlrbeside is beside the site
// on the dominant side, hamlrat at the site's dominant-side instance (e.g. the right cheek).
enum class Side : std::uint8_t { centre, dominant_side, beside };

enum class Proximity : std::uint8_t { close, touch, interlocked, crossed, far, behind, brushing };

// A point the notation names by one site (and, for fingers, which fingers and which part): on the
// body, on the other hand, or on the moving hand itself (the part of it placed at a location).
struct SitePoint {
  Site site = Site::neutral_space;
  FingerSet fingers;  // when site == fingers (or a finger part on a hand site)
  std::optional<FingerPart> finger_part;
  Side side = Side::centre;
};

// A location: the point where the hand goes, and how it goes there.
struct Location : SitePoint {
  std::optional<SitePoint> between;  // hambetween: halfway between this point and that one
  // The part of the hand placed at the location, written as a bracketed sequence after it:
  // "hamchin hamseqbegin hamtouch hamfingertip hamseqend" = the fingertips touch the chin.
  std::optional<SitePoint> hand_part;
  std::optional<Proximity> proximity;  // contact symbol written with the location
  bool contact_before = false;       // the contact symbol preceded the location
  bool nondominant_hand = false;     // a site on the other hand (hand constellations)
  int symbol_index = -1;
};

// ---- actions ----------------------------------------------------------------------------------

enum class MotionKind : std::uint8_t {
  straight,       // in a direction
  circle,         // about an axis direction
  finger_play,    // fingers wiggle
  nodding,        // wrist flexion
  swinging,       // wrist side to side
  twisting,       // forearm rotation
  stirring_cw,    // wrist stirs clockwise
  stirring_ccw,
  wrist_bend,     // hamwristto*: wrist bends towards pulse/back/thumb/pinky
  replacement,    // change of handshape / orientation / location, no path
  to_location,    // targeted motion to a location
  crossing,       // hammovecross
  x_shaped,       // hammoveX
  none,           // hamnomotion: this hand holds still
};

enum class PathShape : std::uint8_t { plain, wavy, zigzag };
enum class Size : std::uint8_t { normal, small, large };
enum class Spiral : std::uint8_t { none, increasing, decreasing };
enum class Ellipse : std::uint8_t { none, horizontal, vertical, up_right, up_left };

struct Manner {
  bool fast = false, slow = false, tense = false, rest = false, halt = false;
};

struct Motion {
  MotionKind kind = MotionKind::straight;
  std::optional<Direction> direction;        // straight: where; circle: axis of rotation
  std::optional<Direction> direction_between;
  std::optional<Direction> arc;              // straight bent into an arc towards this side
  std::optional<Direction> clock_start, clock_end;  // circles: clock positions (u, ur, ...)
  bool clock_full = false;                   // full circle marker
  PathShape path = PathShape::plain;
  Ellipse ellipse = Ellipse::none;
  Spiral spiral = Spiral::none;
  Size size = Size::normal;
  Manner manner;
  FingerSet fingers;                         // finger play: which fingers
  bool alternating = false;                  // hamalternatingmotion: the hands move out of phase
  std::optional<Handshape> new_handshape;    // replacement
  std::optional<Orientation> new_orientation;
  std::optional<Location> target;            // to_location or a straight motion ending at a site
  std::optional<Proximity> target_contact;
  int symbol_index = -1;
};

enum class RepetitionKind : std::uint8_t { from_start, from_start_several, continued, continued_several, reversed };

struct Repetition {
  RepetitionKind kind = RepetitionKind::from_start;
  std::optional<Motion> offset;  // a straight motion right after the symbol displaces each repetition
  bool alternating = false;      // hamalternatingmotion: the hands repeat out of phase
  int symbol_index = -1;
};

// A contact written on its own between actions (e.g. "touch" after a motion).
struct Contact {
  Proximity proximity = Proximity::touch;
  int symbol_index = -1;
};

enum class ElementKind : std::uint8_t {
  handshape, orientation, location, contact, motion, repetition,
  sequence,      // hamseqbegin ... hamseqend: one after another
  parallel,      // hamparbegin ... hamparend: at the same time
  fusion,        // hamfusionbegin ... hamfusionend: fused into one movement
  hand_pair,     // hamparbegin dominant hamplus non-dominant hamparend
  alternatives,  // hamaltbegin a hammetaalt b hamaltend: the notation allows either
  unspecified,   // hametc: left open by the transcriber
  coreference,   // hamcoreftag / hamcorefref
};

// One node of a sign. Leaves carry one typed value; groups carry children. For hand_pair and
// alternatives each child is a sequence holding one branch. A replacement motion whose new values
// are given per hand ("hamreplace hamparbegin ... hamplus ... hamparend") carries that group as
// its one child.
struct Element {
  ElementKind kind = ElementKind::sequence;
  std::variant<std::monostate, Handshape, Orientation, Location, Contact, Motion, Repetition> value;
  std::vector<Element> children;
  bool nondominant = false;  // the branch was marked hamnondominant
  int symbol_index = -1;

  const Handshape* handshape() const { return std::get_if<Handshape>(&value); }
  const Orientation* orientation() const { return std::get_if<Orientation>(&value); }
  const Location* location() const { return std::get_if<Location>(&value); }
  const Contact* contact() const { return std::get_if<Contact>(&value); }
  const Motion* motion() const { return std::get_if<Motion>(&value); }
  const Repetition* repetition() const { return std::get_if<Repetition>(&value); }
};

// ---- sign -------------------------------------------------------------------------------------

enum class SymmetryKind : std::uint8_t { none, parallel, mirrored_lr };

struct Symmetry {
  SymmetryKind kind = SymmetryKind::none;
  bool alternating = false;      // hamalternatingmotion right after the operator
  bool non_ipsilateral = false;  // hamnonipsi
  Size size = Size::normal;      // size modifier written with the operator
  Manner manner;
};

template <class T>
struct PerHand {
  std::optional<T> dominant;
  std::optional<T> nondominant;  // only when written separately (hand pair); else follows symmetry
};

// The hands' starting configuration.
struct Posture {
  PerHand<Handshape> handshape;
  PerHand<Orientation> orientation;
  PerHand<Location> location;
  std::optional<Proximity> hands_contact;  // hand constellation: contact between the two hands
  bool nondominant_unspecified = false;    // hamnondominant hametc: other hand's shape left open
};

// One manual segment; compounds written with a top-level hamplus have several.
struct ManualSign {
  Symmetry symmetry;
  bool nondominant_only = false;  // the sign starts with hamnondominant: one-handed, other hand
  Posture posture;
  std::vector<Element> actions;   // in order; groups nest
  int first_symbol = 0;
};

// Something the parser accepted although it is not well formed, like a mature tool would.
struct ParseNote {
  int symbol_index = -1;
  std::string text;
};

struct HamSign {
  std::vector<ManualSign> segments;  // at least one
  std::vector<ParseNote> notes;
  int symbol_count = 0;

  const ManualSign& main() const { return segments.front(); }
};

}  // namespace gestura::sign
