// gestura info FILE — what a motion file holds (app/info.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/info.hpp"
#include "gestura/app/motion_files.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::InfoRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::InfoResult r = app::run(*request, context);
    std::printf("file:       %s\nformat:     %s\n", r.file.c_str(), r.format.c_str());
    for (const auto& [label, value] : r.facts) {
      const std::string head = label.empty() ? "" : label + ":";
      std::printf("%-12s%s%s\n", head.c_str(), head.size() >= 12 ? " " : "", value.c_str());
    }
    if (!r.tree.empty()) std::printf("tree:\n");
    for (const app::InfoResult::TreeLine& t : r.tree) {
      std::printf("  %s%s", std::string(2 * static_cast<std::size_t>(t.depth), ' ').c_str(), t.name.c_str());
      if (t.hidden_below > 0) std::printf("  (+%d below)", t.hidden_below);
      std::printf("\n");
    }
    return 0;
  };
  return invocation;
}

const Registration reg{{"info", "describe a motion file (BVH, glTF/GLB, VRM, BAP, .gcl: joints, frames, fps, tree)",
                        "Prints what FILE holds: its format, root, joints and end sites, frames, frame time, fps,\n"
                        "duration, where the joints are at rest and the joint tree down to --depth. A BVH also\n"
                        "lists its channel layouts; a BAP its parameters; a VRM its mesh and expressions; a .gcl\n"
                        "its size (and, with --skeleton REF.bvh, everything else).\nReads " +
                            app::motion_file_extensions() + ".",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
