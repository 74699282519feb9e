#pragma once
// Handshapes as data: an anatomical, skeleton-independent description of one hand's posture
// (joint flexions in radians), the HamNoSys basic forms with their thumb and bending modifiers,
// and the ASL handshapes used by the manual alphabet and the digits.
//
// Sign conventions (all angles in radians):
// - Finger flexion is positive when the finger curls toward the palm; 0 is straight in line with
//   the metacarpal. Anatomical limits used here: MCP 0..90°, PIP 0..110°, DIP 0..80°.
// - Spread (abduction at the MCP) is positive away from the hand's midline: index toward the
//   thumb (radial), middle, ring and pinky toward the little-finger side (ulnar). Limits −20..30°.
// - Thumb: cmc_flexion moves the first metacarpal in the palm plane toward the little finger
//   (negative = radial abduction, the "L" thumb); cmc_abduction lifts it out of the palm plane
//   (palmar abduction; negative presses it back toward the palm plane, from the avatar's rest
//   thumb, which already stands ~4 cm out of it); cmc_opposition is the axial pronation that turns the thumb pad to face
//   the finger pads. mcp / ip are flexions. Limits in kThumbLimits below.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gestura {

enum class Finger : std::uint8_t { Thumb, Index, Middle, Ring, Pinky };

// Bit set of fingers (bit i = Finger i).
using FingerSet = std::uint8_t;
inline constexpr FingerSet finger_bit(Finger f) { return static_cast<FingerSet>(1u << static_cast<unsigned>(f)); }
inline constexpr FingerSet kAllFourFingers = 0b11110;  // index..pinky

struct FingerFlexion {
  float mcp = 0.0f;
  float pip = 0.0f;
  float dip = 0.0f;
};

struct ThumbPose {
  float cmc_flexion = 0.0f;
  float cmc_abduction = 0.0f;
  float cmc_opposition = 0.0f;
  float mcp = 0.0f;
  float ip = 0.0f;
};

struct HandPosture {
  ThumbPose thumb;
  std::array<FingerFlexion, 4> fingers{};  // index, middle, ring, pinky
  std::array<float, 4> spread{};           // index, middle, ring, pinky (see sign convention above)
  // Fingertips the thumb tip touches (pinch, O, F, 6–9). The angles put the tips close; an IK
  // pass on the real skeleton may close the last millimetres using this.
  FingerSet thumb_tip_contacts = 0;
  bool middle_crosses_index = false;  // ASL R: the middle finger lies over the index

  // Index..pinky; the thumb has its own ThumbPose (Finger::Thumb throws std::out_of_range).
  FingerFlexion& finger(Finger f) { return fingers.at(static_cast<std::size_t>(f) - 1); }
  const FingerFlexion& finger(Finger f) const { return fingers.at(static_cast<std::size_t>(f) - 1); }
};

struct JointRange {
  float min;
  float max;
};
struct FingerLimits {
  JointRange mcp, pip, dip, spread;
};
struct ThumbLimits {
  JointRange cmc_flexion, cmc_abduction, cmc_opposition, mcp, ip;
};
extern const FingerLimits kFingerLimits;
extern const ThumbLimits kThumbLimits;

// Empty when every angle is finite and inside the limits; otherwise names the first offender
// ("index pip 2.1 rad outside [0, 1.92]").
std::string anatomical_violation(const HandPosture& posture);

// Componentwise linear blend (s = 0 → a, 1 → b); contacts and crossing switch at s = 0.5.
HandPosture mix(const HandPosture& a, const HandPosture& b, float s);

// ---- HamNoSys basic forms -------------------------------------------------------------------

