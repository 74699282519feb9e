// gestura retarget IN -o OUT: a motion played on another skeleton (app/retarget.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/retarget.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::RetargetRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::RetargetResult r = app::run(*request, context);
    std::printf("wrote %s: %zu joints (%d driven), %d frames\n", r.written.path.c_str(), r.target.size(), r.driven,
                r.written.frames);
    return 0;
  };
  return invocation;
}

const Registration reg{{"retarget", "play a motion on another skeleton (the avatar by default)",
                        "Joints are paired by name (H-Anim, VRM, MakeHuman, CMU spellings are recognised); each paired\n"
                        "joint copies the source bone's model-space rotation change from its rest pose, so different rest\n"
                        "poses (T-pose vs A-pose) line up. Root motion is scaled by the ratio of leg lengths.\n"
                        "OUT keeps the source's frame rate unless --fps is given; pictures need --to avatar or\n"
                        "makehuman:DIR (a .png shows the middle of the motion).\n" +
                            std::string(app::kMotionOutputHelp),
                        prepare}};

}  // namespace
}  // namespace gestura::cli
