#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/movement_path.hpp"

using namespace gestura;

namespace {

void expect_vec(vec3 actual, vec3 expected, float tolerance, const std::string& what = "") {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
  EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
  EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// Tangent against a central difference of the positions.
void expect_tangent_consistent(const MovementPath& path, float s) {
  const float h = 1e-3f;
  const vec3 numeric = (sample_path(path, s + h).position - sample_path(path, s - h).position) / (2 * h);
  const vec3 analytic = sample_path(path, s).tangent;
  EXPECT_LT(glm::length(numeric - analytic), 2e-3f + 1e-2f * glm::length(analytic)) << "s=" << s;
}

}  // namespace

TEST(MovementPath, StraightPathsGoTheirSizeInTheirDirection) {
  EXPECT_EQ(straight_length(MovementSize::Small), 0.08f);
  EXPECT_EQ(straight_length(MovementSize::Normal), 0.15f);
  EXPECT_EQ(straight_length(MovementSize::Large), 0.25f);
  const MovementPath up = straight_path(Direction::U);
  expect_vec(sample_path(up, 0.0f).position, {0, 0, 0}, 0);
  expect_vec(path_end(up), {0, 0.15f, 0}, 1e-6f);
  const MovementPath large_out_left = straight_path(Direction::OL, MovementSize::Large);
  const float c = 0.25f / std::sqrt(2.0f);
  expect_vec(path_end(large_out_left), {c, 0, c}, 1e-6f);
  EXPECT_NEAR(path_length(large_out_left), 0.25f, 1e-5f);
  expect_vec(sample_path(up, 0.5f).position, {0, 0.075f, 0}, 1e-6f);
  for (std::size_t k = 0; k < kDirectionCount; ++k) {
    const auto d = static_cast<Direction>(k);
    for (MovementSize size : {MovementSize::Small, MovementSize::Normal, MovementSize::Large}) {
      const MovementPath p = straight_path(d, size);
      expect_vec(path_end(p), straight_length(size) * direction_vector(d), 1e-6f, std::string(to_string(d)));
      EXPECT_NEAR(path_length(p), straight_length(size), 1e-5f);
    }
  }
  EXPECT_THROW(straight_path(vec3{0, 0, 0}, 0.1f), Error);
  EXPECT_THROW(straight_path(vec3{0, 1, 0}, -0.1f), Error);
  EXPECT_THROW(straight_path(vec3{0, NAN, 0}, 0.1f), Error);
}

TEST(MovementPath, ArcsBulgeTowardTheirSideAndEndOnTheChord) {
  const MovementPath arc = arc_path(Direction::R, Direction::U);  // rightward, bulging up
  expect_vec(sample_path(arc, 0.0f).position, {0, 0, 0}, 1e-6f);
  expect_vec(path_end(arc), {-0.15f, 0, 0}, 1e-6f);
  // The midpoint is the sagitta (0.25 × chord) above the chord's middle.
  expect_vec(sample_path(arc, 0.5f).position, {-0.075f, 0.25f * 0.15f, 0}, 1e-6f);
  for (int k = 1; k < 10; ++k) EXPECT_GT(sample_path(arc, k / 10.0f).position.y, 0.0f);
  EXPECT_GT(path_length(arc), 0.15f);
  for (float s : {0.1f, 0.5f, 0.9f}) expect_tangent_consistent(arc, s);
  EXPECT_THROW(arc_path(Direction::U, Direction::U), Error);
  EXPECT_THROW(arc_path(vec3{1, 0, 0}, 0.1f, vec3{0, 1, 0}, 0.7f), Error);
}

TEST(MovementPath, CirclesAreClosedInTheirPlaneAndTurnTheNotatedWay) {
  for (BodyPlane plane : {BodyPlane::Frontal, BodyPlane::Horizontal, BodyPlane::Sagittal})
    for (Rotation rotation : {Rotation::Clockwise, Rotation::Anticlockwise}) {
      const MovementPath c = circle_in_plane(plane, rotation);
      expect_vec(path_end(c), {0, 0, 0}, 1e-6f, "closed");
      EXPECT_NEAR(path_length(c), 2 * kPi * 0.05f, 1e-4f);
      // Every point stays in the plane through the start.
      for (int k = 0; k <= 16; ++k) {
        const vec3 p = sample_path(c, k / 16.0f).position;
        const float off_plane = plane == BodyPlane::Frontal ? p.z : plane == BodyPlane::Horizontal ? p.y : p.x;
        EXPECT_NEAR(off_plane, 0.0f, 1e-6f);
      }
      for (float s : {0.2f, 0.6f}) expect_tangent_consistent(c, s);
    }
  // Frontal, clockwise as the signer sees it looking forward (+X = their left, +Y up): starting at
  // the bottom, a clockwise circle first moves toward the signer's left (like 6 → 9 o'clock).
  const MovementPath cw = circle_in_plane(BodyPlane::Frontal, Rotation::Clockwise);
  EXPECT_GT(sample_path(cw, 0.1f).position.x, 0.0f);
  EXPECT_GT(sample_path(cw, 0.5f).position.y, 0.09f);  // the top is a diameter above the start
  EXPECT_LT(sample_path(circle_in_plane(BodyPlane::Frontal, Rotation::Anticlockwise), 0.1f).position.x, 0.0f);
  // Horizontal clockwise seen from above (forward at the top of the view, so the signer's left is
  // on the left), starting nearest the body: 6 → 9 o'clock is toward the signer's left (+X).
  EXPECT_GT(sample_path(circle_in_plane(BodyPlane::Horizontal, Rotation::Clockwise), 0.1f).position.x, 0.0f);
  // Sagittal clockwise seen from the right: from the bottom it first moves toward the signer (−Z),
  // so the top moves away.
  const MovementPath sag = circle_in_plane(BodyPlane::Sagittal, Rotation::Clockwise);
  EXPECT_LT(sample_path(sag, 0.1f).position.z, 0.0f);
  EXPECT_GT(sample_path(sag, 0.5f).tangent.z, 0.0f);
  EXPECT_THROW(circle_path({0, 0, 1}, 0.05f, {0, 0, 1}), Error);
  EXPECT_THROW(circle_path({0, 0, 1}, -0.05f, {0, 1, 0}), Error);
}

TEST(MovementPath, ModifiersOscillateAroundTheChordAndKeepItsEnds) {
  const MovementPath base = straight_path(Direction::O);
  for (PathModifier m : {PathModifier::Wavy, PathModifier::Zigzag, PathModifier::Spiral}) {
    const MovementPath p = with_modifier(base, m);
    expect_vec(sample_path(p, 0.0f).position, {0, 0, 0}, 1e-6f);
    expect_vec(path_end(p), path_end(base), 1e-5f);
    float max_off = 0.0f;
    for (int k = 0; k <= 400; ++k) {
      const vec3 q = sample_path(p, k / 400.0f).position;
      max_off = std::max(max_off, std::hypot(q.x, q.y));
      EXPECT_NEAR(q.z, sample_path(base, k / 400.0f).position.z, 1e-6f);  // progress along the chord unchanged
    }
    const float expected = m == PathModifier::Spiral ? 2 * 0.025f : 0.02f;  // spiral: a diameter off the line
    EXPECT_NEAR(max_off, expected, 1e-3f) << static_cast<int>(m);
    for (float s : {0.05f, 0.4f, 0.77f}) expect_tangent_consistent(p, s);
  }
  // Wavy swings first toward the requested side (projected ⟂ to the chord).
  const MovementPath wavy = with_modifier(base, PathModifier::Wavy, 0.02f, 2, vec3{1, 0, 1});
  EXPECT_GT(sample_path(wavy, 0.1f).position.x, 0.0f);
  // Zigzag is piecewise straight: a triangle wave hits its peak at a quarter cycle.
  const MovementPath zig = with_modifier(base, PathModifier::Zigzag, 0.02f, 1);
  EXPECT_NEAR(sample_path(zig, 0.25f).position.y, 0.02f, 1e-6f);
  EXPECT_NEAR(sample_path(zig, 0.125f).position.y, 0.01f, 1e-6f);
  EXPECT_THROW(with_modifier(circle_in_plane(BodyPlane::Frontal, Rotation::Clockwise), PathModifier::Wavy), Error);
  EXPECT_THROW(with_modifier(base, PathModifier::Wavy, 0.02f, 0), Error);
}

TEST(MovementPath, PolylinesStopAtCornersWhenAsked) {
  const MovementPath z = polyline_path({{1, 1, 1}, {0.9f, 1, 1}, {1, 0.9f, 1}}, true);
  expect_vec(sample_path(z, 0.0f).position, {0, 0, 0}, 1e-6f);  // made relative to the first point
  expect_vec(path_end(z), {0, -0.1f, 0}, 1e-6f);
  // The corner is reached with zero speed: find it and check the tangent there.
  float corner_s = -1.0f;
  for (int k = 0; k <= 1000; ++k)
    if (glm::distance(sample_path(z, k / 1000.0f).position, vec3{-0.1f, 0, 0}) < 1e-6f) {
      corner_s = k / 1000.0f;
      break;
    }
  ASSERT_GT(corner_s, 0.0f);
  EXPECT_LT(glm::length(sample_path(z, corner_s).tangent), 1e-3f);
  const MovementPath smooth = polyline_path({{0, 0, 0}, {0.1f, 0, 0}, {0.1f, 0.1f, 0}}, false);
  expect_vec(sample_path(smooth, 0.5f).position, {0.1f, 0, 0}, 1e-6f);  // arc-length parameterised
  EXPECT_THROW(polyline_path({{0, 0, 0}}, false), Error);
  EXPECT_THROW(polyline_path({{0, 0, 0}, {0, 0, 0}}, true), Error);
  EXPECT_THROW(polyline_path({{0, 0, 0}, {NAN, 0, 0}}, false), Error);
}

TEST(MovementPath, MirrorFlipsLeftAndRightIncludingTheSenseOfRotation) {
  const MovementPath cw = circle_in_plane(BodyPlane::Frontal, Rotation::Clockwise);
  const MovementPath ccw = circle_in_plane(BodyPlane::Frontal, Rotation::Anticlockwise);
  const MovementPath mirrored = mirror_left_right(cw);
  for (int k = 0; k <= 8; ++k) {
    const vec3 a = sample_path(cw, k / 8.0f).position, m = sample_path(mirrored, k / 8.0f).position;
    expect_vec(m, {-a.x, a.y, a.z}, 1e-6f);
    expect_vec(m, sample_path(ccw, k / 8.0f).position, 1e-6f);
  }
  const MovementPath spiral = with_modifier(straight_path(Direction::UL), PathModifier::Spiral);
  const MovementPath ms = mirror_left_right(spiral);
  for (int k = 0; k <= 8; ++k) {
    const vec3 a = sample_path(spiral, k / 8.0f).position, m = sample_path(ms, k / 8.0f).position;
    expect_vec(m, {-a.x, a.y, a.z}, 1e-6f);
  }
}

TEST(MovementPath, MovementsAreTimedAndRestAtTheEnds) {
  const Movement m = make_movement(straight_path(Direction::U));
  EXPECT_EQ(m.profile, VelocityProfile::MinimumJerk);
  EXPECT_GE(m.duration, 0.5f);
  EXPECT_LE(m.duration, 0.8f);
  expect_vec(sample(m, 0.0f).position, {0, 0, 0}, 1e-6f);
  expect_vec(sample(m, m.duration).position, {0, 0.15f, 0}, 1e-6f);
  EXPECT_LT(glm::length(sample(m, 0.0f).velocity), 1e-6f);
  EXPECT_LT(glm::length(sample(m, m.duration).velocity), 1e-6f);
  // Peak speed of a minimum-jerk stroke is 1.875 × the mean speed.
  EXPECT_NEAR(sample(m, 0.5f * m.duration).velocity.y, 1.875f * 0.15f / m.duration, 1e-4f);
  // Fast / slow / small / large scale the duration.
  EXPECT_LT(make_movement(straight_path(Direction::U), MovementSpeed::Fast).duration, m.duration);
  EXPECT_GT(make_movement(straight_path(Direction::U, MovementSize::Large)).duration, m.duration);
  // Circles cruise at constant speed.
  const Movement circle = make_movement(circle_in_plane(BodyPlane::Horizontal, Rotation::Clockwise));
  EXPECT_EQ(circle.profile, VelocityProfile::ConstantRamped);
  EXPECT_NEAR(glm::length(sample(circle, 0.4f * circle.duration).velocity),
              glm::length(sample(circle, 0.6f * circle.duration).velocity), 1e-4f);
  EXPECT_THROW(make_movement(straight_path(Direction::U), MovementSpeed::Normal, 0), Error);
}

TEST(MovementPath, RepetitionsReturnContinueOrReverse) {
  const MovementPath up = straight_path(Direction::U, MovementSize::Small);
  const Movement from_start = make_movement(up, MovementSpeed::Normal, 3, RepeatMode::FromStart);
  const float pass = make_movement(up).duration;
  EXPECT_NEAR(from_start.duration, pass * (3 + 2 * 0.5f), 1e-5f);
  // After the first pass (1 unit of 4) it is at the top; after its return (1.5 units) back at the start.
  expect_vec(sample(from_start, from_start.duration * 1.0f / 4.0f).position, {0, 0.08f, 0}, 1e-6f);
  expect_vec(sample(from_start, from_start.duration * 1.5f / 4.0f).position, {0, 0, 0}, 1e-6f);
  expect_vec(sample(from_start, from_start.duration).position, {0, 0.08f, 0}, 1e-6f);

  const Movement cont = make_movement(up, MovementSpeed::Normal, 3, RepeatMode::Continue);
  expect_vec(sample(cont, cont.duration).position, {0, 0.24f, 0}, 1e-5f);
  expect_vec(sample(cont, cont.duration / 3).position, {0, 0.08f, 0}, 1e-5f);

  const Movement rev = make_movement(up, MovementSpeed::Normal, 2, RepeatMode::Reverse);
  expect_vec(sample(rev, rev.duration / 2).position, {0, 0.08f, 0}, 1e-6f);
  expect_vec(sample(rev, rev.duration).position, {0, 0, 0}, 1e-6f);
  EXPECT_LT(sample(rev, rev.duration * 0.75f).velocity.y, 0.0f);  // second pass goes back down
  // Velocity is the derivative of position in seconds, including the return segments.
  for (float t : {0.1f, 0.3f, 0.45f, 0.8f}) {
    const float time = t * from_start.duration, h = 1e-3f;
    const vec3 numeric = (sample(from_start, time + h).position - sample(from_start, time - h).position) / (2 * h);
    EXPECT_LT(glm::length(numeric - sample(from_start, time).velocity), 2e-3f) << t;
  }
}
