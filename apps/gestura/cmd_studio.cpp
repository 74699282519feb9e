// gestura studio [LEXICON.db]: the sign database editor (apps/studio, over app/studio.hpp).
#include <memory>

#include "command.hpp"
#include "gestura/app/studio.hpp"
#include "studio_window.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::StudioRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) { return studio_ui::run_studio(*request, context); };
  return invocation;
}

const Registration reg{{"studio", "the sign database editor: browse, edit and preview signs; the environment editor for scenes (window)",
                        "Opens the built-in lexicon read-only under your own SQLite lexicon LEXICON.db (created when\n"
                        "missing). Edit a sign's notation from the HamNoSys palette or as symbol names and watch the\n"
                        "avatar perform it; the parser's error is marked at its symbol and `check`'s problems are\n"
                        "listed. Save writes one transaction; notation that does not parse stays a draft. Every edit\n"
                        "undoes (Ctrl+Z) and redoes (Ctrl+Y), saves and deletes included. Unsaved drafts are autosaved\n"
                        "beside the lexicon (LEXICON.db.studio-draft.json) and offered back after a crash or kill.\n"
                        "Needs a display (without one: xvfb-run -a gestura studio ...). --script FILE replays UI\n"
                        "actions one per frame (docs/studio.md lists them); --frame-log FILE measures frame time and\n"
                        "edit-to-preview latency.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
