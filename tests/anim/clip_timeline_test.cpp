// Placing clips on a timeline: keys shifted to the placement, rest held in the gaps, channels
// merged by name, misuse refused.
#include "gestura/anim/clip_timeline.hpp"

#include <gtest/gtest.h>

#include "gestura/core/error.hpp"

using namespace gestura;

namespace {

Skeleton two_joints() {
  Skeleton s;
  s.add_joint("root", -1, vec3(0.0f, 1.0f, 0.0f));
  s.add_joint("arm", 0, vec3(0.2f, 0.0f, 0.0f), glm::angleAxis(0.3f, vec3(0, 0, 1)));
  return s;
}

// A 1-second clip that bends "arm" about Y from rest to `angle` and back, with a "smile" channel.
Clip bend(const Skeleton& s, float angle) {
  Clip c;
  c.resize_joints(s.size());
  c.duration = 1.0f;
  const quat rest = s.rest_rotations[1];
  c.rotations[1].add(0.0f, rest);
  c.rotations[1].add(0.5f, rest * glm::angleAxis(angle, vec3(0, 1, 0)));
  c.rotations[1].add(1.0f, rest);
  c.channel("smile").add(0.2f, 0.8f);
  c.channel("smile").add(0.8f, 0.8f);
  return c;
}

}  // namespace

TEST(ClipTimeline, PlacesKeysAtOffsetsWithRestBetween) {
  const Skeleton s = two_joints();
  Clip t = empty_timeline(s);
  place_clip(t, bend(s, 0.5f), 2.0f, s);
  place_clip(t, bend(s, -0.5f), 5.0f, s);
  EXPECT_FLOAT_EQ(t.duration, 6.0f);
  EXPECT_NO_THROW(validate(t, s));
  EXPECT_TRUE(t.rotations[0].empty());  // untouched joint stays "at rest"
  const std::vector<float> times{2.0f, 2.5f, 3.0f, 5.0f, 5.5f, 6.0f};
  EXPECT_EQ(t.rotations[1].times, times);
  const quat rest = s.rest_rotations[1];
  // In the gap (3 s to 5 s) and before the first clip the arm is at rest.
  for (float time : {0.0f, 3.0f, 4.0f, 4.99f}) {
    const quat q = sample_track(t.rotations[1], time);
    EXPECT_NEAR(std::abs(glm::dot(q, rest)), 1.0f, 1e-6f) << time;
  }
  const quat peak = sample_track(t.rotations[1], 5.5f);
  EXPECT_NEAR(std::abs(glm::dot(peak, rest * glm::angleAxis(-0.5f, vec3(0, 1, 0)))), 1.0f, 1e-6f);
  // The channel returns to 0 at each placement's ends (the clip has no keys there).
  const FloatTrack& smile = t.channels.at(static_cast<std::size_t>(t.find_channel("smile")));
  const std::vector<float> smile_times{2.0f, 2.2f, 2.8f, 3.0f, 5.0f, 5.2f, 5.8f, 6.0f};
  EXPECT_EQ(smile.times, smile_times);
  EXPECT_FLOAT_EQ(sample_track(smile, 4.0f), 0.0f);
  EXPECT_FLOAT_EQ(sample_track(smile, 2.5f), 0.8f);
}

TEST(ClipTimeline, BackToBackPlacementsShareTheBoundaryKey) {
  const Skeleton s = two_joints();
  Clip t = empty_timeline(s);
  place_clip(t, bend(s, 0.5f), 0.0f, s);
  place_clip(t, bend(s, 0.5f), 1.0f, s);
  EXPECT_NO_THROW(validate(t, s));  // strictly increasing: the 1.0 s key is not doubled
  EXPECT_EQ(t.rotations[1].size(), 5u);
  EXPECT_FLOAT_EQ(t.duration, 2.0f);
}

TEST(ClipTimeline, RefusesMisuse) {
  const Skeleton s = two_joints();
  Clip t = empty_timeline(s);
  place_clip(t, bend(s, 0.5f), 3.0f, s);
  EXPECT_THROW(place_clip(t, bend(s, 0.5f), 3.5f, s), Error);  // overlaps the previous placement
  EXPECT_THROW(place_clip(t, bend(s, 0.5f), std::nanf(""), s), Error);
  Clip wrong = bend(s, 0.5f);
  wrong.resize_joints(3);
  EXPECT_THROW(place_clip(t, wrong, 10.0f, s), Error);
  Clip cubic = bend(s, 0.5f);
  cubic.rotations[1].interpolation = Interpolation::Step;
  try {
    place_clip(t, cubic, 10.0f, s);
    ADD_FAILURE() << "mixed interpolation accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'arm' rotation"), std::string::npos) << e.what();
    EXPECT_EQ(t.rotations[1].size(), 3u);  // left as it was
  }
}
