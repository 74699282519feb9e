#include "gestura/app/avatar_choice.hpp"

#include "gestura/body/avatar_look.hpp"
#include "gestura/io/avatar_source.hpp"

namespace gestura::app {

bool AvatarChoice::generated() const { return find_look(avatar) != nullptr; }

std::string AvatarChoice::key() const { return generated() ? to_json(*this).dump() : avatar; }

void validate(const AvatarChoice& choice) {
  check_fields(choice);
  if (choice.avatar.empty()) usage_error("avatar", "is empty (default, a built-in look, makehuman:DIR or FILE.vrm|.glb|.gltf)");
  as_field_error(ErrorCategory::usage, "avatar", [&] { choice.params.validate(); });
}

Avatar build(const AvatarChoice& choice) {
  validate(choice);
  if (const AvatarLook* look = find_look(choice.avatar))
    return build_avatar(with_given(look->params, choice.params), AvatarOptions{.weights = choice.weights});
  // Other sources are load_avatar's to know; its errors name the spec or the asset file.
  return load_avatar(choice.avatar, choice.params);
}

}  // namespace gestura::app
