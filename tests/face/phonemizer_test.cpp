#include "gestura/face/phonemizer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>

#include "gestura/core/error.hpp"

using namespace gestura;
using namespace gestura::face;

namespace {

std::vector<std::string> symbols(const std::vector<Phoneme>& ps) {
  std::vector<std::string> out;
  for (const Phoneme& p : ps) out.push_back(p.symbol);
  return out;
}

bool is_vowel(const Phoneme& p) { return p.cls == PhonemeClass::vowel; }

}  // namespace

TEST(FacePhonemizer, HelloIsHVowelLRoundedVowel) {
  const auto ps = phonemize("hello");
  ASSERT_EQ(ps.size(), 4u) << testing::PrintToString(symbols(ps));
  EXPECT_EQ(ps[0].symbol, "h");
  EXPECT_TRUE(is_vowel(ps[1]));
  EXPECT_EQ(ps[2].symbol, "l");
  EXPECT_TRUE(is_vowel(ps[3]));
  // eSpeak writes the rounded back vowels with 'o'/'O'/'u'/'U' (oU = the GOAT diphthong).
  EXPECT_NE(std::string("oOuU").find(ps[3].symbol.front()), std::string::npos) << ps[3].symbol;
  EXPECT_EQ(ps[3].stress, Stress::primary);  // hel-LO
  EXPECT_EQ(ps[1].stress, Stress::none);
}

TEST(FacePhonemizer, ThankYouHasThetaEngKAndYou) {
  const auto s = symbols(phonemize("thank you"));
  ASSERT_GE(s.size(), 5u);
  EXPECT_EQ(s.front(), "T");  // θ
  const auto eng = std::find(s.begin(), s.end(), "N");  // ŋ
  ASSERT_NE(eng, s.end());
  ASSERT_NE(eng + 1, s.end());
  EXPECT_EQ(*(eng + 1), "k");
  EXPECT_EQ(s[s.size() - 2], "j");
  EXPECT_EQ(s.back().front(), 'u');
}

TEST(FacePhonemizer, YesterdayStressesTheFirstSyllable) {
  const auto ps = phonemize("yesterday");
  const auto s = symbols(ps);
  ASSERT_GE(s.size(), 6u);
  EXPECT_EQ(s[0], "j");
  EXPECT_TRUE(is_vowel(ps[1]));
  EXPECT_EQ(ps[1].stress, Stress::primary);
  EXPECT_EQ(s[2], "s");
  EXPECT_EQ(s[3], "t");
  EXPECT_EQ(s.back(), "eI");  // -day
}

TEST(FacePhonemizer, StressedVowelsOutlastConsonants) {
  const auto ps = phonemize("hello");
  for (const Phoneme& p : ps)
    if (!is_vowel(p)) {
      EXPECT_LT(p.duration, ps[3].duration) << p.symbol;
    }
  EXPECT_GT(ps[3].duration, ps[1].duration);  // stressed oU vs reduced schwa
}

TEST(FacePhonemizer, ParsesStressMarksAndSeparators) {
  const auto ps = parse_espeak_phonemes("j|'E|s|t|3|d|,eI b|r|'aU|n");
  ASSERT_EQ(ps.size(), 11u);
  EXPECT_EQ(ps[1].symbol, "E");
  EXPECT_EQ(ps[1].stress, Stress::primary);
  EXPECT_EQ(ps[6].symbol, "eI");
  EXPECT_EQ(ps[6].stress, Stress::secondary);
  EXPECT_EQ(ps[7].symbol, "b");
  EXPECT_EQ(ps[7].cls, PhonemeClass::stop);
  EXPECT_EQ(ps[9].symbol, "aU");
  EXPECT_TRUE(parse_espeak_phonemes("").empty());
  EXPECT_TRUE(parse_espeak_phonemes("|||  |").empty());
}

TEST(FacePhonemizer, ClauseBreakBecomesPause) {
  const auto ps = phonemize("hello, world");
  const auto pause = std::find_if(ps.begin(), ps.end(), [](const Phoneme& p) { return p.cls == PhonemeClass::pause; });
  ASSERT_NE(pause, ps.end());
  EXPECT_EQ(pause - ps.begin(), 4);
  EXPECT_EQ(ps.back().symbol, "d");
}

TEST(FacePhonemizer, FailureModesAreGraceful) {
  EXPECT_TRUE(phonemize("").empty());
  EXPECT_TRUE(phonemize("?!").empty());
  const auto cafe = phonemize("café");  // non-ASCII but valid UTF-8
  ASSERT_FALSE(cafe.empty());
  EXPECT_EQ(cafe.front().symbol, "k");
  EXPECT_NO_THROW(phonemize("日本"));
  EXPECT_THROW(phonemize(std::string("ab\xff\xfe" "cd")), Error);
  try {
    phonemize(std::string(10000, 'a'));
    FAIL() << "a 10k-character word must be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("limit"), std::string::npos) << e.what();
  }
}

TEST(FacePhonemizer, ConcurrentCallsAgree) {
  const auto expected = symbols(phonemize("yesterday"));
  std::vector<std::vector<std::string>> results(4);
  std::vector<std::thread> threads;
  for (auto& r : results)
    threads.emplace_back([&r] {
      for (int i = 0; i < 20; ++i) r = symbols(phonemize("yesterday"));
    });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, expected);
}
