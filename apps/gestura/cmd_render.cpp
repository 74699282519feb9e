// gestura render: headless rendering of the avatar to PNG, a PNG contact sheet, GIF, MP4 or WebM
// (app/render.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/render.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::RenderRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  binding(invocation.fields, "output").info.help = "the picture or video to write: .png, .gif, .mp4 or .webm";
  invocation.run = [request](const app::RunContext& context) {
    const app::RenderResult r = app::run(*request, context);
    for (const app::Notice& n : r.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
    return 0;
  };
  return invocation;
}

const Registration reg{{"render", "render the avatar to PNG, contact sheet, GIF, MP4 or WebM (headless)",
                        "Renders the avatar headless (EGL, no display needed): at rest (the default), doing the\n"
                        "test wave, or playing CLIP, a motion on the avatar's skeleton (H-Anim joint names, e.g.\n"
                        "written by gestura convert, retarget or reach -o; .bvh, .glb, .gltf or .bap); its joints\n"
                        "keep the avatar's proportions. A .png is one frame (at --time), or with --sheet a 4x4\n"
                        "contact sheet of 16 frames spread over the clip; .gif/.mp4/.webm get every frame at --fps.\n"
                        "The file appears only when complete.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
