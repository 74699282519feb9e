// The timeline editor's model without a window: per-key interpolation values checked against
// numbers worked out by hand from the Hermite basis and the Kochanek–Bartels tangent formulas,
// bars of an utterance and their retiming, keying a pose, baking, undo.
#include <gtest/gtest.h>

#include <cmath>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/studio/timeline_model.hpp"

namespace gestura::studio {
namespace {

std::vector<TimelineKey> keys(std::initializer_list<std::pair<float, float>> tv, KeyInterpolation kind) {
  std::vector<TimelineKey> out;
  for (const auto& [t, v] : tv) out.push_back(TimelineKey{t, v, kind, {}});
  return out;
}

TEST(TimelineInterpolation, StepHoldsAndLinearInterpolates) {
  const auto step = keys({{0, 0}, {1, 10}}, KeyInterpolation::Step);
  EXPECT_FLOAT_EQ(0.0f, evaluate(step, 0.99f));
  EXPECT_FLOAT_EQ(10.0f, evaluate(step, 1.0f));
  const auto linear = keys({{0, 0}, {1, 10}}, KeyInterpolation::Linear);
  EXPECT_FLOAT_EQ(2.5f, evaluate(linear, 0.25f));
  EXPECT_FLOAT_EQ(0.0f, evaluate(linear, -5.0f));  // before the first key: its value
  EXPECT_FLOAT_EQ(10.0f, evaluate(linear, 7.0f));  // after the last: its value
}

TEST(TimelineInterpolation, CatmullRomWithUnevenSpacingMatchesTheHandComputedValue) {
  // Keys (0, 0), (1, 1), (3, 5), at t = 0.5 (u = 0.5 on the first segment).
  // Leaving key 0 (first key, one-sided): d_out = 1, tangent 2·(1/1)·0.5·1 = 1.
  // Arriving at key 1: d_in = 1, d_out = 4, dst = 0.5 + 2 = 2.5, scaled by 2·dt_prev/(dt_prev + dt_next) = 2/3: 5/3.
  // Hermite at u = 0.5: 0.5·0 + 0.125·1 + 0.5·1 − 0.125·5/3 = 0.416667.
  const auto k = keys({{0, 0}, {1, 1}, {3, 5}}, KeyInterpolation::CatmullRom);
  EXPECT_NEAR(0.4166667f, evaluate(k, 0.5f), 1e-5f);
  EXPECT_FLOAT_EQ(1.0f, evaluate(k, 1.0f));  // passes through its keys
}

TEST(TimelineInterpolation, KochanekBartelsTensionContinuityBiasMatchTheHandComputedValues) {
  // Keys (0, 0), (1, 10), (2, 0), (3, 10), evenly spaced (the spacing factors are 1).
  // Key 1: tension 0.5, continuity 0.25, bias −0.5; key 2: all zero.
  // Leaving key 1: d_in = 10, d_out = −10;
  //   0.5·(1−T)(1+B)(1−C)·d_in = 0.5·0.5·0.5·0.75·10 = 0.9375
  //   0.5·(1−T)(1−B)(1+C)·d_out = 0.5·0.5·1.5·1.25·(−10) = −4.6875   → tangent −3.75.
  // Arriving at key 2 (TCB 0): 0.5·(−10) + 0.5·10 = 0.
  // u = 0.5: h00 = 0.5, h10 = 0.125 → 5 − 0.46875 = 4.53125.
  // u = 0.25: h00 = 0.84375, h10 = 0.140625 → 8.4375 − 0.52734375 = 7.91015625.
  auto k = keys({{0, 0}, {1, 10}, {2, 0}, {3, 10}}, KeyInterpolation::KochanekBartels);
  k[1].tcb = Tcb{0.5f, 0.25f, -0.5f};
  EXPECT_NEAR(4.53125f, evaluate(k, 1.5f), 1e-5f);
  EXPECT_NEAR(7.91015625f, evaluate(k, 1.25f), 1e-5f);
  // With all TCB zero it is Catmull-Rom: the tangent at key 1 is (0 − 0)/2 = 0, so u = 0.5 gives 5.
  k[1].tcb = Tcb{};
  EXPECT_NEAR(5.0f, evaluate(k, 1.5f), 1e-5f);
  // Tension 1 makes both tangents at key 1 zero: also 5 at the middle, but a different curve at u = 0.25.
  k[1].tcb = Tcb{1.0f, 0.0f, 0.0f};
  EXPECT_NEAR(0.84375f * 10.0f, evaluate(k, 1.25f), 1e-5f);
}

TEST(TimelineBars, SignsTransitionsAndPausesFromAnUtterance) {
  const std::vector<SourceSign> signs{{"YOU", 0.3f, 1.0f}, {"NAME", 1.2f, 2.0f}, {"WHAT", 2.8f, 3.5f}};
  const auto bars = bars_from_signs(signs, 4.0f);
  ASSERT_EQ(7u, bars.size());
  EXPECT_EQ(BarKind::Transition, bars[0].kind);  // the way in
  EXPECT_EQ("YOU", bars[1].label);
  EXPECT_EQ(BarKind::Transition, bars[2].kind);  // 0.2 s between YOU and NAME
  EXPECT_EQ(BarKind::Pause, bars[4].kind);       // 0.8 s before WHAT
  EXPECT_EQ("WHAT", bars[5].label);
  EXPECT_EQ(BarKind::Transition, bars[6].kind);  // back to rest
  float total = 0;
  for (const TimelineBar& b : bars) total += b.duration;
  EXPECT_NEAR(4.0f, total, 1e-5f);
}

struct TimelineFixture : ::testing::Test {
  Skeleton skeleton = build_avatar_skeleton();
  Timeline timeline{skeleton, {"smile", "brow_raise"}};
};

TEST_F(TimelineFixture, RetimingABarStretchesTheSourceAndMovesTheKeysWithItAndUndoRestores) {
  Clip clip;
  clip.duration = 3.0f;
  clip.resize_joints(skeleton.size());
  const std::vector<SourceSign> signs{{"A", 0.0f, 1.0f}, {"B", 1.0f, 3.0f}};
  timeline.set_source(clip, signs, "A B");
  ASSERT_EQ(2u, timeline.bars().size());
  const int c = timeline.channel_for("r_elbow.x");
  ASSERT_GE(c, 0);
  timeline.set_key(c, 0.5f, 10.0f);  // inside bar A
  timeline.set_key(c, 2.0f, 20.0f);  // inside bar B
  ASSERT_TRUE(timeline.set_bar_duration(0, 2.0f));  // A lasts twice as long
  EXPECT_NEAR(1.0f, timeline.channels()[static_cast<std::size_t>(c)].keys[0].time, 1e-5f);
  EXPECT_NEAR(3.0f, timeline.channels()[static_cast<std::size_t>(c)].keys[1].time, 1e-5f);
  EXPECT_NEAR(4.0f, timeline.duration(), 1e-5f);
  EXPECT_NEAR(0.5f, timeline.source_time(1.0f), 1e-5f);  // the source plays at half speed in A
  EXPECT_NEAR(2.0f, timeline.source_time(3.0f), 1e-5f);   // and as before in B, 1 s later
  ASSERT_TRUE(timeline.undo());
  EXPECT_NEAR(0.5f, timeline.channels()[static_cast<std::size_t>(c)].keys[0].time, 1e-5f);
  EXPECT_NEAR(3.0f, timeline.duration(), 1e-5f);
  ASSERT_TRUE(timeline.redo());
  EXPECT_NEAR(4.0f, timeline.duration(), 1e-5f);
}

TEST_F(TimelineFixture, KeyingAPoseKeysWhatChangedAndBakingPlaysItBack) {
  Pose pose = rest_pose(skeleton);
  const int elbow = skeleton.find("r_elbow");
  ASSERT_GE(elbow, 0);
  const JointDofs& d = skeleton.dofs[static_cast<std::size_t>(elbow)];
  int axis = 0;
  while (!d.free(axis)) ++axis;
  vec3 angles(0.0f);
  angles[axis] = 0.5f * (d.min_angle[axis] + d.max_angle[axis]);
  pose.rotations[static_cast<std::size_t>(elbow)] = joint_rotation(skeleton, elbow, angles);
  const std::vector<float> morphs{0.7f, 0.0f};
  EXPECT_EQ(2, timeline.key_pose(pose, morphs, 1.0f));  // one elbow axis and the smile
  // At 0 s the timeline holds the first keys' values: the rest pose differs in the same two channels.
  EXPECT_EQ(2, timeline.key_pose(rest_pose(skeleton), std::vector<float>{0, 0}, 0.0f));
  ASSERT_EQ((std::vector<float>{0.0f, 1.0f}), timeline.key_times());
  Pose at;
  at.resize(skeleton.size());
  std::vector<float> w(2);
  timeline.sample(1.0f, at, w);
  EXPECT_NEAR(glm::degrees(angles[axis]), glm::degrees(joint_angles(skeleton, elbow, at.rotations[static_cast<std::size_t>(elbow)])[axis]), 0.01f);
  EXPECT_NEAR(0.7f, w[0], 1e-5f);
  const Clip clip = timeline.bake(30.0f);
  validate(clip, skeleton);
  EXPECT_NEAR(2.0f, clip.duration, 1e-4f);  // no source: 2 s
  const quat q = sample_track(clip.rotations[static_cast<std::size_t>(elbow)], 1.0f);
  EXPECT_GT(std::abs(glm::dot(q, at.rotations[static_cast<std::size_t>(elbow)])), 0.99999f);
  ASSERT_TRUE(timeline.undo());
  ASSERT_TRUE(timeline.undo());
  EXPECT_TRUE(timeline.key_times().empty());
}

TEST_F(TimelineFixture, KeysStayInOrderWhenDraggedAndUnknownChannelsAreRefused) {
  EXPECT_EQ(-1, timeline.channel_for("no_such_joint.x"));
  EXPECT_EQ(-1, timeline.channel_for("nose_wrinkle"));
  const int c = timeline.channel_for("smile");
  timeline.set_key(c, 0.0f, 0.0f);
  timeline.set_key(c, 1.0f, 1.0f);
  timeline.set_key(c, 2.0f, 0.0f);
  ASSERT_TRUE(timeline.move_key(c, 1, 5.0f));  // cannot pass its neighbour
  EXPECT_LT(timeline.channels()[static_cast<std::size_t>(c)].keys[1].time, 2.0f);
  EXPECT_FALSE(timeline.move_key(c, 7, 1.0f));
  ASSERT_TRUE(timeline.set_interpolation(c, 0, KeyInterpolation::KochanekBartels, Tcb{3.0f, 0.0f, 0.0f}));
  EXPECT_FLOAT_EQ(1.0f, timeline.channels()[static_cast<std::size_t>(c)].keys[0].tcb.tension);  // clamped to [-1, 1]
  EXPECT_FALSE(timeline.set_key(c, NAN, 1.0f) >= 0);
}

}  // namespace
}  // namespace gestura::studio

