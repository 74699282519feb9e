// A three-hour programme signed by the real Signer: the TV use of sign-language-interpreter.txt §1.
// One cue every 10 s for 3 hours (1,080 cues) read from SRT text, signed and placed on one
// timeline. Every cue must be placed in order, the programme must last the three hours, and a cue
// near the end must move exactly as the same sentence signed on its own (the programme's clock
// must not drift or lose precision late in the file).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "gestura/anim/track.hpp"
#include "gestura/io/subtitles.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sentence/subtitle_track.hpp"

namespace gestura {
namespace {

constexpr std::array<const char*, 4> kLines{"Hello.", "Thank you.", "My mother is at home.", "Where is the house?"};

std::string timestamp(double seconds) {
  const long ms = std::lround(seconds * 1000.0);
  char text[32];
  std::snprintf(text, sizeof text, "%02ld:%02ld:%02ld,%03ld", ms / 3600000, ms / 60000 % 60, ms / 1000 % 60, ms % 1000);
  return text;
}

// Cue i from 10 i + 0.5 s to 10 i + 7.5 s.
std::string three_hour_srt() {
  std::string srt;
  for (int i = 0; i < 3 * 360; ++i)
    srt += std::to_string(i + 1) + "\n" + timestamp(10.0 * i + 0.5) + " --> " + timestamp(10.0 * i + 7.5) + "\n" +
           kLines[static_cast<std::size_t>(i) % kLines.size()] + "\n\n";
  return srt;
}

TEST(LongProgramme, AThreeHourSrtWithACueEveryTenSecondsIsSignedInFull) {
  const Avatar avatar = build_avatar();
  Lexicon builtin = load_builtin_lexicon(builtin_lexicon_files());
  LayeredLexicon layers;
  layers.push_layer(builtin);
  const Signer signer(avatar, layers);

  const Subtitles subs = parse_subtitles(three_hour_srt(), SubtitleFormat::Srt, "three-hours.srt");
  ASSERT_EQ(subs.cues.size(), 1080u);
  const SignFunction sign = [&](std::string_view text, float speed) {
    SayOptions options;
    options.speed = speed;
    return signer.say(text, options);
  };
  const SubtitleTrack track = fit_subtitles(subs.cues, sign, avatar.skeleton, {});

  ASSERT_EQ(track.cues.size(), 1080u);
  EXPECT_NO_THROW(validate(track.clip, avatar.skeleton));
  for (const FittedCue& c : track.cues) {
    EXPECT_TRUE(c.fitted()) << "cue " << c.index << ": " << to_string(c.fit);
    EXPECT_DOUBLE_EQ(c.start, c.cue_start) << "cue " << c.index;  // 7 s windows: nothing waits
  }
  EXPECT_GE(track.clip.duration, static_cast<float>(3 * 3600 - 10));

  // The last cue, sampled on the programme (past 10,790 s), against the same sentence on its own.
  const FittedCue& last = track.cues.back();
  const SentencePerformance alone = sign(kLines[(1080 - 1) % kLines.size()], last.speed);
  const int wrist = avatar.skeleton.find("r_wrist");
  const int elbow = avatar.skeleton.find("r_elbow");
  ASSERT_GE(wrist, 0);
  ASSERT_GE(elbow, 0);
  int compared = 0;
  float moved = 0.0f;  // how far the elbow turns from rest during the cue: the comparison must see motion
  const quat elbow_rest = avatar.skeleton.rest_rotations[static_cast<std::size_t>(elbow)];
  for (float local = 0.1f; local < alone.duration; local += 0.1f) {
    const float programme = static_cast<float>(last.start + static_cast<double>(local));
    ++compared;
    for (const int j : {wrist, elbow}) {
      const quat a = sample_track(track.clip.rotations[static_cast<std::size_t>(j)], programme);
      const quat b = sample_track(alone.clip.rotations[static_cast<std::size_t>(j)], local);
      if (j == elbow) moved = std::max(moved, 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(a, elbow_rest)))));
      // Within what half a millisecond of motion can change (float spacing at 3 hours is ~1 ms).
      EXPECT_LT(2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(a, b)))), 0.01f) << "joint " << j << " at " << local << " s into the last cue";
    }
  }
  EXPECT_GE(compared, 15);     // the sentence lasts seconds
  EXPECT_GT(moved, 0.3f);      // and the arm signs it
}

}  // namespace
}  // namespace gestura
