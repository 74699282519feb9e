#include "gestura/world/color_palette.hpp"

#include <algorithm>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

std::array<ColorRamp, 6> nearby_colors(vec3 color, int steps, float step) {
  color = glm::clamp(color, vec3(0.0f), vec3(1.0f));
  std::array<ColorRamp, 6> ramps;
  for (int r = 0; r < 6; ++r) {
    ColorRamp& ramp = ramps[static_cast<std::size_t>(r)];
    const int channel = r % 3;
    ramp.channel = static_cast<RampChannel>(channel);
    ramp.up = r < 3;
    const float sign = ramp.up ? 1.0f : -1.0f;
    for (int k = 1; k <= steps; ++k) {
      vec3 c = color;
      const float v = color[channel] + sign * step * static_cast<float>(k);
      // Stop at the edge of the gamut: one colour on it, none past it.
      c[channel] = std::clamp(v, 0.0f, 1.0f);
      if (!ramp.colors.empty() && ramp.colors.back()[channel] == c[channel]) break;
      if (c[channel] == color[channel]) break;
      ramp.colors.push_back(c);
    }
  }
  return ramps;
}

ColorPalette::ColorPalette(vec3 color, int steps, float step) : steps_(std::max(1, steps)), step_(step) { choose(color); }

void ColorPalette::choose(vec3 color) {
  color_ = glm::clamp(color, vec3(0.0f), vec3(1.0f));
  ramps_ = nearby_colors(color_, steps_, step_);
}

void ColorPalette::choose_from_ramp(std::size_t ramp, std::size_t index) {
  if (ramp >= ramps_.size()) throw Error("no ramp " + std::to_string(ramp) + " (0..5)");
  const std::vector<vec3>& colors = ramps_[ramp].colors;
  if (index >= colors.size())
    throw Error("ramp " + std::to_string(ramp) + " has " + std::to_string(colors.size()) + " colours, no " + std::to_string(index));
  choose(colors[index]);
}

void ColorPalette::store(std::size_t slot) {
  if (slot >= kSlots) throw Error("no palette slot " + std::to_string(slot) + " (0..6)");
  slots_[slot] = color_;
}

void ColorPalette::choose_slot(std::size_t slot) {
  if (slot >= kSlots) throw Error("no palette slot " + std::to_string(slot) + " (0..6)");
  if (!slots_[slot]) throw Error("palette slot " + std::to_string(slot) + " is empty");
  choose(*slots_[slot]);
}

std::string apply_color(Scene& scene, std::size_t object, vec3 color) {
  if (object >= scene.objects.size())
    throw Error("no object " + std::to_string(object) + " (the scene has " + std::to_string(scene.objects.size()) + ")");
  SceneObject& o = scene.objects[object];
  const std::string own = o.name.empty() ? "object " + std::to_string(object) : o.name;
  Material material;
  if (const auto it = scene.materials.find(o.material.empty() ? std::string(kDefaultMaterial) : o.material); it != scene.materials.end())
    material = it->second;
  material.color = glm::clamp(color, vec3(0.0f), vec3(1.0f));
  scene.materials[own] = material;
  o.material = own;
  return own;
}

}  // namespace gestura
