#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"

using namespace gestura;

TEST(FingerspellingAsl, CoversLettersAndDigitsWithValidData) {
  std::set<char> seen;
  for (const AslLetter& letter : asl_alphabet()) {
    seen.insert(letter.symbol);
    EXPECT_EQ(anatomical_violation(asl_handshape(letter.handshape)), "") << letter.symbol;
    // Finger and palm directions are perpendicular, so the frame is exactly what the data says.
    EXPECT_NEAR(glm::dot(direction_vector(letter.finger), direction_vector(letter.palm)), 0.0f, 1e-6f) << letter.symbol;
    for (Hand hand : {Hand::Right, Hand::Left}) {
      const HandFrame f = letter_frame(letter, hand);
      EXPECT_NEAR(glm::dot(f.finger, f.palm), 0.0f, 1e-5f);
    }
    if (letter.end_palm) {
      EXPECT_NEAR(glm::dot(direction_vector(letter.finger), direction_vector(*letter.end_palm)), 0.0f, 1e-6f);
    }
  }
  for (char c = 'A'; c <= 'Z'; ++c) EXPECT_TRUE(seen.count(c)) << c;
  for (char c = '0'; c <= '9'; ++c) EXPECT_TRUE(seen.count(c)) << c;
  EXPECT_EQ(asl_alphabet().size(), 36u);
  EXPECT_EQ(find_asl_letter('q'), find_asl_letter('Q'));
  EXPECT_EQ(find_asl_letter('!'), nullptr);
}

TEST(FingerspellingAsl, OnlyJAndZMoveAndTheyTraceTheirLetters) {
  for (const AslLetter& letter : asl_alphabet())
    EXPECT_EQ(letter.movement.has_value(), letter.symbol == 'J' || letter.symbol == 'Z') << letter.symbol;
  // J: the pinky hand (I) drops, then hooks toward the signer's left and turns the palm to the signer.
  const AslLetter& j = *find_asl_letter('J');
  EXPECT_EQ(j.handshape, AslHandshape::I);
  const MovementPath& jp = *j.movement;
  EXPECT_LT(sample_path(jp, 0.5f).position.y, -0.02f);
  EXPECT_GT(path_end(jp).x, 0.01f);
  EXPECT_EQ(j.end_palm, Direction::IL);  // toward the signer, turned through the midline side
  // Z: the index traces three strokes: right, down-left diagonal, right again; it ends lower and to the right.
  const AslLetter& z = *find_asl_letter('Z');
  EXPECT_EQ(z.handshape, AslHandshape::One);
  const MovementPath& zp = *z.movement;
  ASSERT_EQ(zp.points.size(), 4u);
  EXPECT_LT(zp.points[1].x, 0.0f);
  EXPECT_LT(zp.points[2].y, 0.0f);
  EXPECT_GT(zp.points[2].x, zp.points[1].x);
  EXPECT_LT(path_end(zp).x, 0.0f);
  // For a left-handed signer the strokes mirror.
  EXPECT_GT(path_end(*letter_movement(z, Hand::Left)).x, 0.0f);
}

