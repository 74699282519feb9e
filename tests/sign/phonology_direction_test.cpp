#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "support/shared_data.hpp"

using namespace gestura;

namespace {

using gestura::test::shared_data;

std::vector<Direction> all_directions() {
  std::vector<Direction> v;
  for (std::size_t k = 0; k < kDirectionCount; ++k) v.push_back(static_cast<Direction>(k));
  return v;
}
std::vector<PalmOrientation> all_palms() {
  std::vector<PalmOrientation> v;
  for (std::size_t k = 0; k < kPalmOrientationCount; ++k) v.push_back(static_cast<PalmOrientation>(k));
  return v;
}

void expect_vec(vec3 actual, vec3 expected, float tolerance, const std::string& what) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
  EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
  EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

const float kH = 1.0f / std::sqrt(2.0f), kT = 1.0f / std::sqrt(3.0f);

}  // namespace

TEST(PhonologyDirection, AxesFollowTheSignerFrame) {
  expect_vec(direction_vector(Direction::U), {0, 1, 0}, 0, "u");
  expect_vec(direction_vector(Direction::D), {0, -1, 0}, 0, "d");
  expect_vec(direction_vector(Direction::O), {0, 0, 1}, 0, "o = away from the signer");
  expect_vec(direction_vector(Direction::I), {0, 0, -1}, 0, "i = toward the signer");
  expect_vec(direction_vector(Direction::L), {1, 0, 0}, 0, "l = signer's left");
  expect_vec(direction_vector(Direction::R), {-1, 0, 0}, 0, "r = signer's right");
  expect_vec(direction_vector(Direction::UL), {kH, kH, 0}, 1e-6f, "ul");
  expect_vec(direction_vector(Direction::DO), {0, -kH, kH}, 1e-6f, "do");
  expect_vec(direction_vector(Direction::IR), {-kH, 0, -kH}, 1e-6f, "ir");
  expect_vec(direction_vector(Direction::UOL), {kT, kT, kT}, 1e-6f, "uol");
  expect_vec(direction_vector(Direction::DIR), {-kT, -kT, -kT}, 1e-6f, "dir");
}

TEST(PhonologyDirection, AllTwentySixAreDistinctUnitVectorsMatchingTheirNames) {
  const auto all = all_directions();
  ASSERT_EQ(all.size(), 26u);
  for (Direction d : all) {
    const vec3 v = direction_vector(d);
    const std::string name{to_string(d)};
    EXPECT_NEAR(glm::length(v), 1.0f, 1e-6f) << name;
    // Each named letter pulls toward its axis; unnamed axes are zero.
    const auto has = [&](char c) { return name.find(c) != std::string::npos; };
    EXPECT_EQ(v.y > 0, has('u')) << name;
    EXPECT_EQ(v.y < 0, has('d')) << name;
    EXPECT_EQ(v.x > 0, has('l')) << name;
    EXPECT_EQ(v.x < 0, has('r')) << name;
    EXPECT_EQ(v.z > 0, has('o')) << name;
    EXPECT_EQ(v.z < 0, has('i')) << name;
    EXPECT_EQ(parse_direction(name), d);
  }
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = a + 1; b < all.size(); ++b)
      EXPECT_LT(glm::dot(direction_vector(all[a]), direction_vector(all[b])), 0.99f);
}

TEST(PhonologyDirection, ParsingAcceptsHamNoSysNamesAndRejectsNonsense) {
  EXPECT_EQ(parse_direction("lu"), Direction::UL);
  EXPECT_EQ(parse_direction("lou"), Direction::UOL);
  EXPECT_EQ(parse_direction("hamextfingerol"), Direction::OL);
  EXPECT_EQ(parse_direction("hammoveuo"), Direction::UO);
  EXPECT_EQ(parse_direction("hamcircledi"), Direction::DI);
  for (const char* bad : {"", "uu", "ud", "x", "uoll", "lr", "hamextfinger", "hamextfingerq"})
    EXPECT_EQ(parse_direction(bad), std::nullopt) << bad;

  std::ifstream in(shared_data() + "/hamnosys/codepoints.tsv");
  ASSERT_TRUE(in.good());
  std::string line;
  int directions = 0, palms = 0;
  while (std::getline(in, line)) {
    const std::string name = line.substr(0, line.find('\t'));
    if (name.rfind("hamextfinger", 0) == 0 || name.rfind("hammove", 0) == 0 || name.rfind("hamcircle", 0) == 0) {
      if (name == "hammovecross" || name == "hammoveX") continue;  // not directions
      EXPECT_TRUE(parse_direction(name).has_value()) << name;
      ++directions;
    }
    if (name.rfind("hampalm", 0) == 0 && name != "hampalm") {
      EXPECT_TRUE(parse_palm_orientation(name).has_value()) << name;
      ++palms;
    }
  }
  EXPECT_EQ(directions, 18 + 18 + 18);
  EXPECT_EQ(palms, 8);
}

