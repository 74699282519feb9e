#include "render_subject.hpp"

#include "gestura/core/error.hpp"
#include "gestura/render/test_figure.hpp"

namespace gestura::cli {

RenderSubject load_render_subject(Motion motion, const std::string& clip_path) {
  RenderSubject subject = make_test_figure(2);
  switch (motion) {
    case Motion::Rest: subject.clip.reset(); break;
    case Motion::TestMotion: break;  // the test figure's own wave
    case Motion::ClipFile:
      throw Error(clip_path + ": reading BVH clips is not wired into the render command yet (use --rest or --test-motion)");
  }
  return subject;
}

}  // namespace gestura::cli
