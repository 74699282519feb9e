#pragma once
// The Colour Editor (alias-movement-through-environments.txt §7.1) bound to the environment editor:
// the palette (world/color_palette.hpp: the colour being worked with, six ramps of nearby colours,
// seven slots) follows the selected object, and every colour chosen — from a ramp, a slot, or typed
// as RGB or HSV — is given to that object at once (so the views show it) as one undoable step.
#include <cstddef>
#include <string>

#include "gestura/core/math.hpp"
#include "gestura/studio/environment_editor.hpp"
#include "gestura/world/color_palette.hpp"

namespace gestura::studio {

// HSV with hue, saturation and value in 0..1 (hue 0 = red, 1/3 = green, 2/3 = blue).
vec3 rgb_to_hsv(const vec3& rgb);
vec3 hsv_to_rgb(const vec3& hsv);
std::string color_hex(const vec3& rgb);  // "#rrggbb"

class ColourEditor {
 public:
  const ColorPalette& palette() const { return palette_; }

  // The palette takes the selected object's colour when the selection changed since the last call.
  void follow(const EnvironmentEditor& editor);
  // Each of these makes the colour current and gives it to the selected object (one undo step, or
  // part of the step the editor has open: a colour dragged in a picker is one step).
  void choose(EnvironmentEditor& editor, const vec3& rgb);
  void choose_hsv(EnvironmentEditor& editor, const vec3& hsv);
  void choose_ramp(EnvironmentEditor& editor, std::size_t ramp, std::size_t index);  // throws gestura::Error out of range
  void choose_slot(EnvironmentEditor& editor, std::size_t slot);                     // throws for an empty slot
  void store(std::size_t slot) { palette_.store(slot); }

 private:
  ColorPalette palette_;
  EnvSelection followed_;
  std::uint64_t followed_revision_ = ~0ull;
};

}  // namespace gestura::studio
