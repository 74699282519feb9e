#pragma once
// The timeline editor's panels (ALIAS ch. 8 and §4.2), drawn with Dear ImGui over a
// studio::Timeline: the channel list with the selected key's interpolation, and the tracks — a
// time ruler to scrub, the utterance's bars (drag a bar's right edge to retime it), one row of keys
// per channel (drag a key to retime it), the curve of the selected channel (drag a key up or down),
// and the pan-zoom film strip of the poses at the keys. Plain ImDrawList drawing (no implot).
#include <string>
#include <vector>

#include "gestura/studio/timeline_model.hpp"

namespace gestura::studio_ui {

struct TimelineView {
  float time = 0.0f;
  bool playing = false;
  bool loop = true;
  float speed = 1.0f;   // 0.25 .. 2
  int channel = -1;     // the selected channel and key
  int key = -1;
  float zoom = 1.0f;    // 1: the whole timeline fits the width
  float scroll = 0.0f;  // the first second shown
  float strip_zoom = 1.0f;  // film strip thumbnail size (pan-zoom)
  float strip_scroll = 0.0f;
  int first_row = 0;            // the first channel row shown
  bool follow_selection = true;  // scroll the rows to the selected channel once
  std::string clip_gloss;   // "save as clip sign" field
  bool key_requested = false;  // the Key pose button was pressed (the studio keys the pose editor's pose)
  std::string say_text;        // English to sign as the source motion
  bool say_requested = false;  // "Sign it" was pressed
  bool sign_requested = false; // "Use the draft" was pressed (the sign being edited)
  bool clear_requested = false;
  // Where the last frame drew each key (window pixels): for the script's where-key, which lets a
  // test drive the real mouse at a key.
  struct DrawnKey {
    int channel = -1, key = -1;
    float x = 0.0f, y = 0.0f;
  };
  std::vector<DrawnKey> drawn_keys;
};

// Moves the playhead when playing (wrapping when looping, stopping at the end otherwise).
void advance(TimelineView& view, float seconds, float duration);

void draw_timeline_channels(studio::Timeline& timeline, TimelineView& view);
void draw_timeline_tracks(studio::Timeline& timeline, TimelineView& view);

}  // namespace gestura::studio_ui