TEST(FingerspellingBsl, CoversTheAlphabetWithTwoHandedVowels) {
  std::set<char> seen;
  for (const BslLetter& letter : bsl_alphabet()) {
    seen.insert(letter.symbol);
    EXPECT_EQ(anatomical_violation(letter.dominant.posture), "") << letter.symbol;
    EXPECT_NEAR(glm::dot(direction_vector(letter.dominant.finger), direction_vector(letter.dominant.palm)), 0.0f, 1e-6f)
        << letter.symbol;
    if (letter.non_dominant) {
      EXPECT_EQ(anatomical_violation(letter.non_dominant->posture), "") << letter.symbol;
      EXPECT_NEAR(glm::dot(direction_vector(letter.non_dominant->finger), direction_vector(letter.non_dominant->palm)),
                  0.0f, 1e-6f)
          << letter.symbol;
      EXPECT_NE(letter.site, BslContactSite::None) << letter.symbol;
    }
    for (Hand dominant : {Hand::Right, Hand::Left}) {
      const HandFrame d = dominant_frame(letter, dominant);
      EXPECT_NEAR(glm::dot(d.finger, d.palm), 0.0f, 1e-5f);
      EXPECT_EQ(non_dominant_frame(letter, dominant).has_value(), letter.non_dominant.has_value());
    }
  }
  for (char c = 'A'; c <= 'Z'; ++c) EXPECT_TRUE(seen.count(c)) << c;
  EXPECT_EQ(bsl_alphabet().size(), 26u);
  // Vowels: dominant index tip on the fingertips of the spread hand, thumb to little finger.
  const std::pair<char, BslContactSite> vowels[] = {{'A', BslContactSite::ThumbTip},
                                                    {'E', BslContactSite::IndexTip},
                                                    {'I', BslContactSite::MiddleTip},
                                                    {'O', BslContactSite::RingTip},
                                                    {'U', BslContactSite::PinkyTip}};
  for (const auto& [symbol, site] : vowels) {
    const BslLetter& v = *find_bsl_letter(symbol);
    EXPECT_EQ(v.site, site) << symbol;
    EXPECT_EQ(v.part, BslDominantPart::IndexTip) << symbol;
    ASSERT_TRUE(v.non_dominant.has_value());
    for (std::size_t f = 0; f < 4; ++f) EXPECT_LT(v.non_dominant->posture.fingers[f].mcp, 0.1f);  // spread hand
  }
  EXPECT_FALSE(find_bsl_letter('C')->non_dominant.has_value());  // C is one-handed
  EXPECT_TRUE(find_bsl_letter('J')->movement.has_value());
  EXPECT_EQ(find_bsl_letter('3'), nullptr);
  // A left-handed signer's frames are the right-handed ones mirrored l ↔ r.
  const BslLetter& f = *find_bsl_letter('F');
  const vec3 r = dominant_frame(f, Hand::Right).finger, l = dominant_frame(f, Hand::Left).finger;
  EXPECT_NEAR(l.x, -r.x, 1e-6f);
  EXPECT_NEAR(l.z, r.z, 1e-6f);
}

TEST(FingerspellingPlan, FluentAslRunsAtSixLettersPerSecond) {
  const SpellingPlan plan = plan_spelling("gestura", ManualAlphabet::Asl);
  ASSERT_EQ(plan.letters.size(), 7u);
  EXPECT_EQ(plan.letters_per_second, 6.0f);
  for (std::size_t k = 0; k < plan.letters.size(); ++k) {
    const LetterTarget& t = plan.letters[k];
    EXPECT_EQ(t.letter, std::string("GESTURA")[k]);
    EXPECT_EQ(t.index, static_cast<int>(k));
    EXPECT_LT(t.start, t.reached);
    EXPECT_LT(t.reached, t.end);
    if (k > 0) {
      EXPECT_NEAR(t.start, plan.letters[k - 1].end, 1e-6f);
    }
    if (k + 1 < plan.letters.size()) {
      EXPECT_NEAR(t.end - t.start, 1.0f / 6.0f, 1e-5f);
    }
  }
  // Interior letters average within the stated 5–7 letters/s; the last letter is held longer.
  const float interior = plan.letters[6].start / 6.0f;
  EXPECT_GE(1.0f / interior, 5.0f);
  EXPECT_LE(1.0f / interior, 7.0f);
  EXPECT_NEAR(plan.letters.back().end - plan.letters.back().start, 1.0f / 6.0f + 0.25f, 1e-5f);
  EXPECT_NEAR(plan.duration, plan.letters.back().end, 1e-6f);
  // Careful spelling (names) is slower.
  const SpellingPlan careful = plan_spelling("gestura", ManualAlphabet::Asl, SpellingStyle::Careful);
  EXPECT_NEAR(careful.letters[0].end - careful.letters[0].start, 0.25f, 1e-6f);
  EXPECT_GT(careful.duration, plan.duration);
}

TEST(FingerspellingPlan, DoubledLettersAreMarkedAndMovingLettersTakeLonger) {
  const SpellingPlan plan = plan_spelling("Hello", ManualAlphabet::Asl);
  ASSERT_EQ(plan.letters.size(), 5u);
  EXPECT_EQ(plan.letters[2].doubled, DoubleMark::None);
  EXPECT_EQ(plan.letters[3].doubled, DoubleMark::Slide);
  EXPECT_LT(plan.letters[3].offset.x, -0.03f);  // slid toward the dominant (right) side
  EXPECT_EQ(plan.letters[4].offset.x, 0.0f);    // the next letter returns to the spelling place
  const SpellingPlan jazz = plan_spelling("JAZZ", ManualAlphabet::Asl);
  EXPECT_TRUE(jazz.letters[0].has_movement);
  EXPECT_NEAR(jazz.letters[0].end - jazz.letters[0].start, 2.0f / 6.0f, 1e-5f);
  EXPECT_EQ(jazz.letters[3].doubled, DoubleMark::Bounce);  // a moving letter repeats in place
  const SpellingPlan bsl = plan_spelling("BOOK", ManualAlphabet::Bsl);
  EXPECT_EQ(bsl.letters[2].doubled, DoubleMark::Bounce);
  EXPECT_EQ(bsl.letters_per_second, 5.0f);
  // Doubling is within a word only.
  const SpellingPlan two = plan_spelling("a a", ManualAlphabet::Asl);
  EXPECT_EQ(two.letters[1].doubled, DoubleMark::None);
  EXPECT_EQ(two.letters[1].word, 1);
  EXPECT_NEAR(two.letters[1].start - two.letters[0].end, 0.35f, 1e-5f);
}

