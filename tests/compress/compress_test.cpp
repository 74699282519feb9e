// Clip compression: the error bound holds when measured independently (original clip sampled by the
// anim sampler vs the decoder, both through local_to_model, virtual points 3 cm along each joint
// axis), files round-trip, and malformed files give clear errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Largest virtual-point displacement over `times`, computed here, not by the library's metric.
float independent_error(const Clip& clip, const Skeleton& skeleton, const CompressedClip& c, const std::vector<float>& times) {
  const Pose rest = rest_pose(skeleton);
  Pose original = rest, decoded = rest;
  std::vector<mat4> a(skeleton.size()), b(skeleton.size());
  float worst = 0.0f;
  for (float t : times) {
    sample_clip(clip, t, WrapMode::Clamp, rest, original);
    c.sample(t, decoded);
    local_to_model(skeleton, original, a);
    local_to_model(skeleton, decoded, b);
    for (std::size_t j = 0; j < skeleton.size(); ++j)
      for (int axis = 0; axis < 3; ++axis) {
        vec3 offset(0.0f);
        offset[axis] = 0.03f;
        const vec3 pa = vec3(a[j] * vec4(offset, 1.0f)), pb = vec3(b[j] * vec4(offset, 1.0f));
        worst = std::max(worst, glm::length(pa - pb));
      }
  }
  return worst;
}

std::vector<float> frame_times(float duration, float rate) {
  std::vector<float> times;
  for (int f = 0; static_cast<float>(f) / rate <= duration + 1e-6f; ++f) times.push_back(static_cast<float>(f) / rate);
  return times;
}

// A two-joint arm swinging through a half turn: the quaternion components all cross zero.
void half_turn_clip(Skeleton& s, Clip& clip) {
  s.add_joint("root", -1, vec3(0.0f));
  s.add_joint("arm", 0, vec3(0.0f, 0.5f, 0.0f));
  s.add_joint("hand", 1, vec3(0.0f, 0.5f, 0.0f));
  clip.resize_joints(3);
  clip.duration = 2.0f;
  for (int f = 0; f <= 60; ++f) {
    const float t = static_cast<float>(f) / 30.0f;
    clip.rotations[1].add(t, glm::angleAxis(kPi * t, glm::normalize(vec3(0.3f, 1.0f, 0.2f))));
    clip.translations[0].add(t, vec3(0.1f * t, 0.0f, 0.0f));
  }
  make_continuous(clip.rotations[1]);
}

TEST(Compress, HonoursTheErrorBoundOnTheSyntheticHumanoid) {
  const Skeleton s = synthetic_humanoid();
  ASSERT_EQ(s.size(), 67u);
  const Clip clip = synthetic_clip(s, 3.0f);
  for (float bound : {1e-4f, 1e-3f}) {
    CompressionReport report;
    CompressionSettings settings;
    settings.max_error = bound;
    const CompressedClip c = compress(clip, s, settings, &report);
    EXPECT_TRUE(report.within_bound);
    EXPECT_LE(independent_error(clip, s, c, frame_times(clip.duration, 30.0f)), bound) << bound;
    EXPECT_LE(report.max_error, bound);
    EXPECT_LE(report.p99_error, report.max_error);
    const ClipError measured = measure_error(clip, s, c);
    EXPECT_EQ(measured.max, report.max_error);
    EXPECT_EQ(measured.p99, report.p99_error);
    EXPECT_EQ(report.bytes, c.bytes().size());
    EXPECT_LT(c.bytes().size() * 4, report.raw_bytes) << "expected at least 4:1 at " << bound;
  }
}

TEST(Compress, LooserBoundGivesSmallerClip) {
  const Skeleton s = synthetic_humanoid();
  const Clip clip = synthetic_clip(s, 2.0f);
  CompressionSettings tight, loose;
  tight.max_error = 1e-4f;
  loose.max_error = 1e-2f;
  EXPECT_LT(compress(clip, s, loose).bytes().size(), compress(clip, s, tight).bytes().size());
}

