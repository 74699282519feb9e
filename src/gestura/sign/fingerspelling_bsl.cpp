#include "gestura/sign/fingerspelling_bsl.hpp"

#include <array>
#include <cctype>
#include <vector>

namespace gestura {

namespace {

using D = Direction;

// The hands that recur. For a right-handed signer the non-dominant (left) hand is held in front of
// the chest, palm toward the signer, fingers pointing up and to the right (toward the dominant
// hand), so its fingertips are easy for the dominant index to reach.
BslHand pointer() { return {basic_handshape(BasicHandshape::Finger2), D::UL, D::I}; }      // vowels
BslHand spread_base() { return {make_handshape(BasicHandshape::Finger2345, ThumbModifier::Out), D::UR, D::I}; }
BslHand flat_base() { return {basic_handshape(BasicHandshape::Flat), D::UR, D::I}; }
// Something laid on the base palm: the dominant hand points up-left with its palm facing the base.
BslHand on_palm(HandPosture shape) { return {shape, D::UL, D::O}; }
BslHand upright_index() { return {basic_handshape(BasicHandshape::Finger2), D::U, D::R}; }

HandPosture little_finger_hooked() {
  HandPosture h = asl_handshape(AslHandshape::I);
  apply_bending(h, finger_bit(Finger::Pinky), FingerBending::Hooked);
  return h;
}

// J: the index draws a J down the base palm — 5 cm down, then a hook of radius 1.5 cm toward the
// signer's right (away from the base's thumb) — in the frontal plane the base palm lies in.
MovementPath bsl_j_path() {
  std::vector<vec3> points{{0.0f, 0.0f, 0.0f}, {0.0f, -0.05f, 0.0f}};
  const float r = 0.015f;
  const vec3 centre{-r, -0.05f, 0.0f};
  for (int k = 1; k <= 8; ++k) {
    const float a = kPi * static_cast<float>(k) / 8.0f;  // +X side of the centre, under it, up on its −X side
    points.push_back(centre + r * vec3{std::cos(a), -std::sin(a), 0.0f});
  }
  return polyline_path(std::move(points), false);
}

BslLetter vowel(char symbol, BslContactSite site) {
  return {symbol, pointer(), spread_base(), site, BslDominantPart::IndexTip, std::nullopt, false};
}

const std::array<BslLetter, 26>& table() {
  using P = BslDominantPart;
  using C = BslContactSite;
  const HandPosture index_only = basic_handshape(BasicHandshape::Finger2);
  const HandPosture two_fingers = basic_handshape(BasicHandshape::Finger23);
  const HandPosture ring = asl_handshape(AslHandshape::O);
  const HandPosture fist = asl_handshape(AslHandshape::S);
  const HandPosture flat = basic_handshape(BasicHandshape::Flat);
  static const std::array<BslLetter, 26> letters{{
      vowel('A', C::ThumbTip),
      // B: two rings side by side, touching along the thumb–index sides (the two bowls of a b).
      {'B', {ring, D::U, D::L}, BslHand{ring, D::U, D::R}, C::ThumbIndexSide, P::ThumbIndex, std::nullopt, true},
      {'C', {asl_handshape(AslHandshape::C), D::U, D::L}, std::nullopt, C::None, P::None, std::nullopt, false},
      // D: the dominant thumb–index curve closes on the upright non-dominant index (the stem).
      {'D', {make_handshape(BasicHandshape::Cee12), D::U, D::L}, upright_index(), C::IndexFinger, P::ThumbIndex,
       std::nullopt, false},
      vowel('E', C::IndexTip),
      // F: two fingers laid across two fingers, both palms down, crossing at ~135°.
      {'F', {two_fingers, D::OL, D::D}, BslHand{two_fingers, D::R, D::D}, C::IndexMiddle, P::FingerPads,
       std::nullopt, false},
      // G: dominant fist on top of the non-dominant fist, both thumbs up.
      {'G', {fist, D::O, D::L}, BslHand{fist, D::O, D::R}, C::FistTop, P::FistSide, std::nullopt, false},
      // H: the flat dominant palm brushes across the upturned non-dominant palm toward the signer.
      {'H', {flat, D::O, D::D}, BslHand{flat, D::R, D::U}, C::Palm, P::PalmSurface,
       straight_path(vec3{0.0f, 0.0f, -1.0f}, 0.08f), false},
      vowel('I', C::MiddleTip),
      {'J', pointer(), flat_base(), C::Palm, P::IndexTip, bsl_j_path(), true},
      // K: the crooked dominant index rests on the upright non-dominant index.
      {'K', {make_handshape(BasicHandshape::Finger2, ThumbModifier::Default, FingerBending::Hooked), D::L, D::D},
       upright_index(), C::IndexFinger, P::IndexPad, std::nullopt, false},
      {'L', on_palm(index_only), flat_base(), C::Palm, P::IndexPad, std::nullopt, false},
      {'M', on_palm(asl_handshape(AslHandshape::W)), flat_base(), C::Palm, P::FingerPads, std::nullopt, false},
      {'N', on_palm(two_fingers), flat_base(), C::Palm, P::FingerPads, std::nullopt, false},
      vowel('O', C::RingTip),
      // P: the dominant thumb–index ring sits on the tip of the upright non-dominant index.
      {'P', {basic_handshape(BasicHandshape::Pinch12), D::L, D::I}, upright_index(), C::IndexTip, P::ThumbIndex,
       std::nullopt, false},
      // Q: as P with the non-dominant index pointing down (the tail).
      {'Q', {basic_handshape(BasicHandshape::Pinch12), D::L, D::D},
       BslHand{index_only, D::D, D::R}, C::IndexTip, P::ThumbIndex, std::nullopt, true},
      // R: the dominant index bent at the knuckle, its tip on the base palm.
      {'R', on_palm(make_handshape(BasicHandshape::Finger2, ThumbModifier::Default, FingerBending::Bent)), flat_base(),
       C::Palm, P::IndexTip, std::nullopt, false},
      // S: the two little fingers hook into each other.
      {'S', {little_finger_hooked(), D::L, D::I}, BslHand{little_finger_hooked(), D::R, D::O}, C::LittleFinger,
       P::LittleFinger, std::nullopt, false},
      // T: the dominant index tip meets the lower (little-finger) edge of the non-dominant flat hand,
      // which points forward with its palm facing the midline.
      {'T', {index_only, D::U, D::O}, BslHand{flat, D::O, D::R}, C::PinkyEdge, P::IndexTip, std::nullopt, true},
      vowel('U', C::PinkyTip),
      {'V', on_palm(basic_handshape(BasicHandshape::Finger23Spread)), flat_base(), C::Palm, P::FingerPads,
       std::nullopt, false},
      // W: both spread hands, palms to the signer, fingers interlocking.
      {'W', {asl_handshape(AslHandshape::Five), D::UL, D::I}, spread_base(), C::Fingers, P::Fingers, std::nullopt,
       false},
      // X: the two index fingers cross.
      {'X', on_palm(index_only), BslHand{index_only, D::UR, D::I}, C::IndexFinger, P::IndexPad, std::nullopt, false},
      // Y: the dominant index tip in the web between the non-dominant thumb and index.
      {'Y', pointer(), spread_base(), C::ThumbIndexWeb, P::IndexTip, std::nullopt, false},
      {'Z', on_palm(flat), flat_base(), C::Palm, P::FingerPads, std::nullopt, true},
  }};
  return letters;
}

HandFrame frame_of(const BslHand& hand, Hand side, bool mirrored) {
  const Direction finger = mirrored ? mirror_left_right(hand.finger) : hand.finger;
  const Direction palm = mirrored ? mirror_left_right(hand.palm) : hand.palm;
  return hand_frame_from_vectors(direction_vector(finger), direction_vector(palm), side);
}

}  // namespace

std::string_view to_string(BslContactSite site) {
  static constexpr std::string_view kNames[] = {"none", "thumb tip", "index tip", "middle tip", "ring tip",
                                                "little finger tip", "index finger", "index and middle",
                                                "palm", "little-finger edge", "thumb-index web", "fist top",
                                                "thumb-index side", "little finger", "fingers"};
  return kNames[static_cast<std::size_t>(site)];
}

std::span<const BslLetter> bsl_alphabet() { return table(); }

const BslLetter* find_bsl_letter(char symbol) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(symbol)));
  for (const BslLetter& letter : table())
    if (letter.symbol == upper) return &letter;
  return nullptr;
}

HandFrame dominant_frame(const BslLetter& letter, Hand dominant) {
  return frame_of(letter.dominant, dominant, dominant == Hand::Left);
}

std::optional<HandFrame> non_dominant_frame(const BslLetter& letter, Hand dominant) {
  if (!letter.non_dominant) return std::nullopt;
  const Hand other = dominant == Hand::Right ? Hand::Left : Hand::Right;
  return frame_of(*letter.non_dominant, other, dominant == Hand::Left);
}

}  // namespace gestura