TEST(FingerspellingPlan, BadInputIsRejectedWithItsPosition) {
  try {
    plan_spelling("ab3", ManualAlphabet::Bsl);
    FAIL() << "digit accepted in BSL";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().index, 2);
    EXPECT_NE(std::string(e.what()).find("'3'"), std::string::npos);
  }
  try {
    plan_spelling(std::string("ok\xff", 3), ManualAlphabet::Asl);
    FAIL() << "binary byte accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().index, 2);
    EXPECT_NE(std::string(e.what()).find("0xFF"), std::string::npos);
  }
  EXPECT_THROW(plan_spelling("", ManualAlphabet::Asl), Error);
  EXPECT_THROW(plan_spelling("   ", ManualAlphabet::Asl), Error);
  EXPECT_THROW(plan_spelling(std::string(300, 'a'), ManualAlphabet::Asl), Error);
  SpellingOptions too_fast;
  too_fast.letters_per_second = 50.0f;
  EXPECT_THROW(plan_spelling("abc", ManualAlphabet::Asl, SpellingStyle::Fluent, too_fast), Error);
  SpellingOptions bad_fraction;
  bad_fraction.transition_fraction = 1.5f;
  EXPECT_THROW(plan_spelling("abc", ManualAlphabet::Asl, SpellingStyle::Fluent, bad_fraction), Error);
}

TEST(FingerspellingPlan, SamplingBlendsLettersWithMinimumJerkTransitions) {
  const SpellingPlan plan = plan_spelling("all", ManualAlphabet::Asl);
  const LetterTarget& a = plan.letters[0];
  const LetterTarget& l1 = plan.letters[1];
  const LetterTarget& l2 = plan.letters[2];
  SpellingSample s = sample_spelling(plan, -1.0f);
  EXPECT_EQ(s.from, -1);
  EXPECT_EQ(s.to, 0);
  EXPECT_EQ(s.blend, 0.0f);
  s = sample_spelling(plan, a.reached);
  EXPECT_NEAR(s.blend, 1.0f, 1e-6f);
  s = sample_spelling(plan, 0.5f * (l1.start + l1.reached));
  EXPECT_EQ(s.from, 0);
  EXPECT_EQ(s.to, 1);
  EXPECT_NEAR(s.blend, 0.5f, 1e-5f);
  // The doubled L slides: halfway through its transition the hand is halfway to the offset.
  s = sample_spelling(plan, 0.5f * (l2.start + l2.reached));
  EXPECT_EQ(l2.doubled, DoubleMark::Slide);
  EXPECT_NEAR(s.offset.x, 0.5f * l2.offset.x, 1e-5f);
  s = sample_spelling(plan, plan.duration + 5.0f);
  EXPECT_EQ(s.to, 2);
  EXPECT_NEAR(s.offset.x, l2.offset.x, 1e-6f);

  // A bounce dips 1.5 cm at the middle of the transition and is back at the letter.
  const SpellingPlan jazz = plan_spelling("jazz", ManualAlphabet::Asl);
  const LetterTarget& z2 = jazz.letters[3];
  EXPECT_NEAR(sample_spelling(jazz, 0.5f * (z2.start + z2.reached)).offset.y, -0.015f, 1e-5f);
  EXPECT_NEAR(sample_spelling(jazz, z2.reached).offset.y, 0.0f, 1e-6f);
  // Z's own movement runs from reaching the letter to the end of its slot (not the final hold).
  EXPECT_NEAR(sample_spelling(jazz, 0.5f * (z2.reached + z2.movement_end)).movement_progress, 0.5f, 1e-5f);
  EXPECT_NEAR(z2.movement_end, z2.start + 2.0f / 6.0f, 1e-5f);
  EXPECT_EQ(sample_spelling(jazz, jazz.letters[1].reached).movement_progress, 0.0f);  // A does not move
  EXPECT_THROW(sample_spelling(SpellingPlan{}, 0.0f), Error);
}
