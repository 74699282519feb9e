#include <gtest/gtest.h>

#include <vector>

#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

FloatTrack scalar_track(Interpolation interpolation) {
  FloatTrack t;
  t.interpolation = interpolation;
  // Uneven spacing on purpose: tangents must be adjusted for it.
  const float times[] = {0.0f, 0.4f, 1.0f, 1.3f, 2.5f};
  const float values[] = {0.0f, 2.0f, -1.0f, 0.5f, 3.0f};
  for (int k = 0; k < 5; ++k) t.add(times[k], values[k]);
  return t;
}

float slope(const FloatTrack& t, float at, float h) { return (sample_track(t, at + h) - sample_track(t, at - h)) / (2 * h); }

// One-sided derivatives at a key, Richardson-extrapolated so curvature near the key does not
// masquerade as a tangent break (direction −1 = from the left, +1 = from the right).
float one_sided_slope(const FloatTrack& t, float at, float direction) {
  const float h = 2e-3f;
  auto d = [&](float step) { return direction * (sample_track(t, at + direction * step) - sample_track(t, at)) / step; };
  return 2 * d(h / 2) - d(h);
}

}  // namespace

TEST(Interpolation, EveryModePassesThroughItsKeys) {
  for (Interpolation mode : {Interpolation::Step, Interpolation::Linear, Interpolation::Cardinal,
                             Interpolation::CatmullRom, Interpolation::KochanekBartels}) {
    FloatTrack t = scalar_track(mode);
    t.tension = 0.3f;
    if (mode == Interpolation::KochanekBartels) t.tcb.assign(5, Tcb{0.2f, -0.4f, 0.5f});
    for (std::size_t k = 0; k < t.size(); ++k)
      EXPECT_NEAR(sample_track(t, t.times[k]), t.values[k], 1e-5f) << to_string(mode) << " key " << k;
  }
}

TEST(Interpolation, StepHoldsAndLinearIsLinear) {
  const FloatTrack step = scalar_track(Interpolation::Step);
  EXPECT_FLOAT_EQ(sample_track(step, 0.39f), 0.0f);
  const FloatTrack lin = scalar_track(Interpolation::Linear);
  EXPECT_NEAR(sample_track(lin, 0.2f), 1.0f, 1e-6f);
  EXPECT_NEAR(sample_track(lin, 0.7f), 0.5f, 1e-6f);
}

TEST(Interpolation, CatmullRomIsC1AtInteriorKeysEvenWithUnevenSpacing) {
  const FloatTrack t = scalar_track(Interpolation::CatmullRom);
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const float left = one_sided_slope(t, t.times[k], -1), right = one_sided_slope(t, t.times[k], 1);
    EXPECT_NEAR(left, right, 0.02f * (1 + std::abs(left))) << "key " << k;
    // And the velocity is the Catmull-Rom chord slope (non-uniform form).
    const float chord = (t.values[k + 1] - t.values[k - 1]) / (t.times[k + 1] - t.times[k - 1]);
    EXPECT_NEAR(0.5f * (left + right), chord, 0.02f * (1 + std::abs(chord))) << "key " << k;
  }
}

TEST(Interpolation, KochanekBartelsWithZeroContinuityIsC1AndZeroTcbIsCatmullRom) {
  FloatTrack kb = scalar_track(Interpolation::KochanekBartels);
  kb.tcb.assign(kb.size(), Tcb{0.4f, 0.0f, -0.3f});
  for (std::size_t k = 1; k + 1 < kb.size(); ++k) {
    const float left = one_sided_slope(kb, kb.times[k], -1), right = one_sided_slope(kb, kb.times[k], 1);
    EXPECT_NEAR(left, right, 0.02f * (1 + std::abs(left))) << "key " << k;
  }
  FloatTrack zero = scalar_track(Interpolation::KochanekBartels);
  zero.tcb.assign(zero.size(), Tcb{});
  const FloatTrack cr = scalar_track(Interpolation::CatmullRom);
  for (float x = 0.0f; x <= 2.5f; x += 0.05f) EXPECT_NEAR(sample_track(zero, x), sample_track(cr, x), 1e-5f);
}

