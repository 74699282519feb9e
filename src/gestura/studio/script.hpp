#pragma once
// `gestura studio --script FILE`: UI actions, one per line, replayed one per frame boundary by the
// running studio (the same actions the menus, buttons and keys call). '#' starts a comment.
//
//   open GLOSS [LANG [VARIANT]]   new   duplicate   save   delete   undo   redo
//   set FIELD VALUE...            FIELD: gloss lang variant names keywords meaning source licence agreement
//   select-symbol INDEX           palette NAME (as a click on the palette: replaces the selected
//   replace-symbol INDEX NAME     symbol, else appends)
//   insert-symbol INDEX NAME      remove-symbol INDEX
//   nonmanual TIER [VALUE] (TIER: shoulder body head gaze eyebrows eyelids nose cheeks mouth-gesture
//   mouth-picture extra; VALUE a SiGML tag such as RB, SAMPA for mouth-picture; none or '-' clears)
//   search TEXT...                filter FIELD VALUE (lang, handshape, location; '-' clears)
//   panel NAME                    camera front|side|three-quarter|top
//   time SECONDS   play   pause   wait FRAMES
//   import FILE   export FILE     recover   discard-recovery
//   export-sign FILE (.bvh .glb .gltf .json .png .gif .mp4 .webm: the sign as performed; the next
//   step waits until it is written)
//   screenshot FILE.png           dump FILE.json (the studio's state, for tests)
//   kill (the process kills itself with SIGKILL, as a crash would)   quit
//   learning mode: mode learn|edit   topic NAME   word GLOSS   sentence TEXT...   quiz SEED
//   answer GLOSS   next-question   views one|side|three-quarter|top   speed X
//   pose editor: mode pose   pose-joint NAME   pose-angles X Y Z (degrees)   pose-hand r|l HANDSHAPE
//   pose-mirror   pose-morph NAME WEIGHT   (undo / redo act on the pose in pose mode)
//   pose-pick X Y (a click at that fraction of the preview: the bone under it)
//   pose-drag JOINT X Y Z (drag the limb of JOINT until its hand or foot is at X Y Z, metres)
//   pose-drag-by JOINT DX DY DZ (the same, relative to where the wrist or ankle is)
//   timeline editor: mode timeline   timeline-say TEXT...   timeline-sign   timeline-clear
//   key-pose [SECONDS]   key CHANNEL SECONDS VALUE   move-key CHANNEL INDEX SECONDS
//   move-keys-at FROM TO   key-interp CHANNEL INDEX step|linear|catmull-rom|kb [T C B]
//   bar-duration INDEX SECONDS   loop on|off   timeline-zoom X   strip-zoom X
//   export-timeline FILE (.bvh .glb .gltf .json .gcl .png .gif .mp4 .webm)   save-clip-sign GLOSS [LANG]
//   (time, play, pause, speed, undo and redo act on the timeline in timeline mode)
//   figure editor: mode figure   figure-joint NAME   figure-rename NAME   figure-add NAME X Y Z
//   figure-remove   figure-copy   figure-mirror   figure-offset X Y Z   figure-limits AXIS MIN MAX
//   figure-order XYZ..ZYX   figure-dh   figure-save FILE.bvh   figure-load FILE.bvh
//   figure-view body|sticks|both   (undo and redo act on the figure in figure mode)
//   environment editor (docs/studio.md): mode env   env-open FILE   env-save [FILE]   env-select ITEM
//   env-tool T   env-snap M [DEG]   env-click VIEW X Y   env-drag VIEW X0 Y0 X1 Y1 [AXIS]
//   env-drag-from VIEW ITEM DX DY [AXIS]   env-set FIELD X [Y Z]   env-add KIND [NAME]   env-delete
//   env-duplicate   env-group NAME OBJECT...   env-colour RRGGBB|R G B|hsv H S V   env-ramp R I
//   env-keep S   env-slot S   env-orbit VIEW DYAW DPITCH   env-zoom VIEW F   env-frame
//   env-walk CHARACTER TARGET   env-walk-time S   env-stop   (undo / redo act on the scene in env mode)
#include <string>
#include <vector>

namespace gestura::studio {

struct ScriptStep {
  int line = 0;
  std::string action;
  std::vector<std::string> args;  // words; for set/search the rest of the line is one argument
};

// Throws gestura::Error naming file:line for an unknown action or a wrong number of arguments.
std::vector<ScriptStep> parse_script(const std::string& text, const std::string& file_name);
std::vector<ScriptStep> read_script(const std::string& path);

}  // namespace gestura::studio
