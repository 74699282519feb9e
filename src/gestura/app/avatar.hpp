#pragma once
// avatar: build the avatar (generated from parameters, or loaded from assets) and export it as
// binary glTF, describe it, or list its sign locations.
#include <optional>
#include <string>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"

namespace gestura::app {

enum class AvatarAction { export_glb, info, sites };

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
    visit(self.action, FieldInfo{.name = "action", .help = "export, info or sites", .value = "ACTION"});
    AvatarChoice::fields(self.avatar, visit);
    visit(self.output, FieldInfo{.name = "output", .help = "export: the binary glTF to write (.glb); sites: a .json file", .value = "FILE", .short_flag = 'o'});
  }
};

struct AvatarResult {
  Avatar avatar;
  std::string sites_json;  // sites: name → position in metres
  std::string written;     // the file written, if any
};

void validate(const AvatarRequest& request);
AvatarResult run(const AvatarRequest& request, const RunContext& context = {});
nlohmann::json to_json(const AvatarResult& result, AvatarAction action);

}  // namespace gestura::app