TEST(Compress, BetweenFramesStaysNearTheBound) {
  const Skeleton s = synthetic_humanoid();
  const Clip clip = synthetic_clip(s, 2.0f);
  CompressionSettings settings;
  settings.max_error = 1e-3f;
  const CompressedClip c = compress(clip, s, settings);
  std::vector<float> times;
  for (float t = 0.0f; t < clip.duration; t += 1.0f / 73.0f) times.push_back(t);
  // Between samples both sides interpolate linearly from values within the bound; nlerp's slight
  // non-linearity may add a hair.
  EXPECT_LE(independent_error(clip, s, c, times), 1.05f * settings.max_error);
}

TEST(Compress, HalfTurnRotationsAndRootTranslation) {
  Skeleton s;
  Clip clip;
  half_turn_clip(s, clip);
  for (float bound : {1e-5f, 1e-4f, 1e-2f}) {
    CompressionSettings settings;
    settings.max_error = bound;
    CompressionReport report;
    const CompressedClip c = compress(clip, s, settings, &report);
    EXPECT_TRUE(report.within_bound) << bound;
    EXPECT_LE(independent_error(clip, s, c, frame_times(clip.duration, 30.0f)), bound) << bound;
  }
}

// Keys at irregular times with spline interpolation, animated scale and a non-root translation:
// the compressed clip is sampled at 30 Hz and must hold the bound at those samples.
TEST(Compress, IrregularSplineClipWithScaleAndTranslation) {
  Skeleton s;
  s.add_joint("root", -1, vec3(0.0f));
  s.add_joint("spine", 0, vec3(0.0f, 0.4f, 0.0f));
  s.add_joint("arm", 1, vec3(0.2f, 0.3f, 0.0f));
  s.add_joint("hand", 2, vec3(0.5f, 0.0f, 0.0f));
  Clip clip;
  clip.resize_joints(4);
  clip.duration = 2.0f;
  std::uint64_t state = 17;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  };
  for (int joint = 1; joint < 3; ++joint) {
    float t = 0.0f;
    while (t < 2.0f) {
      clip.rotations[static_cast<std::size_t>(joint)].add(t, glm::normalize(quat(1.0f, next() - 0.5f, next() - 0.5f, next() - 0.5f)));
      t += 0.1f + 0.3f * next();
    }
    clip.rotations[static_cast<std::size_t>(joint)].add(2.0f, quat(1, 0, 0, 0));
    clip.rotations[static_cast<std::size_t>(joint)].interpolation = Interpolation::Squad;
    make_continuous(clip.rotations[static_cast<std::size_t>(joint)]);
  }
  for (float t : {0.0f, 0.7f, 1.3f, 2.0f}) {
    clip.scales[2].add(t, vec3(1.0f + 0.2f * next()));
    clip.translations[1].add(t, vec3(0.05f * next(), 0.4f, 0.0f));
  }
  clip.scales[2].interpolation = Interpolation::CatmullRom;
  for (float bound : {1e-4f, 1e-3f}) {
    CompressionSettings settings;
    settings.max_error = bound;
    CompressionReport report;
    const CompressedClip c = compress(clip, s, settings, &report);
    EXPECT_TRUE(report.within_bound) << bound;
    EXPECT_LE(independent_error(clip, s, c, frame_times(clip.duration, 30.0f)), bound) << bound;
  }
}

TEST(Compress, StillClipIsTiny) {
  const Skeleton s = synthetic_humanoid();
  Clip clip;
  clip.resize_joints(s.size());
  clip.duration = 5.0f;
  CompressionReport report;
  const CompressedClip c = compress(clip, s, {}, &report);
  // Header, one descriptor byte per identity track and constants for the bone offsets.
  EXPECT_LT(c.bytes().size(), 40u + s.size() * (3 + 12));
  EXPECT_EQ(report.max_error, 0.0f);
  Pose pose = rest_pose(s);
  c.sample(2.0f, pose);
  for (std::size_t j = 0; j < s.size(); ++j) EXPECT_NEAR(glm::length(pose.translations[j] - s.rest_translations[j]), 0.0f, 1e-6f);
}

TEST(Compress, RejectsBadSettings) {
  const Skeleton s = synthetic_humanoid();
  const Clip clip = synthetic_clip(s, 0.5f);
  CompressionSettings bad;
  bad.max_error = 0.0f;
  EXPECT_THROW(compress(clip, s, bad), Error);
  bad = {};
  bad.sample_rate = -30.0f;
  EXPECT_THROW(compress(clip, s, bad), Error);
}

