// PlaybackContext: sampling through the context gives exactly the pose CompressedClip::sample gives,
// whatever the order of the times (forward at various rates, backward, jumps, outside the clip),
// on both SIMD paths, for clips whose tracks keep every frame or only some key frames.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/compress/playback_context.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

constexpr SimdPath kPaths[] = {SimdPath::Portable, SimdPath::Avx2};
bool available(SimdPath path) { return path != SimdPath::Avx2 || cpu_has_avx2_fma(); }

struct Subject {
  Skeleton skeleton = synthetic_humanoid();
  Clip clip = synthetic_clip(skeleton, 4.0f, 30.0f);
};

const Subject& subject() {
  static const Subject s;
  return s;
}

CompressedClip compressed_at(float bound) {
  CompressionSettings settings;
  settings.max_error = bound;
  return compress(subject().clip, subject().skeleton, settings);
}

// Bitwise: the context promises the stateless decoder's exact values.
void expect_identical(const Pose& a, const Pose& b, float t) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.rotations.data(), b.rotations.data(), a.size() * sizeof(quat)), 0) << "rotations at t = " << t;
  EXPECT_EQ(std::memcmp(a.translations.data(), b.translations.data(), a.size() * sizeof(vec3)), 0) << "translations at t = " << t;
  EXPECT_EQ(std::memcmp(a.scales.data(), b.scales.data(), a.size() * sizeof(vec3)), 0) << "scales at t = " << t;
}

std::vector<float> playback_times(float duration) {
  std::vector<float> times;
  for (float t = 0.0f; t <= duration; t += 1.0f / 60.0f) times.push_back(t);         // forward at 60 fps
  for (float t = duration; t >= 0.0f; t -= 1.0f / 24.0f) times.push_back(t);         // backward
  for (float t = 0.0f; t <= duration; t += 0.25f) times.push_back(t);                // forward, skipping keys
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> any(-0.5f, duration + 0.5f);                // jumps, also outside
  for (int i = 0; i < 200; ++i) times.push_back(any(rng));
  times.push_back(duration);  // the last frame exactly
  times.push_back(std::numeric_limits<float>::quiet_NaN());
  times.push_back(1e9f);
  return times;
}

}  // namespace

TEST(PlaybackContext, GivesTheStatelessDecodersPoseBitForBit) {
  for (float bound : {1e-4f, 3e-3f, 1e-2f}) {  // every frame a key … few keys with keysets
    const CompressedClip c = compressed_at(bound);
    bool has_keyset = false;
    for (const GclTrack& t : c.tracks()) has_keyset |= t.keyset != nullptr;
    if (bound >= 1e-2f) {
      EXPECT_TRUE(has_keyset) << "the coarse clip should drop keys";
    }
    for (SimdPath path : kPaths) {
      if (!available(path)) continue;
      PlaybackContext context;
      Pose expected = rest_pose(subject().skeleton), got = expected;
      for (float t : playback_times(c.duration())) {
        c.sample(t, expected);
        context.sample(c, t, got, path);
        SCOPED_TRACE("bound " + std::to_string(bound) + (path == SimdPath::Avx2 ? ", AVX2" : ", portable"));
        expect_identical(got, expected, t);
      }
    }
  }
}

TEST(PlaybackContext, RebindsToAnotherClipAndChecksThePoseSize) {
  const CompressedClip fine = compressed_at(1e-4f), coarse = compressed_at(1e-2f);
  PlaybackContext context;
  Pose expected = rest_pose(subject().skeleton), got = expected;
  for (int i = 0; i < 10; ++i) {
    const CompressedClip& c = i % 2 ? coarse : fine;
    const float t = 0.37f * static_cast<float>(i);
    c.sample(t, expected);
    context.sample(c, t, got);
    expect_identical(got, expected, t);
  }
  Pose wrong;
  wrong.resize(3);
  EXPECT_THROW(context.sample(fine, 0.5f, wrong), Error);
}

}  // namespace gestura
