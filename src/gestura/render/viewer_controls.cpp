#include "gestura/render/viewer_controls.hpp"

#include <algorithm>
#include <cmath>

namespace gestura {

ViewerControls::ViewerControls(const FramingBox& framing, CameraPreset start, float view_aspect)
    : box(framing), aspect(view_aspect) {
  select(start);
}

void ViewerControls::select(CameraPreset preset) {
  orbit = preset_orbit(preset, box, aspect);
  fixed.reset();
  if (preset == CameraPreset::Top || preset == CameraPreset::SideSection) fixed = preset;
}

void ViewerControls::apply(ViewerCommand command) {
  switch (command) {
    case ViewerCommand::PlayPause: playing = !playing; break;
    case ViewerCommand::StepBack: playing = false, time = std::max(0.0f, time - step); break;
    case ViewerCommand::StepForward: playing = false, time += step; break;
    case ViewerCommand::Speed025: speed = 0.25f; break;
    case ViewerCommand::Speed05: speed = 0.5f; break;
    case ViewerCommand::Speed1: speed = 1.0f; break;
    case ViewerCommand::ToggleLoop: loop = !loop; break;
    case ViewerCommand::Restart: time = 0.0f, playing = true; break;
    case ViewerCommand::Front: select(CameraPreset::Front); break;
    case ViewerCommand::Side: select(CameraPreset::Side); break;
    case ViewerCommand::ThreeQuarter: select(CameraPreset::ThreeQuarter); break;
    case ViewerCommand::Top: select(CameraPreset::Top); break;
    case ViewerCommand::SideSection: select(CameraPreset::SideSection); break;
  }
}

void ViewerControls::advance(float seconds, float duration) {
  if (playing) time += seconds * speed;
  if (duration > 0.0f && time > duration) time = loop ? std::fmod(time, duration) : duration;
}

void ViewerControls::orbit_drag(float dx, float dy) {
  fixed.reset();
  orbit.yaw -= dx * 0.008f;
  orbit.pitch = std::clamp(orbit.pitch + dy * 0.008f, deg(-89.0f), deg(89.0f));
}

void ViewerControls::pan_drag(float dx, float dy) {
  fixed.reset();
  const Camera c = orbit_camera(orbit, aspect);
  const vec3 right{c.view[0][0], c.view[1][0], c.view[2][0]}, up{c.view[0][1], c.view[1][1], c.view[2][1]};
  orbit.target += (-dx * right + dy * up) * (orbit.distance * 0.0015f);
}

void ViewerControls::zoom(float notches) {
  fixed.reset();
  orbit.distance = std::clamp(orbit.distance * std::pow(0.9f, notches), 0.1f, 100.0f);
}

Camera ViewerControls::camera(float view_aspect) const {
  return fixed ? preset_camera(*fixed, box, view_aspect) : orbit_camera(orbit, view_aspect);
}

}  // namespace gestura
