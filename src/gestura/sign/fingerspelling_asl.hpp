#pragma once
// The ASL one-handed manual alphabet A–Z and the digits 0–9, as our own data: a handshape, the
// hand's absolute finger and palm directions in the signer frame for the RIGHT (dominant) hand,
// and for J and Z the movement the hand traces. A left-handed signer uses the l ↔ r mirror.
#include <optional>
#include <span>

#include "gestura/sign/movement_path.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

struct AslLetter {
  char symbol;                // 'A'..'Z', '0'..'9'
  AslHandshape handshape;
  Direction finger;           // extended-finger direction (as if the fingers were straight)
  Direction palm;             // palm normal, ⟂ finger
  // J and Z only: the path the hand (wrist) follows, starting at the letter's location, and the
  // palm direction at the end of it (J turns the palm toward the signer).
  std::optional<MovementPath> movement;
  std::optional<Direction> end_palm;
};

// The 36 entries, letters first, in order.
std::span<const AslLetter> asl_alphabet();
// Case-insensitive lookup; nullptr when the character is not in the alphabet.
const AslLetter* find_asl_letter(char symbol);
// The letter's hand frame for the given hand (the left hand mirrors l ↔ r).
HandFrame letter_frame(const AslLetter& letter, Hand hand);
// The letter's movement for the given hand (mirrored for the left), if it has one.
std::optional<MovementPath> letter_movement(const AslLetter& letter, Hand hand);

}  // namespace gestura
