// gestura sign: one sign written in HamNoSys (Unicode or symbol names) or SiGML, performed on the
// avatar and written as joint positions, motion or pictures (app/sign.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/sign.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::SignRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::SignResult result = app::run(*request, context);
    for (const app::Notice& n : result.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
    const SignSynthesis& s = result.synthesis;
    std::printf("%s: %.2f s (sign %.2f–%.2f s), %d frames\n", result.written.path.c_str(), s.clip.duration,
                s.plan.sign_start, s.plan.sign_end, s.stats.frames);
    return 0;
  };
  return invocation;
}

const Registration reg{{
    "sign",
    "perform one sign from HamNoSys or SiGML on the default avatar",
    "Give the sign with exactly one of --hamnosys (HamNoSys 4 in Unicode), --names (a comma-separated\n"
    "list of HamNoSys symbol names: hamflathand,hamextfingeru,...) or --sigml FILE [--gloss NAME].\n"
    "The dominant hand is the right hand. A SiGML sign's non-manual tiers (head, shoulders, body, eye\n"
    "gaze, brows, eyelids, nose, cheeks, mouth gestures and pictures) are performed over the sign;\n"
    "values that cannot be are named with their line on stderr. A single .png shows the middle of\n"
    "the sign.\n" + std::string(app::kMotionOutputHelp),
    prepare,
}};

}  // namespace
}  // namespace gestura::cli
