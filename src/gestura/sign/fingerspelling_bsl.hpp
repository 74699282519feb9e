#pragma once
// The BSL two-handed manual alphabet A–Z as our own data. Each letter is a dominant-hand
// configuration, usually a non-dominant configuration, and the site on the non-dominant hand the
// dominant hand touches: vowels are the dominant index tip on a fingertip of the spread
// non-dominant hand (A thumb, E index, I middle, O ring, U little finger). Directions are for a
// right-handed signer (dominant = right); a left-handed signer uses the l ↔ r mirror.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "gestura/sign/movement_path.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

// Where on the non-dominant hand the contact is.
enum class BslContactSite : std::uint8_t {
  None,            // one-handed letter (C)
  ThumbTip,
  IndexTip,
  MiddleTip,
  RingTip,
  PinkyTip,
  IndexFinger,     // along the extended index finger
  IndexMiddle,     // across the extended index and middle fingers
  Palm,
  PinkyEdge,       // the ulnar edge of the flat hand
  ThumbIndexWeb,   // the web between thumb and index
  FistTop,         // the thumb/index side of the closed fist
  ThumbIndexSide,  // side by side, thumb and index sides touching (B)
  LittleFinger,    // the two little fingers hook together (S)
  Fingers,         // the spread fingers interlock (W)
};
std::string_view to_string(BslContactSite site);

// Which part of the dominant hand makes the contact.
enum class BslDominantPart : std::uint8_t {
  None,
  IndexTip,
  IndexPad,      // the index laid along its palmar surface
  FingerPads,    // two or more extended fingers laid on the site
  ThumbIndex,    // the thumb–index curve or ring
  FistSide,      // the closed fist
  LittleFinger,  // hooked little finger
  Fingers,       // spread fingers (W)
  PalmSurface,   // the flat palm (H brushes across)
};

struct BslHand {
  HandPosture posture;
  Direction finger;
  Direction palm;  // ⟂ finger
};

struct BslLetter {
  char symbol;  // 'A'..'Z'
  BslHand dominant;
  std::optional<BslHand> non_dominant;  // empty for one-handed letters
  BslContactSite site;
  BslDominantPart part;
  std::optional<MovementPath> movement;  // of the dominant hand, after contact (H brushes, J traces)
  // True where our description is the least certain (B, J, Q, T, Z): the configuration and
  // contact are plausible but not verified against a reference signer.
  bool approximate = false;
};

std::span<const BslLetter> bsl_alphabet();       // 26 entries, A..Z
const BslLetter* find_bsl_letter(char symbol);  // case-insensitive; nullptr if absent
// Hand frames for a letter's two hands for a right-handed (dominant = Hand::Right) or
// left-handed (dominant = Hand::Left, everything mirrored l ↔ r) signer.
HandFrame dominant_frame(const BslLetter& letter, Hand dominant);
std::optional<HandFrame> non_dominant_frame(const BslLetter& letter, Hand dominant);

}  // namespace gestura
