// Fitting signed cues into subtitle timing, with a fake signer whose durations the test controls:
// each word takes 1 s at speed 1 (scaled by 1/speed) plus a 0.2 s return to rest that does not scale.
#include "gestura/sentence/subtitle_track.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

constexpr double kReturn = 0.2;

Skeleton one_arm() {
  Skeleton s;
  s.add_joint("root", -1, vec3(0.0f, 1.0f, 0.0f));
  s.add_joint("arm", 0, vec3(0.2f, 0.0f, 0.0f));
  return s;
}

struct FakeSigner {
  const Skeleton* skeleton;
  int calls = 0;

  SentencePerformance operator()(std::string_view text, float speed) {
    ++calls;
    SentencePerformance p;
    std::istringstream words{std::string(text)};
    std::string word;
    double t = 0.0;
    while (words >> word) {
      const double d = 1.0 / speed;
      for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      p.glosses.push_back({word, word, static_cast<float>(t), static_cast<float>(t + d)});
      t += d;
    }
    p.duration = static_cast<float>(t + kReturn);
    p.clip.resize_joints(skeleton->size());
    p.clip.duration = p.duration;
    p.clip.rotations[1].add(0.0f, quat(1, 0, 0, 0));
    p.clip.rotations[1].add(static_cast<float>(t / 2), glm::angleAxis(0.4f, vec3(1, 0, 0)));
    p.clip.rotations[1].add(p.duration, quat(1, 0, 0, 0));
    return p;
  }
};

SubtitleCue cue(int index, double start, double end, std::string text) {
  return {index, start, end, std::move(text), index};
}

SubtitleFitOptions no_slack() {
  SubtitleFitOptions o;
  o.slack = 0.0f;
  return o;
}

}  // namespace

TEST(SubtitleTrack, FitsAtNormalSpeed) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const auto t = fit_subtitles({cue(1, 1.0, 4.0, "hello there")}, std::ref(signer), s, no_slack());
  ASSERT_EQ(t.cues.size(), 1u);
  const FittedCue& c = t.cues[0];
  EXPECT_EQ(c.fit, CueFit::InTime);
  EXPECT_TRUE(c.fitted());
  EXPECT_FLOAT_EQ(c.speed, 1.0f);
  EXPECT_DOUBLE_EQ(c.start, 1.0);
  EXPECT_NEAR(c.duration, 2.2, 1e-6);
  EXPECT_DOUBLE_EQ(c.available, 3.0);
  EXPECT_EQ(c.glosses, (std::vector<std::string>{"HELLO", "THERE"}));
  EXPECT_EQ(signer.calls, 1);
  EXPECT_FLOAT_EQ(t.clip.duration, 4.0f);  // the last cue's end
  EXPECT_NO_THROW(validate(t.clip, s));
  EXPECT_FLOAT_EQ(t.clip.rotations[1].times.front(), 1.0f);
}

TEST(SubtitleTrack, SpeedsUpWithinTheLimit) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  // 2 words need 2.2 s; the window is 1.7 s: 2/speed + 0.2 <= 1.7 needs speed >= 4/3.
  const auto t = fit_subtitles({cue(1, 0.0, 1.7, "a b"), cue(2, 10.0, 11.5, "c")}, std::ref(signer), s, no_slack());
  const FittedCue& c = t.cues[0];
  EXPECT_EQ(c.fit, CueFit::InTime);
  EXPECT_GE(c.speed, 4.0f / 3.0f);
  EXPECT_LE(c.speed, 1.5f);
  EXPECT_LE(c.duration, 1.7);
  EXPECT_EQ(t.cues[1].fit, CueFit::InTime);
  EXPECT_FLOAT_EQ(t.cues[1].speed, 1.0f);
}

TEST(SubtitleTrack, SlackCountsAsInTime) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  SubtitleFitOptions o;
  o.slack = 0.25f;
  const auto t = fit_subtitles({cue(1, 0.0, 2.0, "a b"), cue(2, 5.0, 6.0, "c")}, std::ref(signer), s, o);
  EXPECT_EQ(t.cues[0].fit, CueFit::InTime);
  EXPECT_FLOAT_EQ(t.cues[0].speed, 1.0f);  // 2.2 s <= 2.0 + 0.25
}

TEST(SubtitleTrack, SpillsIntoTheGapAtTheLowestSpeedThatFits) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  // At 1.5× the 2 words take 1.53 s > 1 s window; the gap to cue 2 (at 2 s) fits them at ~1.1×.
  const auto t = fit_subtitles({cue(1, 0.0, 1.0, "a b"), cue(2, 2.0, 4.0, "c")}, std::ref(signer), s, no_slack());
  const FittedCue& c = t.cues[0];
  EXPECT_EQ(c.fit, CueFit::Spilled);
  EXPECT_TRUE(c.fitted());
  EXPECT_DOUBLE_EQ(c.available, 2.0);
  EXPECT_LE(c.duration, 2.0);
  EXPECT_GE(c.speed, 1.1f);
  EXPECT_LT(c.speed, 1.3f);
  EXPECT_DOUBLE_EQ(t.cues[1].start, 2.0);  // not delayed
}

