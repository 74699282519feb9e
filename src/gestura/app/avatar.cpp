#include "gestura/app/avatar.hpp"

#include <cstdio>

#include "gestura/body/avatar_look.hpp"
#include "gestura/body/body_sites.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/io/gltf_export.hpp"

namespace gestura::app {

AvatarAction TextCodec<AvatarAction>::parse(std::string_view text) {
  if (text == "export") return AvatarAction::export_glb;
  if (text == "info") return AvatarAction::info;
  if (text == "sites") return AvatarAction::sites;
  if (text == "looks") return AvatarAction::looks;
  throw Error("'" + std::string(text.substr(0, 40)) + "' is not export, info, sites or looks");
}

std::string TextCodec<AvatarAction>::format(AvatarAction action) {
  switch (action) {
    case AvatarAction::export_glb: return "export";
    case AvatarAction::info: return "info";
    case AvatarAction::sites: return "sites";
    case AvatarAction::looks: return "looks";
  }
  return "info";
}

void validate(const AvatarRequest& request) {
  check_fields(request);
  validate(request.avatar);
  switch (request.action) {
    case AvatarAction::export_glb:
      if (request.output.empty()) usage_error("output", "missing: the .glb file to write");
      if (!has_extension(request.output, ".glb"))
        usage_error("output", request.output + ": avatar export writes binary glTF; name the file .glb");
      break;
    case AvatarAction::info:
    case AvatarAction::looks:
      if (!request.output.empty()) usage_error("output", "is only for export and sites");
      break;
    case AvatarAction::sites:
      if (!request.output.empty() && !has_extension(request.output, ".json"))
        usage_error("output", request.output + ": sites are written as .json");
      break;
  }
}

AvatarResult run(const AvatarRequest& request, const RunContext&) {
  validate(request);
  if (request.action == AvatarAction::looks) {
    AvatarResult result;
    for (const AvatarLook& look : builtin_looks()) result.looks.push_back({std::string(look.name), std::string(look.description)});
    return result;
  }
  AvatarResult result{build(request.avatar), {}, {}, {}};
  const Avatar& a = result.avatar;
  if (request.action == AvatarAction::export_glb) {
    as_field_error(ErrorCategory::output, "output", [&] { write_glb(request.output, a.skeleton, a.mesh, "gestura_avatar"); });
    result.written = request.output;
  }
  if (request.action == AvatarAction::sites) {
    result.sites_json = body_sites_json(a.skeleton, find_body_sites(a.skeleton, a.mesh));
    if (!request.output.empty()) {
      as_field_error(ErrorCategory::output, "output", [&] { write_file_atomically(request.output, result.sites_json); });
      result.written = request.output;
    }
  }
  return result;
}

nlohmann::json to_json(const AvatarResult& result, AvatarAction action) {
  if (action == AvatarAction::looks) {
    nlohmann::json looks = nlohmann::json::array();
    for (const AvatarLookEntry& look : result.looks) looks.push_back({{"name", look.name}, {"description", look.description}});
    return nlohmann::json{{"looks", looks}};
  }
  const Avatar& a = result.avatar;
  nlohmann::json out{{"height", a.params.height},
                     {"joints", a.skeleton.size()},
                     {"degrees_of_freedom", a.skeleton.total_dofs()},
                     {"vertices", a.mesh.vertex_count()},
                     {"triangles", a.mesh.triangle_count()}};
  auto& morphs = out["morph_targets"] = nlohmann::json::array();
  for (const MorphTarget& m : a.mesh.morphs) morphs.push_back(m.name);
  if (action == AvatarAction::sites) out["sites"] = nlohmann::json::parse(result.sites_json);
  if (!result.written.empty()) out["written"] = result.written;
  return out;
}

}  // namespace gestura::app