// The twelve basic handshapes. Reading used for the thumb combinations (documented in
// docs/sign-phonology.md): the fingers not taking part stay extended (pinch12 is the "F"/"OK"
// form); the openings grow pinch12 (tips touch) < pinch12open (tips ~1.5 cm apart) < cee12 (C)
// < cee12open (wide C).
enum class BasicHandshape : std::uint8_t {
  Fist,
  Flat,
  Finger2,
  Finger23,
  Finger23Spread,
  Finger2345,
  Pinch12,
  PinchAll,
  Pinch12Open,
  Cee12,
  CeeAll,
  Cee12Open,
};
inline constexpr std::size_t kBasicHandshapeCount = 12;

enum class ThumbModifier : std::uint8_t {
  Default,  // the form's own thumb: alongside the index for fist/flat, across the fingers otherwise
  Out,      // hamthumboutmod: abducted in the palm plane, straight ("L", thumbs-up)
  Across,   // hamthumbacrossmod: folded across the curled fingers / palm ("S")
  Opposed,  // hamthumbopenmod: opposed to the finger pads without touching
};

// HamNoSys symbol names follow the glyphs: hamfingerstraightmod draws a finger bent at the base
// joint only, hamfingerbendmod a finger curved at all joints. "Straight" is no bending at all.
enum class FingerBending : std::uint8_t {
  Bent,          // hamfingerstraightmod, SiGML "bent": flexed at the knuckle (MCP) only
  Round,         // hamfingerbendmod, "round": all three joints moderately flexed, a smooth arc
  Hooked,        // hamfingerhookmod, "hooked": MCP straight, PIP and DIP flexed (claw)
  DoubleBent,    // hamdoublebent, "dblbent": MCP and PIP flexed, DIP nearly straight
  DoubleHooked,  // hamdoublehooked, "dblhooked": tight claw, PIP and DIP near their limits
  HalfBent,      // SiGML "halfbent": MCP half flexed, fingers straight
};
inline constexpr std::size_t kFingerBendingCount = 6;

HandPosture basic_handshape(BasicHandshape shape);
FingerFlexion bending_flexion(FingerBending bending);
// The thumb pose a modifier gives (Default returns `shape`'s own thumb).
ThumbPose thumb_pose(ThumbModifier modifier, BasicHandshape shape);
// Sets the flexion of the selected fingers (the thumb bit is ignored) to the bending's values.
void apply_bending(HandPosture& posture, FingerSet fingers, FingerBending bending);
// basic_handshape + thumb + bending of the form's selected fingers in one call.
HandPosture make_handshape(BasicHandshape shape, ThumbModifier thumb = ThumbModifier::Default,
                           std::optional<FingerBending> bending = std::nullopt);
// The extended ("selected") fingers of a basic form, the ones a bending modifier acts on.
FingerSet selected_fingers(BasicHandshape shape);

// Names: ours ("finger23spread", also the gestural SiGML values such as "dblhooked") and the
// HamNoSys symbol names ("hamfinger23spread", "hamflathand", "hamceeopen", "hamthumboutmod",
// "hamfingerhookmod", ...) are all accepted.
std::string_view to_string(BasicHandshape shape);
std::optional<BasicHandshape> parse_basic_handshape(std::string_view name);
std::string_view to_string(ThumbModifier modifier);
std::optional<ThumbModifier> parse_thumb_modifier(std::string_view name);
std::string_view to_string(FingerBending bending);
std::optional<FingerBending> parse_finger_bending(std::string_view name);

// ---- ASL handshapes (manual alphabet and digits) --------------------------------------------

// Letters that share a shape reuse it (H = U, J = I, P = K, Q = G, Z = One, digits 0/2/9 = O/V/F).
enum class AslHandshape : std::uint8_t {
  A, B, C, D, E, F, G, I, K, L, M, N, O, R, S, T, U, V, W, X, Y,
  One, Three, Four, Five, Six, Seven, Eight,
};
inline constexpr std::size_t kAslHandshapeCount = 28;

HandPosture asl_handshape(AslHandshape shape);
std::string_view to_string(AslHandshape shape);
std::optional<AslHandshape> parse_asl_handshape(std::string_view name);

}  // namespace gestura
