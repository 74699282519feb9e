#pragma once
// What `render` and `view` show: an avatar at rest, doing the built-in test wave, playing a motion
// file whose joints are the avatar's own (H-Anim names; any format motion_files.hpp reads),
// performing one sign, or signing English text.
#include <string>
#include <vector>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/notice.hpp"
#include "gestura/app/sign_source.hpp"
#include "gestura/render/subject.hpp"

namespace gestura::app {

struct SubjectChoice {
  std::string clip;    // a motion file on the avatar's skeleton
  bool rest = false;   // the rest pose (what is shown when nothing else is chosen)
  bool test_motion = false;
  AvatarChoice avatar;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.clip, FieldInfo{.name = "clip", .help = "a motion on the avatar's skeleton (H-Anim joint names): .bvh, .glb, .gltf, .bap", .value = "CLIP", .positional = true});
    visit(self.rest, FieldInfo{.name = "rest", .help = "the rest pose, no motion (the default)"});
    visit(self.test_motion, FieldInfo{.name = "test_motion", .help = "the built-in test motion (the right hand waves, 2 s)"});
    AvatarChoice::fields(self.avatar, visit);
  }
};

// What else a viewer may show.
struct SubjectExtras {
  SignSource sign;   // one sign
  std::string text;  // English to sign
};

// At most one of clip, rest, test_motion, a sign and text; throws AppError (usage).
void validate(const SubjectChoice& choice, const SubjectExtras& extras = {});

struct LoadedSubject {
  RenderSubject subject;
  std::vector<Notice> notices;
};

// Reads the motion first (a bad file or sign fails before the avatar is built), then builds the
// avatar and attaches the motion. A clip whose joints are not the avatar's is an input error naming
// a few of them.
LoadedSubject load_subject(const SubjectChoice& choice, const SubjectExtras& extras, const RunContext& context);

}  // namespace gestura::app
