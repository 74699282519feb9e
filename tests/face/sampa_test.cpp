#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gestura/face/sampa.hpp"

using namespace gestura::face;

namespace {

std::vector<std::string> symbols(const SampaReading& r) {
  std::vector<std::string> out;
  for (const Phoneme& p : r.phonemes) out.push_back(p.symbol);
  return out;
}

}  // namespace

TEST(FaceSampa, ReadsTheLongestSymbolFirst) {
  // "Australia" as written in the ISL data: long O:, a diphthong-free e, separators '_'.
  const SampaReading r = phonemes_from_sampa("O:stre_IljV");
  EXPECT_TRUE(r.unknown.empty());
  EXPECT_EQ(symbols(r), (std::vector<std::string>{"O:", "s", "t", "r", "e", "I", "l", "j", "V"}));
  // Without the separator, e and I are one diphthong.
  EXPECT_EQ(symbols(phonemes_from_sampa("eI")), (std::vector<std::string>{"eI"}));
  EXPECT_EQ(symbols(phonemes_from_sampa("tSi:z")), (std::vector<std::string>{"tS", "i:", "z"}));
}

TEST(FaceSampa, MapsOtherLanguagesSoundsToTheSameLipShape) {
  // German "Pfütze": the affricate pf is two phonemes, ü (y) is rounded like u, ts too is split.
  EXPECT_EQ(symbols(phonemes_from_sampa("pfYts@")), (std::vector<std::string>{"p", "f", "U", "t", "s", "@"}));
  EXPECT_EQ(symbols(phonemes_from_sampa("m{rId")), (std::vector<std::string>{"m", "a", "r", "I", "d"}));
}

TEST(FaceSampa, StressGoesToTheNextVowel) {
  const SampaReading r = phonemes_from_sampa("b@\"nA:n@");
  ASSERT_EQ(r.phonemes.size(), 6u);
  EXPECT_EQ(r.phonemes[1].stress, Stress::none);  // the schwa before the mark
  EXPECT_EQ(r.phonemes[3].symbol, "A:");
  EXPECT_EQ(r.phonemes[3].stress, Stress::primary);
  EXPECT_GT(r.phonemes[3].duration, r.phonemes[5].duration);  // stressed long vowel vs schwa
  EXPECT_EQ(r.phonemes[3].cls, PhonemeClass::vowel);
  EXPECT_EQ(r.phonemes[0].cls, PhonemeClass::stop);
}

TEST(FaceSampa, ReportsWhatIsNotSampaAndGoesOn) {
  const SampaReading r = phonemes_from_sampa("m#u\xff!");
  EXPECT_EQ(symbols(r), (std::vector<std::string>{"m", "u"}));
  EXPECT_EQ(r.unknown, std::string("#\xff!"));
  EXPECT_TRUE(phonemes_from_sampa("").phonemes.empty());
  // A lone length mark lengthens what came before.
  EXPECT_GT(phonemes_from_sampa("s:").phonemes.at(0).duration, phonemes_from_sampa("s").phonemes.at(0).duration);
}
