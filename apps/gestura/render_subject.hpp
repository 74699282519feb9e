#pragma once
// The one place that decides what `gestura render` and `gestura view` show. Until the avatar
// module and the BVH importer are on main this is the renderer's procedural TEST FIGURE; point
// load_render_subject at the real avatar (and BVH clips) when they land.
#include <optional>
#include <string>

#include "gestura/render/subject.hpp"

namespace gestura::cli {

enum class Motion { Rest, TestMotion, ClipFile };

// Throws gestura::Error for a clip that cannot be read (or, for now, any clip file: BVH import is
// not wired into this build yet).
RenderSubject load_render_subject(Motion motion, const std::string& clip_path);

}  // namespace gestura::cli
