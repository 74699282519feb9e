#pragma once
// Directions and hand orientation in the SIGNER's frame: metres, +Y up, the signer faces +Z, so
// "o" (out, away from the signer) = +Z, "i" (in, towards the signer) = −Z, the signer's left
// "l" = +X and the signer's right "r" = −X. HamNoSys "l"/"r" are always the signer's own left and
// right, for either hand.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "gestura/core/math.hpp"
#include "gestura/sign/hand.hpp"

namespace gestura {

// The 26 directions of HamNoSys (the parsed notation uses them as they are): 6 axes, 12 two-axis
// diagonals, 8 three-axis diagonals. The letter order in
// the names is HamNoSys's: vertical (u/d) first, then depth (o/i), then side (l/r).
enum class Direction : std::uint8_t {
  U, D, L, R, O, I,
  UL, UR, DL, DR,
  OL, OR, IL, IR,
  UO, UI, DO, DI,
  UOL, UOR, UIL, UIR, DOL, DOR, DIL, DIR,
};
inline constexpr std::size_t kDirectionCount = 26;

// Signed unit components of a direction: vertical (+1 up), lateral (+1 the signer's left),
// sagittal (+1 out, away from the body).
struct DirectionComponents {
  std::int8_t vertical = 0;
  std::int8_t lateral = 0;
  std::int8_t sagittal = 0;
};
DirectionComponents components(Direction direction);
std::optional<Direction> direction_from_components(DirectionComponents c);
// Unit vector (diagonals are normalised sums of their axes).
vec3 direction_vector(Direction direction);
std::string_view to_string(Direction direction);  // "u", "uol", ...
// Accepts our names, the letters in any order ("lu" = "ul"), and HamNoSys symbol names with the
// prefixes hamextfinger / hammove / hamcircle ("hamextfingerol" → OL).
std::optional<Direction> parse_direction(std::string_view name);
// The direction naming every axis either names (HamNoSys writes some 3-axis diagonals as two
// symbols, e.g. ul + o → uol, ul + uo → uol). Empty when they name an axis in opposite senses.
std::optional<Direction> combine(Direction a, Direction b);
// The mirror image across the body's midline (l ↔ r), used for the non-dominant hand in
// mirror-symmetric signs and for left-handed signers.
Direction mirror_left_right(Direction direction);

// The 8 HamNoSys palm orientations: directions in the frontal plane as the signer sees them
// (u = up, l = the signer's left, ...). The palm normal for a finger direction f is the notated
// direction projected orthogonally to f. When the notated direction lies along the finger axis
// (fingers u with palm u or d, fingers l with palm l or r, ...) the projection vanishes and the
// symbol is read RELATIVE to the finger direction: as it would be for fingers pointing away from
// the signer ("o"), carried by the shortest rotation from "o" to f. So fingers up + palm "d" →
// palm away from the signer, fingers up + palm "u" → palm toward the signer, fingers pointing
// left + palm "l" → palm toward the signer.
enum class PalmOrientation : std::uint8_t { U, UR, R, DR, D, DL, L, UL };
inline constexpr std::size_t kPalmOrientationCount = 8;

vec3 palm_reference_vector(PalmOrientation palm);  // the frontal-plane vector for fingers "o"
std::string_view to_string(PalmOrientation palm);
std::optional<PalmOrientation> parse_palm_orientation(std::string_view name);  // "ul", "hampalmul"
PalmOrientation mirror_left_right(PalmOrientation palm);
// The palm orientation a frontal-plane direction names (u, ur, r, dr, d, dl, l, ul); empty for
// directions with a depth component, which HamNoSys palm symbols cannot express.
std::optional<PalmOrientation> palm_orientation_of(Direction direction);

// A hand's orientation in the signer frame.
// Hand-local axes (the contract with the skeleton; documented in docs/sign-phonology.md):
//   local +Y = extended-finger direction (wrist → middle-finger MCP, as if the fingers were straight),
//   local +Z = palm normal (out of the palm),
//   local +X = +Y × +Z: the thumb (radial) side for the RIGHT hand, the little-finger side for the LEFT.
// `rotation` maps hand-local vectors to the signer frame; it is a proper rotation for both hands
// (no mirroring), so a skeleton whose hands differ by a mirror must account for that in its rest
// offset, not here.
struct HandFrame {
  vec3 finger{0.0f, 1.0f, 0.0f};
  vec3 palm{0.0f, 0.0f, 1.0f};
  vec3 thumb_side{1.0f, 0.0f, 0.0f};  // radial side, in the signer frame
  quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

// From the notation: the finger axis equals direction_vector(finger); the palm is palm_normal().
HandFrame hand_frame(Direction finger, PalmOrientation palm, Hand hand);
// From absolute vectors (e.g. fingerspelling data): finger is normalised; palm is made orthogonal
// to it (Gram–Schmidt). Throws gestura::Error if either is not finite, zero, or they are parallel.
HandFrame hand_frame_from_vectors(vec3 finger, vec3 palm, Hand hand);
// Palm direction for a finger direction and a notated palm orientation (unit, ⟂ finger).
vec3 palm_normal(vec3 finger, PalmOrientation palm);

// ---- wiring to a skeleton ---------------------------------------------------------------------

// The hand frame a skeleton's hand has, from model-space joint positions (e.g. in the rest pose):
// the wrist and the index, middle and little-finger knuckles (H-Anim l_wrist, l_index1,
// l_middle1, l_pinky1). finger = wrist → middle knuckle; the radial side runs from the little
// finger's knuckle to the index's; the palm normal follows from the hand. Throws gestura::Error if
// the points are not finite or degenerate (coincident, collinear).
HandFrame hand_frame_from_joints(vec3 wrist, vec3 index_knuckle, vec3 middle_knuckle, vec3 pinky_knuckle, Hand hand);
// The model-space rotation the wrist joint needs so its hand takes the `target` frame, given the
// wrist's model-space rotation and the hand frame (hand_frame_from_joints) in one reference pose:
// target.rotation · reference_frame⁻¹ · reference_wrist.
quat wrist_rotation_for(const HandFrame& target, const quat& reference_frame, const quat& reference_wrist);

}  // namespace gestura
