// gestura convert IN OUT — motion files between formats, chosen by extension (app/convert.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/convert.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::ConvertRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::ConvertResult r = app::run(*request, context);
    for (const app::Notice& n : r.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
    std::printf("wrote %s: %zu joints and end sites, %d frames\n", request->output.c_str(), r.joints, r.frames);
    return 0;
  };
  return invocation;
}

const Registration reg{{"convert", "convert motion files (BVH, glTF, VRM, BAP, .gcl → BVH, glTF, BAP, .pose, OpenPose; scale, Z-up → Y-up)",
                        "Reads IN and writes OUT, formats chosen by extension in any case. Reads .bvh, .glb, .gltf,\n"
                        ".vrm (the skeleton at rest), .bap and .gcl (with --skeleton); writes .bvh, .glb, .gltf,\n"
                        ".bap, .pose (joint positions for the pose-format toolkit) and with --openpose .json\n"
                        "(OpenPose BODY_25 + hand keypoints from a front camera, OUT_<frame>_keypoints.json per frame).\n"
                        ".bap  MPEG-4 BAP text, angles on the default avatar's H-Anim skeleton (1e-5 rad\n"
                        "      resolution). A motion on other joint names (MakeHuman, CMU, VRM) is mapped to H-Anim\n"
                        "      by the joint-name tables and retargeted onto that skeleton first; MakeHuman BVH\n"
                        "      needs --scale 0.1 --z-up.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
