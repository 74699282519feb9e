#pragma once
// studio: the interactive sign database editor (apps/studio draws it). The request names the
// user's lexicon and how the window runs; run() resolves what the window needs before it opens, so
// a bad script or an unusable path fails as a usage or input error like any other command.
#include <string>
#include <vector>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/codecs.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/studio/script.hpp"

namespace gestura::app {

struct StudioRequest {
  std::string db;          // the user lexicon; default as for `gestura lexicon`
  std::string script;      // UI actions replayed at frame boundaries
  std::string screenshot;  // save the window after `frames` frames (or the script) and quit
  int frames = 0;          // 0: run until closed (or the script ends with quit)
  ImageSize size{1280, 800};
  float preview_scale = 1.0f;  // the 3D preview renders at this fraction of its panel's pixels
  float playing_scale = 0.5f;  // ... and at this fraction of that while it plays (full again when it stops)
  std::string frame_log;   // one line per frame: frame time, preview time, synthesis
  AvatarChoice avatar;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.db, FieldInfo{.name = "db", .help = "the user lexicon (SQLite file, created when missing); default $GESTURA_LEXICON or ~/.local/share/gestura/lexicon.sqlite", .value = "LEXICON.db", .positional = true});
    visit(self.script, FieldInfo{.name = "script", .help = "replay UI actions from FILE, one per frame (see docs/studio.md)", .value = "FILE"});
    visit(self.screenshot, FieldInfo{.name = "screenshot", .help = "save the window as PNG after --frames frames, then quit", .value = "PATH.png"});
    visit(self.frames, FieldInfo{.name = "frames", .help = "quit after this many frames (0: when closed)", .value = "N", .min = 0, .max = 1000000});
    visit(self.size, FieldInfo{.name = "size", .help = "window size", .value = "WxH"});
    visit(self.preview_scale, FieldInfo{.name = "preview_scale", .help = "render the 3D preview at this fraction of its panel (faster on a CPU)", .value = "X", .min = 0.25, .max = 1});
    visit(self.playing_scale, FieldInfo{.name = "playing_scale", .help = "while the preview plays, render it at this fraction of --preview-scale (full again when it stops)", .value = "X", .min = 0.25, .max = 1});
    visit(self.frame_log, FieldInfo{.name = "frame_log", .help = "write each frame's timings (ms) to FILE and a summary to stderr", .value = "FILE"});
    AvatarChoice::fields(self.avatar, visit);
  }
};

// What the studio window opens with.
struct StudioSetup {
  std::string user_db;                     // absolute or as given
  std::vector<std::string> builtin_files;  // the built-in lexicon's .jsonl files
  std::vector<studio::ScriptStep> script;
};

void validate(const StudioRequest& request);
// A script that does not parse is an input error at file:line.
StudioSetup run(const StudioRequest& request, const RunContext& context = {});

}  // namespace gestura::app
