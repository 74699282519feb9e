// The viewer's input → state rules, without a window.
#include <gtest/gtest.h>

#include "gestura/render/viewer_controls.hpp"

namespace gestura {
namespace {

const FramingBox kBox{{-0.3f, 0.0f, -0.15f}, {0.3f, 1.8f, 0.15f}, 1.0f};

TEST(RenderViewerControls, PlayPauseStepAndSlowMotion) {
  ViewerControls c(kBox, CameraPreset::Front, 16.0f / 9.0f);
  c.advance(0.5f, 2.0f);
  EXPECT_FLOAT_EQ(c.time, 0.5f);
  c.apply(ViewerCommand::Speed025);
  c.advance(0.4f, 2.0f);
  EXPECT_FLOAT_EQ(c.time, 0.6f);
  c.apply(ViewerCommand::PlayPause);
  c.advance(1.0f, 2.0f);
  EXPECT_FLOAT_EQ(c.time, 0.6f);  // paused: time stands
  c.apply(ViewerCommand::StepForward);
  EXPECT_NEAR(c.time, 0.6f + 1.0f / 30.0f, 1e-6f);
  c.apply(ViewerCommand::StepBack);
  c.apply(ViewerCommand::StepBack);
  EXPECT_NEAR(c.time, 0.6f - 1.0f / 30.0f, 1e-6f);
  c.apply(ViewerCommand::Speed05);
  c.apply(ViewerCommand::PlayPause);
  c.advance(0.2f, 2.0f);
  EXPECT_NEAR(c.time, 0.6f - 1.0f / 30.0f + 0.1f, 1e-6f);
  c.apply(ViewerCommand::Restart);
  EXPECT_EQ(c.time, 0.0f);
  EXPECT_TRUE(c.playing);
}

TEST(RenderViewerControls, LoopWrapsAndNoLoopHoldsTheEnd) {
  ViewerControls c(kBox, CameraPreset::Front, 1.0f);
  c.advance(2.5f, 2.0f);
  EXPECT_NEAR(c.time, 0.5f, 1e-6f);
  c.apply(ViewerCommand::ToggleLoop);
  c.advance(2.5f, 2.0f);
  EXPECT_FLOAT_EQ(c.time, 2.0f);
}

TEST(RenderViewerControls, PresetsAndMouseMoveTheCamera) {
  ViewerControls c(kBox, CameraPreset::Front, 1.5f);
  const Camera front = c.camera(1.5f);
  EXPECT_GT(front.eye.z, 1.0f);
  c.apply(ViewerCommand::Side);
  EXPECT_GT(c.camera(1.5f).eye.x, 1.0f);
  c.apply(ViewerCommand::Top);
  ASSERT_TRUE(c.fixed.has_value());
  EXPECT_TRUE(c.camera(1.5f).orthographic);
  c.orbit_drag(100.0f, 0.0f);  // any drag leaves the fixed view for the orbit
  EXPECT_FALSE(c.fixed.has_value());
  c.apply(ViewerCommand::Front);
  const float distance = c.orbit.distance;
  c.zoom(2.0f);
  EXPECT_NEAR(c.orbit.distance, distance * 0.81f, 1e-4f);
  const vec3 target = c.orbit.target;
  c.pan_drag(50.0f, 0.0f);
  EXPECT_LT(c.orbit.target.x, target.x);  // dragging right moves the scene right: the target goes left
  const float yaw = c.orbit.yaw;
  c.orbit_drag(-100.0f, 1e6f);
  EXPECT_GT(c.orbit.yaw, yaw);
  EXPECT_LE(c.orbit.pitch, deg(89.0f));
}

}  // namespace
}  // namespace gestura
