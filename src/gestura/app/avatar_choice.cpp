#include "gestura/app/avatar_choice.hpp"

#include "gestura/io/avatar_source.hpp"

namespace gestura::app {

std::string AvatarChoice::key() const { return generated() ? to_json(*this).dump() : avatar; }

void validate(const AvatarChoice& choice) {
  check_fields(choice);
  if (choice.avatar.empty()) usage_error("avatar", "is empty (default, makehuman:DIR or FILE.vrm|.glb|.gltf)");
  as_field_error(ErrorCategory::usage, "avatar", [&] { choice.params.validate(); });
}

Avatar build(const AvatarChoice& choice) {
  validate(choice);
  if (choice.generated()) return build_avatar(choice.params, AvatarOptions{.weights = choice.weights});
  // Other sources are load_avatar's to know; its errors name the spec or the asset file.
  return load_avatar(choice.avatar, choice.params);
}

}  // namespace gestura::app