struct GclFiles : ::testing::Test {
  Skeleton s;
  Clip clip;
  std::vector<std::uint8_t> bytes;
  void SetUp() override {
    half_turn_clip(s, clip);
    CompressionSettings settings;
    settings.max_error = 1e-3f;
    bytes = compress(clip, s, settings).bytes();
  }
  std::string message_for(std::vector<std::uint8_t> b) {
    try {
      CompressedClip::from_bytes(std::move(b), "clip.gcl");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(GclFiles, SaveAndLoadRoundTrip) {
  const std::string path = ::testing::TempDir() + "roundtrip.gcl";
  CompressedClip original = CompressedClip::from_bytes(bytes);
  save_gcl(path, original);
  const CompressedClip loaded = load_gcl(path);
  EXPECT_EQ(loaded.bytes(), bytes);
  Pose a = rest_pose(s), b = rest_pose(s);
  original.sample(0.77f, a);
  loaded.sample(0.77f, b);
  for (std::size_t j = 0; j < s.size(); ++j) EXPECT_EQ(a.rotations[j], b.rotations[j]);
  std::remove(path.c_str());
}

TEST_F(GclFiles, EveryTruncationIsAClearError) {
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string m = message_for(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n)));
    ASSERT_FALSE(m.empty()) << "prefix of " << n << " bytes was accepted";
    EXPECT_NE(m.find("clip.gcl"), std::string::npos) << m;
    EXPECT_NE(m.find("byte "), std::string::npos) << m;
  }
}

TEST_F(GclFiles, HeaderDamageIsNamed) {
  auto with = [&](std::size_t at, std::uint8_t value) {
    std::vector<std::uint8_t> b = bytes;
    b[at] = value;
    return message_for(b);
  };
  EXPECT_NE(with(0, 'X').find("magic"), std::string::npos);
  EXPECT_NE(with(4, 9).find("unsupported version 9"), std::string::npos);
  EXPECT_NE(with(8, 0).find("joint count"), std::string::npos);  // low byte of 3 → 0
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_NE(message_for(longer).find("trailing"), std::string::npos);
}

TEST_F(GclFiles, RandomDamageNeverCrashes) {
  // The file itself decodes, to the clip within its bound: a decoder that refused everything would
  // fail here rather than pass below.
  const CompressedClip intact = CompressedClip::from_bytes(bytes, "clip.gcl");
  ASSERT_EQ(intact.joint_count(), s.size());
  EXPECT_LE(independent_error(clip, s, intact, frame_times(clip.duration, 30.0f)), 1e-3f * 1.0001f);
  // Flipped bytes either fail validation with an Error naming the file or decode to finite poses.
  std::uint64_t state = 99;
  int decoded = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> b = bytes;
    for (int k = 0; k < 3; ++k) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      b[(state >> 33) % b.size()] ^= static_cast<std::uint8_t>(1u + ((state >> 20) % 255u));
    }
    try {
      const CompressedClip c = CompressedClip::from_bytes(std::move(b), "clip.gcl");
      ++decoded;
      if (c.joint_count() != s.size()) continue;  // a consistent file for another skeleton
      Pose pose = rest_pose(s);
      for (float t : {0.0f, 0.5f, 1.9f, 5.0f}) {
        c.sample(t, pose);
        for (std::size_t j = 0; j < s.size(); ++j) ASSERT_TRUE(is_finite(pose.rotations[j]) && is_finite(pose.translations[j]));
      }
    } catch (const Error& e) {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("clip.gcl"), std::string::npos) << e.what();
    }
  }
  // Both outcomes happen: damage to key values leaves a valid file, damage to the layout does not.
  EXPECT_GT(decoded, 0);
  EXPECT_GT(refused, 0);
  EXPECT_EQ(decoded + refused, 300);
}

TEST(GclFile, MissingFileIsAClearError) {
  try {
    load_gcl("/nonexistent/dir/clip.gcl");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/clip.gcl"), std::string::npos);
  }
}

}  // namespace
}  // namespace gestura