TEST(SubtitleTrack, ReportsTheUnfitAndShiftsTheNextCue) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const auto t = fit_subtitles({cue(4, 0.0, 1.0, "a b c d"), cue(5, 1.5, 5.0, "e")}, std::ref(signer), s, no_slack());
  const FittedCue& bad = t.cues[0];
  EXPECT_EQ(bad.fit, CueFit::Overran);
  EXPECT_FALSE(bad.fitted());
  EXPECT_EQ(bad.index, 4);
  EXPECT_FLOAT_EQ(bad.speed, 1.5f);
  EXPECT_NEAR(bad.needed, 4.0 / 1.5 + kReturn, 1e-5);
  EXPECT_DOUBLE_EQ(bad.available, 1.5);
  EXPECT_EQ(bad.glosses.size(), 4u);  // signed whole, not truncated
  const FittedCue& next = t.cues[1];
  EXPECT_NEAR(next.start, bad.needed, 1e-5);  // waits for the overrun signing
  EXPECT_EQ(next.fit, CueFit::InTime);
  EXPECT_NO_THROW(validate(t.clip, s));
  EXPECT_FLOAT_EQ(t.clip.duration, 5.0f);
  EXPECT_LE(signer.calls, 2 * 4 + 1);  // bounded by max_attempts per window
}

TEST(SubtitleTrack, LastCueMayRunPastTheEndOfTheProgramme) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const auto t = fit_subtitles({cue(1, 0.0, 1.0, "a b c d")}, std::ref(signer), s, no_slack());
  EXPECT_EQ(t.cues[0].fit, CueFit::Spilled);  // nothing follows: the gap is open-ended
  EXPECT_FLOAT_EQ(t.cues[0].speed, 1.0f);
  EXPECT_NEAR(t.clip.duration, 4.2f, 1e-5f);
}

TEST(SubtitleTrack, EmptyCuesAreSkippedAndRestHeld) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const auto t = fit_subtitles({cue(1, 0.0, 3.0, "a"), cue(2, 3.0, 4.0, ""), cue(3, 6.0, 8.0, "b")}, std::ref(signer),
                               s, no_slack());
  EXPECT_EQ(t.cues[1].fit, CueFit::Skipped);
  EXPECT_EQ(signer.calls, 2);
  const std::vector<float> times{0.0f, 0.5f, 1.2f, 6.0f, 6.5f, 7.2f};
  ASSERT_EQ(t.clip.rotations[1].times.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(t.clip.rotations[1].times[k], times[k], 1e-5f);
  EXPECT_NEAR(glm::angle(sample_track(t.clip.rotations[1], 4.0f)), 0.0f, 1e-4f);  // at rest between cues
  EXPECT_FLOAT_EQ(t.clip.duration, 8.0f);
}

TEST(SubtitleTrack, RefusesBadOptions) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  SubtitleFitOptions o;
  o.max_speed = 0.9f;
  EXPECT_THROW(fit_subtitles({}, std::ref(signer), s, o), Error);
  o.max_speed = 2.5f;
  EXPECT_THROW(fit_subtitles({}, std::ref(signer), s, o), Error);
  o = {};
  o.slack = -1.0f;
  EXPECT_THROW(fit_subtitles({}, std::ref(signer), s, o), Error);
  EXPECT_EQ(fit_subtitles({}, std::ref(signer), s, {}).clip.duration, 0.0f);
}

TEST(SubtitleTrack, SignerErrorsNameTheCue) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const SignFunction refusing = [&](std::string_view text, float speed) {
    if (text == "bad") throw Error("text refused");
    return signer(text, speed);
  };
  try {
    fit_subtitles({cue(1, 0.0, 2.0, "a"), cue(7, 3.0, 5.0, "bad")}, refusing, s, {});
    ADD_FAILURE() << "the refusal was swallowed";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "line 7: cue 7: text refused");
  }
}

namespace {

// A signer whose hands are raised (elbow at 0.5 rad) from its first sign's start (0.1 s) to its last
// sign's end, at rest before and after.
SentencePerformance raised_arm_performance(const Skeleton& s, std::string_view text) {
  SentencePerformance p;
  const float signing = 0.5f * static_cast<float>(std::count(text.begin(), text.end(), ' ') + 1);
  p.glosses.push_back({"SIGN", std::string(text), 0.1f, 0.1f + signing});
  p.duration = 0.1f + signing + 0.4f;
  p.clip.resize_joints(s.size());
  p.clip.duration = p.duration;
  QuatTrack& elbow = p.clip.rotations[static_cast<std::size_t>(s.find("r_elbow"))];
  const quat raised = glm::angleAxis(0.5f, vec3(1, 0, 0));
  elbow.add(0.0f, quat(1, 0, 0, 0));
  elbow.add(0.1f, raised);
  elbow.add(0.1f + signing, raised);
  elbow.add(p.duration, quat(1, 0, 0, 0));
  return p;
}

float elbow_angle(const SubtitleTrack& t, const Skeleton& s, float time) {
  const quat q = sample_track(t.clip.rotations[static_cast<std::size_t>(s.find("r_elbow"))], time);
  return 2.0f * std::acos(std::min(1.0f, std::abs(q.w)));
}

}  // namespace

