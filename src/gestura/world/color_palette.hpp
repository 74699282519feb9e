#pragma once
// The Colour Editor's palette (alias-movement-through-environments.txt §7.1): the colour being
// worked with and six ramps of nearby colours — three going up that add red, green or blue, three
// going down that take it away — so a person finds the colour they have in mind by clicking toward
// it rather than typing numbers; seven slots keep colours found; the current colour is applied to an
// object picked in a view. Plain data for the studio's colour editor (and any other front end).
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/world/scene.hpp"

namespace gestura {

enum class RampChannel { red, green, blue };

struct ColorRamp {
  RampChannel channel = RampChannel::red;
  bool up = true;             // adds the channel (up) or takes it away (down)
  std::vector<vec3> colors;   // nearest first; ends where the channel reaches 1 (up) or 0 (down)
};

// Contract: `steps` ≥ 1, `step` in (0, 1]. The colour is clamped to 0..1 first. Ramps in the order
// red up, green up, blue up, red down, green down, blue down.
std::array<ColorRamp, 6> nearby_colors(vec3 color, int steps = 8, float step = 1.0f / 16.0f);

class ColorPalette {
 public:
  static constexpr std::size_t kSlots = 7;

  explicit ColorPalette(vec3 color = vec3(0.5f), int steps = 8, float step = 1.0f / 16.0f);

  vec3 color() const { return color_; }
  const std::array<ColorRamp, 6>& ramps() const { return ramps_; }
  const std::array<std::optional<vec3>, kSlots>& slots() const { return slots_; }

  // A colour clicked anywhere (a ramp, a slot, a typed value) becomes the palette colour; the ramps
  // follow it.
  void choose(vec3 color);
  // The colour at `index` of ramp `ramp` (both checked: out of range throws gestura::Error).
  void choose_from_ramp(std::size_t ramp, std::size_t index);
  void store(std::size_t slot);          // the current colour into a slot (0..6)
  void choose_slot(std::size_t slot);    // an empty slot throws gestura::Error

 private:
  vec3 color_;
  int steps_;
  float step_;
  std::array<ColorRamp, 6> ramps_;
  std::array<std::optional<vec3>, kSlots> slots_;
};

// Gives the top-level object `object` (an index into scene.objects) `color`: the object gets a
// material of its own named after it (its present material's specular kept), so other objects that
// shared the material keep their colour. Parts that name a material of their own keep it (a door's
// metal handle). Returns the material's name. Throws gestura::Error for an index out of range.
std::string apply_color(Scene& scene, std::size_t object, vec3 color);

}  // namespace gestura
