#include "support/avatar_subject.hpp"

#include "gestura/body/avatar.hpp"
#include "gestura/render/test_motion.hpp"

namespace gestura {

const RenderSubject& default_avatar_subject() {
  static const RenderSubject subject = [] {
    Avatar avatar = build_avatar();
    RenderSubject s{std::move(avatar.skeleton), std::move(avatar.mesh), std::nullopt};
    s.clip = make_wave_clip(s.skeleton);
    return s;
  }();
  return subject;
}

}  // namespace gestura
