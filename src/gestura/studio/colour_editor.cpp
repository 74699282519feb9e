#include "gestura/studio/colour_editor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gestura::studio {

vec3 rgb_to_hsv(const vec3& c) {
  const float hi = std::max({c.x, c.y, c.z}), lo = std::min({c.x, c.y, c.z}), d = hi - lo;
  float h = 0.0f;
  if (d > 0.0f) {
    if (hi == c.x) h = std::fmod((c.y - c.z) / d + 6.0f, 6.0f);
    else if (hi == c.y) h = (c.z - c.x) / d + 2.0f;
    else h = (c.x - c.y) / d + 4.0f;
    h /= 6.0f;
  }
  return vec3(h, hi > 0.0f ? d / hi : 0.0f, hi);
}

vec3 hsv_to_rgb(const vec3& hsv) {
  const float h = (hsv.x - std::floor(hsv.x)) * 6.0f, s = std::clamp(hsv.y, 0.0f, 1.0f), v = std::clamp(hsv.z, 0.0f, 1.0f);
  const float f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (static_cast<int>(h) % 6) {
    case 0: return vec3(v, t, p);
    case 1: return vec3(q, v, p);
    case 2: return vec3(p, v, t);
    case 3: return vec3(p, q, v);
    case 4: return vec3(t, p, v);
    default: return vec3(v, p, q);
  }
}

std::string color_hex(const vec3& rgb) {
  const auto byte = [](float x) { return static_cast<int>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(rgb.x), byte(rgb.y), byte(rgb.z));
  return text;
}

void ColourEditor::follow(const EnvironmentEditor& editor) {
  if (editor.selection() == followed_ && editor.revision() == followed_revision_) return;
  const bool moved_on = !(editor.selection() == followed_);
  followed_ = editor.selection();
  followed_revision_ = editor.revision();
  // A new selection, or its colour changed under the palette (undo): the palette shows it.
  if (const auto c = editor.selected_color(); c && (moved_on || *c != palette_.color())) palette_.choose(*c);
}

void ColourEditor::choose(EnvironmentEditor& editor, const vec3& rgb) {
  palette_.choose(rgb);
  editor.set_color(palette_.color());
  followed_revision_ = editor.revision();
}

void ColourEditor::choose_hsv(EnvironmentEditor& editor, const vec3& hsv) { choose(editor, hsv_to_rgb(hsv)); }

void ColourEditor::choose_ramp(EnvironmentEditor& editor, std::size_t ramp, std::size_t index) {
  palette_.choose_from_ramp(ramp, index);
  choose(editor, palette_.color());
}

void ColourEditor::choose_slot(EnvironmentEditor& editor, std::size_t slot) {
  palette_.choose_slot(slot);
  choose(editor, palette_.color());
}

}  // namespace gestura::studio
