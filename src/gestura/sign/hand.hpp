#pragma once
// The two hands, and values that come one per hand. The dominant hand is the right hand: the
// notation's "dominant" is Hand::Right and its "non-dominant" Hand::Left (a left-handed signer is
// the mirror image of the notation, phonology_direction.hpp's mirror_left_right).
#include <array>
#include <cstddef>
#include <cstdint>

namespace gestura {

enum class Hand : std::uint8_t { Right, Left };

inline constexpr Hand kDominantHand = Hand::Right;
inline constexpr std::array<Hand, 2> kBothHands{Hand::Right, Hand::Left};

constexpr Hand other_hand(Hand hand) { return hand == Hand::Right ? Hand::Left : Hand::Right; }
// The hand's place in a pair: 0 for the right hand, 1 for the left (ByHand's order).
constexpr std::size_t hand_index(Hand hand) { return hand == Hand::Right ? 0 : 1; }

// One value per hand, indexed by Hand (the right hand's first).
template <class T>
struct ByHand {
  std::array<T, 2> values{};

  constexpr T& operator[](Hand hand) { return values[hand_index(hand)]; }
  constexpr const T& operator[](Hand hand) const { return values[hand_index(hand)]; }
  constexpr auto begin() { return values.begin(); }
  constexpr auto end() { return values.end(); }
  constexpr auto begin() const { return values.begin(); }
  constexpr auto end() const { return values.end(); }
};

// Which hands an action of the notation drives: "the hand" of a one-handed sign is the dominant
// one, a symmetry operator makes it both, a hand pair's second branch is the non-dominant one.
enum class Hands : std::uint8_t { Dominant = 1, NonDominant = 2, Both = 3 };

constexpr bool drives(Hands hands, Hand hand) {
  return (static_cast<unsigned>(hands) & (hand == kDominantHand ? 1u : 2u)) != 0;
}
constexpr Hands only(Hand hand) { return hand == kDominantHand ? Hands::Dominant : Hands::NonDominant; }

}  // namespace gestura
