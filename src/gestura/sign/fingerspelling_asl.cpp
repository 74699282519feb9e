#include "gestura/sign/fingerspelling_asl.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <vector>

namespace gestura {

namespace {

using D = Direction;
using S = AslHandshape;

// J: the little finger draws the letter — down, then a hook toward the signer's left (the body's
// midline for the right hand) — while the forearm supinates so the palm ends facing the signer and
// the midline (in-left: turning from out to that is the short way through the midline side, the
// way a right forearm supinates; a full half turn to "in" would leave the direction to chance).
// The hand path is a 5 cm drop followed by a half circle of radius 1.5 cm. One smooth stroke
// (no stop at the joins). The forearm's turn swings the little finger (6 cm to the side of the
// palm centre) toward the midline as well, so the drop must be long enough for the J to keep
// its stem: with 3 cm the traced letter was a shallow swoosh.
MovementPath j_path() {
  constexpr float drop = 0.05f;
  std::vector<vec3> points{{0.0f, 0.0f, 0.0f}, {0.0f, -drop, 0.0f}};
  const float r = 0.015f;
  const vec3 centre{r, -drop, 0.0f};
  for (int k = 1; k <= 8; ++k) {
    const float a = kPi + kPi * static_cast<float>(k) / 8.0f;  // −X side of the centre, under it, up on its +X side
    points.push_back(centre + r * vec3{std::cos(a), std::sin(a), 0.0f});
  }
  return polyline_path(std::move(points), false);
}

// Z: the index draws a Z as the signer would write it: top stroke to the signer's right (−X),
// diagonal back down to the left, bottom stroke to the right. 6 cm square; the hand stops at the
// two corners (each stroke is its own minimum-jerk movement).
MovementPath z_path() {
  const float w = 0.06f;
  return polyline_path({{0, 0, 0}, {-w, 0, 0}, {0, -w, 0}, {-w, -w, 0}}, true);
}

const std::array<AslLetter, 36>& table() {
  // Most letters: fingers up, palm toward the addressee (O) at the dominant shoulder. C, O and X
  // turn the palm to the midline (L for the right hand) so their shape is seen from the side;
  // G, H and Q point sideways/down with the palm toward the signer; P is K pointing forward with
  // the palm down. Digits 1–5 face the palm to the signer (ASL cardinal numbers), 6–9 outward.
  static const std::array<AslLetter, 36> letters{{
      {'A', S::A, D::U, D::O, std::nullopt, std::nullopt},
      {'B', S::B, D::U, D::O, std::nullopt, std::nullopt},
      {'C', S::C, D::U, D::L, std::nullopt, std::nullopt},
      {'D', S::D, D::U, D::O, std::nullopt, std::nullopt},
      {'E', S::E, D::U, D::O, std::nullopt, std::nullopt},
      {'F', S::F, D::U, D::O, std::nullopt, std::nullopt},
      {'G', S::G, D::L, D::I, std::nullopt, std::nullopt},
      {'H', S::U, D::L, D::I, std::nullopt, std::nullopt},
      {'I', S::I, D::U, D::O, std::nullopt, std::nullopt},
      {'J', S::I, D::U, D::O, j_path(), D::IL},
      {'K', S::K, D::U, D::O, std::nullopt, std::nullopt},
      {'L', S::L, D::U, D::O, std::nullopt, std::nullopt},
      {'M', S::M, D::U, D::O, std::nullopt, std::nullopt},
      {'N', S::N, D::U, D::O, std::nullopt, std::nullopt},
      {'O', S::O, D::U, D::L, std::nullopt, std::nullopt},
      {'P', S::K, D::O, D::D, std::nullopt, std::nullopt},
      {'Q', S::G, D::D, D::I, std::nullopt, std::nullopt},
      {'R', S::R, D::U, D::O, std::nullopt, std::nullopt},
      {'S', S::S, D::U, D::O, std::nullopt, std::nullopt},
      {'T', S::T, D::U, D::O, std::nullopt, std::nullopt},
      {'U', S::U, D::U, D::O, std::nullopt, std::nullopt},
      {'V', S::V, D::U, D::O, std::nullopt, std::nullopt},
      {'W', S::W, D::U, D::O, std::nullopt, std::nullopt},
      {'X', S::X, D::U, D::L, std::nullopt, std::nullopt},
      {'Y', S::Y, D::U, D::O, std::nullopt, std::nullopt},
      {'Z', S::One, D::U, D::O, z_path(), std::nullopt},
      {'0', S::O, D::U, D::L, std::nullopt, std::nullopt},
      {'1', S::One, D::U, D::I, std::nullopt, std::nullopt},
      {'2', S::V, D::U, D::I, std::nullopt, std::nullopt},
      {'3', S::Three, D::U, D::I, std::nullopt, std::nullopt},
      {'4', S::Four, D::U, D::I, std::nullopt, std::nullopt},
      {'5', S::Five, D::U, D::I, std::nullopt, std::nullopt},
      {'6', S::Six, D::U, D::O, std::nullopt, std::nullopt},
      {'7', S::Seven, D::U, D::O, std::nullopt, std::nullopt},
      {'8', S::Eight, D::U, D::O, std::nullopt, std::nullopt},
      {'9', S::F, D::U, D::O, std::nullopt, std::nullopt},
  }};
  return letters;
}

}  // namespace

std::span<const AslLetter> asl_alphabet() { return table(); }

const AslLetter* find_asl_letter(char symbol) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(symbol)));
  for (const AslLetter& letter : table())
    if (letter.symbol == upper) return &letter;
  return nullptr;
}

HandFrame letter_frame(const AslLetter& letter, Hand hand) {
  const Direction finger = hand == Hand::Right ? letter.finger : mirror_left_right(letter.finger);
  const Direction palm = hand == Hand::Right ? letter.palm : mirror_left_right(letter.palm);
  return hand_frame_from_vectors(direction_vector(finger), direction_vector(palm), hand);
}

std::optional<MovementPath> letter_movement(const AslLetter& letter, Hand hand) {
  if (!letter.movement) return std::nullopt;
  return hand == Hand::Right ? *letter.movement : mirror_left_right(*letter.movement);
}

}  // namespace gestura