TEST(SubtitleTrack, CloseCuesAreCoarticulatedWithoutRest) {
  Skeleton s;
  s.add_joint("root", -1, vec3(0.0f, 1.0f, 0.0f));
  s.add_joint("r_elbow", 0, vec3(0.2f, 0.0f, 0.0f));
  const auto sign = [&](std::string_view text, float) { return raised_arm_performance(s, text); };
  // Cue 1 signs 0.1–0.6 s and is back at rest at 1.0 s; cue 2 starts at 1.2 s, its first sign at
  // 1.3 s: 0.7 s after cue 1's last sign, so the hands stay up.
  const auto close = fit_subtitles({cue(1, 0.0, 1.0, "a"), cue(2, 1.2, 2.0, "b")}, sign, s, no_slack());
  ASSERT_EQ(close.cues.size(), 2u);
  EXPECT_FALSE(close.cues[0].coarticulated);
  EXPECT_TRUE(close.cues[1].coarticulated);
  for (float t = 0.6f; t <= 1.3f; t += 0.05f) EXPECT_NEAR(elbow_angle(close, s, t), 0.5f, 1e-3f) << t;
  // 2 s apart: the hands rest between the cues.
  const auto apart = fit_subtitles({cue(1, 0.0, 1.0, "a"), cue(2, 2.5, 3.5, "b")}, sign, s, no_slack());
  EXPECT_FALSE(apart.cues[1].coarticulated);
  EXPECT_NEAR(elbow_angle(apart, s, 1.5f), 0.0f, 1e-3f);
}

// A television programme is hours long. Every cue here overruns its 10 s window (18 words take 12 s
// even at 1.5×), so each next cue starts exactly where the previous signing ended: the case where a
// float clock once refused cue after cue ("placed at 277.666656 s, before the timeline's end at
// 277.666687 s"). Three hours, a cue every 10 s: all placed, each key on the programme within half a
// millisecond of its exact (double) time.
TEST(SubtitleTrack, AThreeHourProgrammeKeepsEveryCueInOrderAndOnTime) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  std::vector<SubtitleCue> cues;
  for (int i = 0; i < 3 * 360; ++i)
    cues.push_back(cue(i + 1, 10.0 * i + 0.37, 10.0 * i + 10.37, i % 2 ? "a b c d e f g h i j k l m n o p q r" : "a b"));
  const auto t = fit_subtitles(cues, std::ref(signer), s, no_slack());
  ASSERT_EQ(t.cues.size(), cues.size());
  EXPECT_NO_THROW(validate(t.clip, s));
  const std::vector<float>& keys = t.clip.rotations[1].times;
  double previous_end = 0.0;
  int waited = 0;  // cues that started where the previous signing ended
  for (const FittedCue& c : t.cues) {
    EXPECT_GE(c.start, std::max(c.cue_start, previous_end)) << "cue " << c.index;
    waited += c.start == previous_end && c.start > c.cue_start;
    // The performance's mid key (at t/2 of its signing) and its end are on the programme where
    // the double clock puts them.
    const double words = static_cast<double>(c.glosses.size());
    for (const double local : {words / c.speed / 2.0, c.duration}) {
      const double exact = c.start + local;
      const auto k = std::lower_bound(keys.begin(), keys.end(), static_cast<float>(exact - 1e-3));
      ASSERT_NE(k, keys.end()) << "cue " << c.index;
      EXPECT_NEAR(*k, exact, 5e-4) << "cue " << c.index;
    }
    previous_end = c.start + c.duration;
  }
  EXPECT_EQ(waited, 539);  // every cue after an overrun but the first
  EXPECT_GE(t.cues.back().start, 3 * 3600.0 - 10.0);
  EXPECT_NEAR(t.clip.duration, previous_end, 1e-3);
}

TEST(SubtitleTrack, AProgrammePastTheLongestTimelineIsRefusedNamingTheCue) {
  const Skeleton s = one_arm();
  FakeSigner signer{&s};
  const double day = 24.0 * 3600.0;
  try {
    fit_subtitles({cue(1, 0.0, 2.0, "a"), cue(2, day - 1.0, day + 5.0, "a b c")}, std::ref(signer), s, no_slack());
    ADD_FAILURE() << "a cue ending past 24 hours was placed";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cue 2"), std::string::npos) << what;
    EXPECT_NE(what.find("kMaxTimelineSeconds"), std::string::npos) << what;
  }
}
