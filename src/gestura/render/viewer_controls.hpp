#pragma once
// The interactive viewer's state and how input changes it, kept apart from the window so it can be
// tested without one: playback (play/pause, frame steps, slow motion, loop) and the camera (presets,
// orbit, pan, zoom).
#include <optional>

#include "gestura/render/camera.hpp"

namespace gestura {

enum class ViewerCommand : std::uint8_t {
  PlayPause, StepBack, StepForward, Speed025, Speed05, Speed1, ToggleLoop, Restart,
  Front, Side, ThreeQuarter, Top, SideSection,
};

struct ViewerControls {
  FramingBox box;
  Orbit orbit;
  std::optional<CameraPreset> fixed;  // an orthographic preset shown as is until the mouse moves the camera
  float time = 0.0f;
  float speed = 1.0f;
  float step = 1.0f / 30.0f;  // one frame at 30 fps
  bool playing = true;
  bool loop = true;
  float aspect = 16.0f / 9.0f;

  ViewerControls(const FramingBox& framing, CameraPreset start, float aspect);

  void apply(ViewerCommand command);
  void select(CameraPreset preset);
  // Moves playback time by `seconds` of wall time (scaled by speed when playing); wraps into the
  // clip when looping, else holds at its end. duration 0 = no clip.
  void advance(float seconds, float duration);
  // Mouse input in pixels: orbit (left drag), pan (right/middle drag), zoom (wheel notches).
  void orbit_drag(float dx, float dy);
  void pan_drag(float dx, float dy);
  void zoom(float notches);

  Camera camera(float view_aspect) const;
};

}  // namespace gestura
