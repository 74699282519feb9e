#pragma once
// avatar: build the avatar (generated from parameters, or loaded from assets) and export it as
// binary glTF, describe it, list its sign locations, or list the built-in looks.
#include <optional>
#include <string>
#include <vector>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"

namespace gestura::app {

enum class AvatarAction { export_glb, info, sites, looks };

template <>
struct TextCodec<AvatarAction> {
  static AvatarAction parse(std::string_view text);
  static std::string format(AvatarAction action);
};

struct AvatarRequest {
  AvatarAction action = AvatarAction::info;
  AvatarChoice avatar;
  std::string output;  // export: the .glb (required); sites: a .json (else the result carries it)

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.action, FieldInfo{.name = "action", .help = "export, info, sites or looks", .value = "ACTION"});
    AvatarChoice::fields(self.avatar, visit);
    visit(self.output, FieldInfo{.name = "output", .help = "export: the binary glTF to write (.glb); sites: a .json file", .value = "FILE", .short_flag = 'o'});
  }
};

struct AvatarLookEntry {
  std::string name, description;
};

struct AvatarResult {
  Avatar avatar;                       // empty for looks
  std::vector<AvatarLookEntry> looks;  // looks: the built-in looks, the default first
  std::string sites_json;  // sites: name → position in metres
  std::string written;     // the file written, if any
};

void validate(const AvatarRequest& request);
AvatarResult run(const AvatarRequest& request, const RunContext& context = {});
nlohmann::json to_json(const AvatarResult& result, AvatarAction action);

}  // namespace gestura::app
