#pragma once
// Which avatar a request performs on: the generated one shaped by a few parameters, or one loaded
// from assets. Every command that shows or moves a body takes these same fields.
#include <string>

#include "gestura/app/codecs.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/body/avatar.hpp"

namespace gestura::app {

struct AvatarChoice {
  std::string avatar = "default";  // default | a built-in look | makehuman:DIR | FILE.vrm/.glb/.gltf (io/avatar_source.hpp)
  AvatarParams params;
  SkinWeightMethod weights = SkinWeightMethod::FieldDiffused;

  // The ranges are AvatarParams::validate()'s (a test holds them equal).
  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.avatar, FieldInfo{.name = "avatar", .help = "default (the generated avatar), a built-in look of it (ana, ben, chidi, dana, eli: gestura avatar looks; the parameters given change it), makehuman:DIR (MakeHuman base mesh and rig) or FILE.vrm|.glb|.gltf (your rigged avatar: VRM 1.0/0.x, glTF)", .value = "SPEC", .group = "Avatar"});
    visit(self.params.height, FieldInfo{.name = "height", .help = "generated avatar: crown to floor in metres", .value = "M", .min = 1.0, .max = 2.5, .group = "Avatar"});
    visit(self.params.build, FieldInfo{.name = "build", .help = "generated avatar: girth multiplier", .value = "X", .min = 0.6, .max = 1.6, .group = "Avatar"});
    visit(self.params.sex, FieldInfo{.name = "sex", .help = "generated avatar: female, male or neutral", .value = "S", .group = "Avatar"});
    visit(self.params.shoulder_width, FieldInfo{.name = "shoulder_width", .help = "generated avatar: shoulder width multiplier", .value = "X", .min = 0.7, .max = 1.4, .group = "Avatar"});
    visit(self.params.arm_length, FieldInfo{.name = "arm_length", .help = "generated avatar: arm length multiplier", .value = "X", .min = 0.8, .max = 1.25, .group = "Avatar"});
    visit(self.params.hand_size, FieldInfo{.name = "hand_size", .help = "generated avatar: hand size multiplier", .value = "X", .min = 0.7, .max = 1.4, .group = "Avatar"});
    visit(self.params.finger_length, FieldInfo{.name = "finger_length", .help = "generated avatar: finger length multiplier", .value = "X", .min = 0.7, .max = 1.4, .group = "Avatar"});
    visit(self.params.finger_thickness, FieldInfo{.name = "finger_thickness", .help = "generated avatar: finger thickness multiplier", .value = "X", .min = 0.6, .max = 1.5, .group = "Avatar"});
    visit(self.weights, FieldInfo{.name = "weights", .help = "generated avatar's skin weights: field, spheres or two-layer", .value = "METHOD", .group = "Avatar"});
  }

  // The generated avatar: "default" or a built-in look (body/avatar_look.hpp).
  bool generated() const;
  // A key equal for choices that give the same avatar (makehuman ignores the parameters).
  std::string key() const;
};

// Field checks plus the spec's form; throws AppError (usage) naming the field.
void validate(const AvatarChoice& choice);

// Builds or loads the avatar (slow: seconds). Asset errors are input errors naming the file.
Avatar build(const AvatarChoice& choice);

}  // namespace gestura::app
