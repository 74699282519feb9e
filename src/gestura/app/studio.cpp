#include "gestura/app/studio.hpp"

#include "gestura/app/input_file.hpp"
#include "gestura/lexicon/lexicon_files.hpp"
#include "gestura/render/render_job.hpp"

namespace gestura::app {

void validate(const StudioRequest& request) {
  check_fields(request);
  validate(request.avatar);
  check_image_size(request.size);
  if (!request.screenshot.empty() && request.frames == 0 && request.script.empty())
    usage_error("screenshot", "needs --frames N (or a --script) to say when to take it");
}

StudioSetup run(const StudioRequest& request, const RunContext&) {
  validate(request);
  StudioSetup setup;
  setup.user_db = request.db.empty() ? default_user_lexicon_path() : request.db;
  setup.builtin_files = builtin_lexicon_files();
  if (!request.script.empty()) {
    require_file("script", request.script);
    setup.script = as_field_error(ErrorCategory::input, "script", [&] { return studio::read_script(request.script); });
  }
  return setup;
}

}  // namespace gestura::app
