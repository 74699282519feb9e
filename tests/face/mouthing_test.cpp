#include "gestura/face/mouthing.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "gestura/core/error.hpp"
#include "gestura/face/expressions.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/face/phonemizer.hpp"

using namespace gestura;
using namespace gestura::face;
using gestura::Expression;

namespace {

float at(Clip& clip, std::string_view channel, float t) {
  if (clip.find_channel(std::string(channel)) < 0) return 0.0f;
  return sample_track(clip.channel(std::string(channel)), t);
}

// The viseme with the largest weight at time t.
std::string dominant_viseme(Clip& clip, float t) {
  std::string best;
  float best_w = 0.0f;
  for (std::string_view v : kVisemes)
    if (float w = at(clip, v, t); w > best_w) best_w = w, best = std::string(v);
  return best;
}

}  // namespace

TEST(FaceMouthing, MomClosesTheLipsAtStartAndEnd) {
  Clip clip;
  add_mouthing("mom", 1.0f, 1.6f, {}, clip);
  EXPECT_EQ(dominant_viseme(clip, 1.06f), "PP");
  EXPECT_EQ(dominant_viseme(clip, 1.54f), "PP");
  EXPECT_EQ(dominant_viseme(clip, 1.3f), "oh");  // eSpeak en-us: m 0 m, 0 = the LOT vowel
  EXPECT_GT(at(clip, kPP, 1.08f), 0.9f);
  EXPECT_LT(at(clip, kPP, 1.3f), 0.1f);
}

TEST(FaceMouthing, ArticulationStartsAndEndsWithTheSign) {
  Clip clip;
  const float start = 2.0f, end = 2.8f;
  add_mouthing("yesterday", start, end, {}, clip);
  ASSERT_FALSE(clip.channels.empty());
  float first = 1e9f, last = -1e9f;
  for (std::size_t c = 0; c < clip.channels.size(); ++c) {
    const FloatTrack& tr = clip.channels[c];
    ASSERT_FALSE(tr.empty()) << clip.channel_names[c];
    first = std::min(first, tr.times.front());
    last = std::max(last, tr.times.back());
    EXPECT_NEAR(sample_track(tr, start), 0.0f, 1e-5f) << clip.channel_names[c];
    EXPECT_NEAR(sample_track(tr, end), 0.0f, 1e-5f) << clip.channel_names[c];
  }
  EXPECT_FLOAT_EQ(first, start);
  EXPECT_FLOAT_EQ(last, end);
  // Moving from the first 10% of the sign: /j/ (ih) is visibly on.
  EXPECT_GT(at(clip, kIH, start + 0.06f), 0.3f);
  // And still moving in the last 10%: the -day diphthong (E).
  EXPECT_GT(at(clip, kE, end - 0.06f), 0.3f);
}

TEST(FaceMouthing, JawIsItsOwnChannel) {
  Clip clip;
  add_mouthing("mom", 0.0f, 0.6f, {}, clip);
  ASSERT_GE(clip.find_channel("jaw_open"), 0);
  // The jaw opens for the vowel and is shut while the lips close for m.
  EXPECT_GT(at(clip, kJawOpen, 0.3f), 0.5f);
  EXPECT_LT(at(clip, kJawOpen, 0.06f), 0.05f);
  // An expression written afterwards does not touch the jaw or the visemes.
  std::vector<FaceAction> smile;
  for (const auto& [channel, weight] : gestura::expression_weights(gestura::Expression::Joy))
    smile.push_back(make_action(channel, 0, 0.6f, weight));
  const FloatTrack jaw_before = clip.channel("jaw_open");
  const FloatTrack oh_before = clip.channel("oh");
  write_face_channels(smile, clip);
  EXPECT_EQ(clip.channel("jaw_open").values, jaw_before.values);
  EXPECT_EQ(clip.channel("oh").values, oh_before.values);
  EXPECT_GT(at(clip, kMouthSmileL, 0.3f), 0.5f);
}

TEST(FaceMouthing, ReducedAmplitudeScalesEveryWeight) {
  Clip full, half;
  add_mouthing("hello", 0.0f, 0.7f, {}, full);
  add_mouthing("hello", 0.0f, 0.7f, {0.5f}, half);
  float max_full = 0, max_half = 0;
  for (const FloatTrack& tr : full.channels) for (float v : tr.values) max_full = std::max(max_full, v);
  for (const FloatTrack& tr : half.channels) for (float v : tr.values) max_half = std::max(max_half, v);
  EXPECT_GT(max_full, 0.9f);
  EXPECT_LE(max_half, 0.5f + 1e-5f);
  EXPECT_GT(max_half, 0.3f);
  EXPECT_NEAR(at(half, kOH, 0.6f), 0.5f * at(full, kOH, 0.6f), 1e-4f);
}

TEST(FaceMouthing, LipsRoundBeforeARoundedVowel) {
  // "two" = t u: — the lips are already rounding during the t.
  Clip clip;
  add_mouthing("two", 0.0f, 0.5f, {}, clip);
  const auto ps = phonemize("two");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].symbol, "t");
  const float t_mid = 0.5f * ps[0].duration / (ps[0].duration + ps[1].duration) * 0.5f;
  EXPECT_GT(at(clip, kMouthPucker, t_mid), 0.1f);
  EXPECT_GT(at(clip, kDD, t_mid), 0.3f);
  // "tea" = t i: — no rounding at all.
  Clip tea;
  add_mouthing("tea", 0.0f, 0.5f, {}, tea);
  EXPECT_LT(tea.find_channel("mouthPucker"), 0);
}

TEST(FaceMouthing, FailureModesAreGraceful) {
  Clip clip;
  add_mouthing("", 0.0f, 1.0f, {}, clip);
  add_mouthing("...", 0.0f, 1.0f, {}, clip);
  add_mouthing("mom", 1.0f, 1.0f, {}, clip);  // zero-length sign
  add_mouthing("mom", 1.0f, 0.5f, {}, clip);  // reversed
  EXPECT_TRUE(clip.channels.empty());
  add_mouthing("naïve", 0.0f, 1.0f, {}, clip);
  EXPECT_FALSE(clip.channels.empty());
  EXPECT_THROW(add_mouthing(std::string(10000, 'm'), 0.0f, 1.0f, {}, clip), Error);
  EXPECT_THROW(add_mouthing("m\xc3", 0.0f, 1.0f, {}, clip), Error);
  EXPECT_THROW(add_mouthing("mom", 0.0f, INFINITY, {}, clip), Error);
}