namespace gestura::studio {
namespace {

TEST(TimelineSource, UndoingANewSourceBringsBackTheOldMotionWithItsBars) {
  const Skeleton skeleton = build_avatar_skeleton();
  Timeline timeline(skeleton, {});
  Clip a, b;
  a.duration = 2.0f, b.duration = 5.0f;
  a.resize_joints(skeleton.size()), b.resize_joints(skeleton.size());
  const std::vector<SourceSign> two{{"ONE", 0.0f, 1.0f}, {"TWO", 1.0f, 2.0f}}, one{{"LONG", 0.0f, 5.0f}};
  timeline.set_source(a, two, "one two");
  timeline.set_source(b, one, "long");
  EXPECT_NEAR(5.0f, timeline.duration(), 1e-5f);
  ASSERT_TRUE(timeline.undo());
  EXPECT_EQ("one two", timeline.title());
  ASSERT_EQ(2u, timeline.bars().size());
  EXPECT_NEAR(2.0f, timeline.duration(), 1e-5f);
  EXPECT_NEAR(1.5f, timeline.source_time(1.5f), 1e-5f);
  ASSERT_TRUE(timeline.undo());
  EXPECT_FALSE(timeline.has_source());
  ASSERT_TRUE(timeline.redo() && timeline.redo());
  EXPECT_EQ("long", timeline.title());
}

}  // namespace
}  // namespace gestura::studio
