#pragma once
// Built-in looks of the generated avatar, chosen by name (`--avatar ana`): who the avatar is (sex,
// stature, build) and how they appear (skin, hair and eye colours, hairstyle, clothing and its
// sleeves). Every look dresses for signing as interpreters do: a plain top in one colour that the
// hands stand out against.
//
// The colours a mesh is shown in (Mesh::material_colors) follow from the params' AvatarColors:
// lips a little redder and darker than the skin, nails paler, brows and lashes the hair's colour
// (darkened for fair hair, so the eyes and brows still read), the eye's white, teeth and the
// mouth's lining fixed.
#include <string>
#include <string_view>
#include <vector>

#include "gestura/body/avatar_params.hpp"

namespace gestura {

struct AvatarLook {
  std::string_view name;
  std::string_view description;  // one line, for listings
  AvatarParams params;
};

// The built-in looks, the default first.
const std::vector<AvatarLook>& builtin_looks();
// nullptr when there is no look of that name.
const AvatarLook* find_look(std::string_view name);
// "default, ana, ben, …" for messages and help.
std::string look_names();

// `look` with every field of `given` that differs from AvatarParams{} taken from `given`: flags
// given on the command line change a look (a flag given its default value does not).
AvatarParams with_given(const AvatarParams& look, const AvatarParams& given);

// The colour of every MaterialId (sRGB) for these colours.
std::vector<vec3> material_colors(const AvatarColors& colors);

}  // namespace gestura