TEST(PhonologyDirection, CombineAndMirror) {
  EXPECT_EQ(combine(Direction::UL, Direction::O), Direction::UOL);
  EXPECT_EQ(combine(Direction::UL, Direction::UO), Direction::UOL);
  EXPECT_EQ(combine(Direction::D, Direction::IR), Direction::DIR);
  EXPECT_EQ(combine(Direction::U, Direction::D), std::nullopt);
  EXPECT_EQ(combine(Direction::U, Direction::DL), std::nullopt);
  EXPECT_EQ(mirror_left_right(Direction::L), Direction::R);
  EXPECT_EQ(mirror_left_right(Direction::UOR), Direction::UOL);
  EXPECT_EQ(mirror_left_right(Direction::DI), Direction::DI);
  EXPECT_EQ(mirror_left_right(PalmOrientation::UL), PalmOrientation::UR);
  EXPECT_EQ(mirror_left_right(PalmOrientation::D), PalmOrientation::D);
  EXPECT_EQ(palm_orientation_of(Direction::DL), PalmOrientation::DL);
  EXPECT_EQ(palm_orientation_of(Direction::R), PalmOrientation::R);
  EXPECT_EQ(palm_orientation_of(Direction::O), std::nullopt);
  EXPECT_EQ(palm_orientation_of(Direction::UOL), std::nullopt);
  int frontal = 0;
  for (Direction d : all_directions()) frontal += palm_orientation_of(d).has_value();
  EXPECT_EQ(frontal, 8);
  for (Direction d : all_directions()) {
    const vec3 v = direction_vector(d), m = direction_vector(mirror_left_right(d));
    expect_vec(m, {-v.x, v.y, v.z}, 1e-6f, std::string(to_string(d)));
  }
}

TEST(PhonologyDirection, HandFramesAreOrthonormalRotationsWithTheNotatedFingerAxis) {
  for (Hand hand : {Hand::Right, Hand::Left})
    for (Direction d : all_directions())
      for (PalmOrientation p : all_palms()) {
        const HandFrame f = hand_frame(d, p, hand);
        const std::string what = std::string(to_string(d)) + "/" + std::string(to_string(p));
        expect_vec(f.finger, direction_vector(d), 1e-5f, what + " finger");
        EXPECT_NEAR(glm::length(f.palm), 1.0f, 1e-5f) << what;
        EXPECT_NEAR(glm::dot(f.palm, f.finger), 0.0f, 1e-5f) << what;
        EXPECT_NEAR(glm::dot(f.thumb_side, f.finger), 0.0f, 1e-5f) << what;
        EXPECT_NEAR(glm::dot(f.thumb_side, f.palm), 0.0f, 1e-5f) << what;
        // The quaternion carries the hand-local axes onto the frame.
        expect_vec(f.rotation * vec3{0, 1, 0}, f.finger, 1e-5f, what + " local +Y");
        expect_vec(f.rotation * vec3{0, 0, 1}, f.palm, 1e-5f, what + " local +Z");
        EXPECT_NEAR(glm::length(f.rotation), 1.0f, 1e-5f);
        // Thumb side: right hand = finger × palm, left hand the opposite.
        const vec3 radial = glm::cross(f.finger, f.palm);
        expect_vec(f.thumb_side, hand == Hand::Right ? radial : -radial, 1e-5f, what + " thumb");
      }
}

TEST(PhonologyDirection, PalmIsTheNotatedDirectionProjectedOrthogonally) {
  int projected = 0, along_axis = 0;
  for (Direction d : all_directions())
    for (PalmOrientation p : all_palms()) {
      const vec3 f = direction_vector(d), ref = palm_reference_vector(p);
      const vec3 proj = ref - glm::dot(ref, f) * f;
      const vec3 palm = hand_frame(d, p, Hand::Right).palm;
      if (glm::length(proj) > 1e-4f) {
        expect_vec(palm, glm::normalize(proj), 1e-5f, std::string(to_string(d)) + "/" + std::string(to_string(p)));
        ++projected;
      } else {
        ++along_axis;
      }
    }
  EXPECT_EQ(projected + along_axis, 26 * 8);
  EXPECT_EQ(along_axis, 16);  // 8 frontal-plane finger directions × (same, opposite) palm symbol
}

TEST(PhonologyDirection, PalmAlongTheFingerAxisIsReadRelativeToTheFingers) {
  // Fingers up: "d" faces away from the signer, "u" toward; fingers left: "l" faces the signer.
  expect_vec(hand_frame(Direction::U, PalmOrientation::D, Hand::Right).palm, {0, 0, 1}, 1e-6f, "u/d");
  expect_vec(hand_frame(Direction::U, PalmOrientation::U, Hand::Right).palm, {0, 0, -1}, 1e-6f, "u/u");
  expect_vec(hand_frame(Direction::L, PalmOrientation::L, Hand::Right).palm, {0, 0, -1}, 1e-6f, "l/l");
  expect_vec(hand_frame(Direction::R, PalmOrientation::R, Hand::Right).palm, {0, 0, -1}, 1e-6f, "r/r");
  expect_vec(hand_frame(Direction::D, PalmOrientation::U, Hand::Right).palm, {0, 0, 1}, 1e-6f, "d/u");
  // A right hand with fingers away and palm down has its thumb on the signer's left.
  expect_vec(hand_frame(Direction::O, PalmOrientation::D, Hand::Right).thumb_side, {1, 0, 0}, 1e-6f, "right thumb");
  expect_vec(hand_frame(Direction::O, PalmOrientation::D, Hand::Left).thumb_side, {-1, 0, 0}, 1e-6f, "left thumb");
}

TEST(PhonologyDirection, FramesFromVectorsRejectDegenerateInput) {
  const HandFrame f = hand_frame_from_vectors({0, 2, 0}, {0.3f, 0.5f, 1.0f}, Hand::Right);
  expect_vec(f.finger, {0, 1, 0}, 1e-6f, "normalised finger");
  expect_vec(f.palm, glm::normalize(vec3{0.3f, 0, 1}), 1e-6f, "orthogonalised palm");
  EXPECT_THROW(hand_frame_from_vectors({0, 0, 0}, {0, 0, 1}, Hand::Right), Error);
  EXPECT_THROW(hand_frame_from_vectors({0, 1, 0}, {0, -3, 0}, Hand::Right), Error);
  EXPECT_THROW(hand_frame_from_vectors({0, std::nanf(""), 0}, {0, 0, 1}, Hand::Right), Error);
}