TEST(Interpolation, ContinuityBreaksTheTangentAndTensionOneFlattensIt) {
  FloatTrack kb = scalar_track(Interpolation::KochanekBartels);
  kb.tcb.assign(kb.size(), Tcb{0.0f, 0.8f, 0.0f});
  const float left = one_sided_slope(kb, 1.0f, -1), right = one_sided_slope(kb, 1.0f, 1);
  EXPECT_GT(std::abs(left - right), 0.5f);  // a corner, as continuity ≠ 0 asks
  FloatTrack card = scalar_track(Interpolation::Cardinal);
  card.tension = 1.0f;
  EXPECT_NEAR(slope(card, 0.4f, 1e-3f), 0.0f, 0.05f);  // zero tangent at every key
}

TEST(Interpolation, SquadReducesToSlerpForEvenKeysOnOneGreatArc) {
  QuatTrack sq, sl;
  sq.interpolation = Interpolation::Squad;
  sl.interpolation = Interpolation::Slerp;
  for (int k = 0; k < 5; ++k) {
    const quat q = glm::angleAxis(deg(25.0f * static_cast<float>(k)), glm::normalize(vec3(1, 2, 0.5f)));
    sq.add(0.5f * static_cast<float>(k), q);
    sl.add(0.5f * static_cast<float>(k), q);
  }
  for (float x = 0.5f; x <= 1.5f; x += 0.01f) {
    const quat a = sample_track(sq, x), b = sample_track(sl, x);
    EXPECT_GT(std::abs(glm::dot(a, b)), 1.0f - 1e-6f) << "t " << x;
  }
}

TEST(Interpolation, SquadPassesThroughKeysAndIsSmoothOnACurvedPath) {
  QuatTrack t;
  t.interpolation = Interpolation::Squad;
  const vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}};
  for (int k = 0; k < 5; ++k) t.add(static_cast<float>(k), glm::angleAxis(0.6f, glm::normalize(axes[k])));
  make_continuous(t);
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_GT(std::abs(glm::dot(sample_track(t, t.times[k]), t.values[k])), 1.0f - 1e-6f);
  // Angular velocity continuous across an interior key (evenly timed keys).
  const float h = 1e-3f;
  auto omega = [&](float a, float b) {
    const quat d = glm::inverse(sample_track(t, a)) * sample_track(t, b);
    return 2.0f * vec3(d.x, d.y, d.z) / (b - a);
  };
  const vec3 left = omega(2.0f - h, 2.0f), right = omega(2.0f, 2.0f + h);
  EXPECT_LT(glm::length(left - right), 0.05f * glm::length(left) + 0.01f);
}

TEST(Interpolation, EulerKeysBecomeRotationsWithoutFlips) {
  // Yaw keyed 170° then −170° (a wrapped angle, as mocap writes it): the raw quaternions land on
  // opposite hemispheres; the track must take the short 20° way through 180°, not spin 340°.
  const std::vector<float> times{0.0f, 1.0f};
  const std::vector<vec3> angles{vec3(0, deg(170), 0), vec3(0, deg(-170), 0)};
  QuatTrack t = rotation_track_from_euler(times, angles, RotationOrder::ZXY, Interpolation::Linear);
  const quat mid = sample_track(t, 0.5f);
  EXPECT_GT(std::abs(glm::dot(mid, glm::angleAxis(kPi, vec3(0, 1, 0)))), 1.0f - 1e-5f);
}

TEST(Interpolation, ValidationNamesTheKey) {
  FloatTrack t = scalar_track(Interpolation::Linear);
  t.times[3] = 0.2f;
  try {
    validate_track(t, "channel 'x'");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("key 3"), std::string::npos);
  }
  QuatTrack q;
  q.add(0, quat(0, 0, 0, 0));
  EXPECT_THROW(validate_track(q, "r"), Error);
  FloatTrack bad = scalar_track(Interpolation::Slerp);
  EXPECT_THROW(validate_track(bad, "s"), Error);
}

TEST(Interpolation, OutOfRangeTimesClampAndEmptyTracksGiveDefaults) {
  const FloatTrack t = scalar_track(Interpolation::CatmullRom);
  EXPECT_FLOAT_EQ(sample_track(t, -5.0f), 0.0f);
  EXPECT_FLOAT_EQ(sample_track(t, 99.0f), 3.0f);
  EXPECT_FLOAT_EQ(sample_track(FloatTrack{}, 1.0f), 0.0f);
  const quat q = sample_track(QuatTrack{}, 1.0f);
  EXPECT_FLOAT_EQ(q.w, 1.0f);
}
