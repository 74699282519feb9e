// gestura avatar export|info|sites — the avatar as binary glTF, its structure, or its sign
// locations (app/avatar.hpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/avatar.hpp"
#include "gestura/body/face_morphs.hpp"

namespace gestura::cli {
namespace {

void print_info(const Avatar& a, SkinWeightMethod weights) {
  const Skeleton& s = a.skeleton;
  std::printf("height %.3f m, sex %s, skin weights %s\n", a.params.height, std::string(to_string(a.params.sex)).c_str(),
              std::string(to_string(weights)).c_str());
  std::printf("joints %zu, degrees of freedom %d\n", s.size(), s.total_dofs());
  for (std::size_t j = 0; j < s.size(); ++j) {
    const JointDofs& d = s.dofs[j];
    std::printf("  %-20s parent %-20s dof %d", s.names[j].c_str(),
                s.parents[j] < 0 ? "-" : s.names[static_cast<std::size_t>(s.parents[j])].c_str(), d.count());
    for (int axis = 0; axis < 3; ++axis)
      if (d.free(axis)) std::printf("  %c %.0f..%.0f", "xyz"[axis], to_degrees(d.min_angle[axis]), to_degrees(d.max_angle[axis]));
    std::printf("\n");
  }
  std::printf("vertices %zu, triangles %zu\n", a.mesh.vertex_count(), a.mesh.triangle_count());
  std::printf("morph targets %zu:", a.mesh.morphs.size());
  for (const MorphTarget& m : a.mesh.morphs) std::printf(" %s", m.name.c_str());
  std::printf("\nexpressions:");
  for (std::string_view e : kExpressionNames) std::printf(" %s", std::string(e).c_str());
  std::printf("\n");
}

std::function<Invocation()> action(app::AvatarAction kind) {
  return [kind] {
    auto request = std::make_shared<app::AvatarRequest>();
    request->action = kind;
    Invocation invocation;
    invocation.fields = bind_fields(*request);
    unbind(invocation.fields, "action");
    if (kind == app::AvatarAction::info || kind == app::AvatarAction::looks) unbind(invocation.fields, "output");
    if (kind == app::AvatarAction::looks)
      for (const char* name : {"avatar", "height", "build", "sex", "shoulder_width", "arm_length", "hand_size", "finger_length",
                               "finger_thickness", "weights"})
        unbind(invocation.fields, name);
    if (kind == app::AvatarAction::export_glb) binding(invocation.fields, "output").info.help = "the binary glTF to write (.glb)";
    if (kind == app::AvatarAction::sites) binding(invocation.fields, "output").info.help = "a .json file to write (else printed)";
    invocation.run = [request](const app::RunContext& context) {
      const app::AvatarResult r = app::run(*request, context);
      const Avatar& a = r.avatar;
      switch (request->action) {
        case app::AvatarAction::export_glb:
          std::printf("wrote %s: %zu joints, %zu vertices, %zu triangles, %zu morph targets\n", r.written.c_str(),
                      a.skeleton.size(), a.mesh.vertex_count(), a.mesh.triangle_count(), a.mesh.morphs.size());
          break;
        case app::AvatarAction::info: print_info(a, request->avatar.weights); break;
        case app::AvatarAction::sites:
          if (r.written.empty()) std::fputs(r.sites_json.c_str(), stdout);
          else std::printf("wrote %s\n", r.written.c_str());
          break;
        case app::AvatarAction::looks:
          for (const app::AvatarLookEntry& look : r.looks) std::printf("%-8s %s\n", look.name.c_str(), look.description.c_str());
          break;
      }
      return 0;
    };
    return invocation;
  };
}

const Registration reg{{"avatar", "build the default avatar; export it as glTF or print its structure",
                        "Builds the avatar from parameters (no asset files; --avatar NAME takes a built-in look, --avatar\n"
                        "makehuman:DIR loads the MakeHuman"
                        "base mesh and rig instead, the parameters then unused) and writes it as binary glTF 2.0 (skin,\n"
                        "joints, inverse bind matrices, named morph targets, materials), prints its joints, degrees of\n"
                        "freedom, vertex and triangle counts and morph names, or lists its sign locations.",
                        {},
                        {Command{"export", "write the avatar as binary glTF (-o FILE.glb)", {}, action(app::AvatarAction::export_glb), {}},
                         Command{"info", "print joints, degrees of freedom, vertices, triangles and morphs", {}, action(app::AvatarAction::info), {}},
                         Command{"sites", "sign locations: name → position in metres (JSON; -o FILE.json)", {}, action(app::AvatarAction::sites), {}},
                         Command{"looks", "the built-in looks --avatar takes by name (sex, build, skin, hair, clothing)", {}, action(app::AvatarAction::looks), {}}}}};

}  // namespace
}  // namespace gestura::cli
