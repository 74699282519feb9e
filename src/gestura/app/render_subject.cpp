#include "gestura/app/render_subject.hpp"

#include <optional>

#include "gestura/anim/clip_by_name.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/render/test_motion.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace gestura::app {
namespace {

// The clip on the avatar's skeleton. Clips made on the avatar's H-Anim skeleton (any size, or a
// part of it) bind by joint name; anything else needs retargeting (gestura retarget).
Clip bind_to_avatar(const MotionFile& file, const Skeleton& avatar, const std::string& path) {
  const JointNameMatch match = match_joints_by_name(file.motion.skeleton, file.motion.clip, avatar);
  if (!match.unmatched.empty()) {
    std::string names;
    const std::size_t shown = std::min<std::size_t>(5, match.unmatched.size());
    for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + match.unmatched[i];
    if (shown < match.unmatched.size()) names += ", …";
    throw AppError(ErrorCategory::input, Place{"clip", {path}},
                   std::to_string(match.unmatched.size()) + " of the clip's " + std::to_string(file.motion.skeleton.size()) +
                       " joints are not joints of the avatar (" + names +
                       "); only clips on the avatar's H-Anim skeleton play here (gestura retarget puts others on it)");
  }
  return clip_for_skeleton(file.motion.skeleton, file.motion.clip, avatar, match);
}

}  // namespace

void validate(const SubjectChoice& choice, const SubjectExtras& extras) {
  check_fields(choice);
  validate(choice.avatar);
  const int chosen = !choice.clip.empty() + choice.rest + choice.test_motion + extras.sign.given() + !extras.text.empty();
  if (chosen > 1) usage_error("", "show one thing: CLIP, --rest, --test-motion, a sign (--hamnosys, --names, --sigml) or TEXT");
  if (extras.sign.given() || !extras.sign.gloss.empty()) validate(extras.sign);
  if (!choice.clip.empty() && !is_motion_file(choice.clip))
    usage_error("clip", choice.clip + ": cannot play this kind of file (" + motion_file_extensions() + ")");
}

LoadedSubject load_subject(const SubjectChoice& choice, const SubjectExtras& extras, const RunContext& context) {
  validate(choice, extras);
  std::optional<MotionFile> file;
  if (!choice.clip.empty()) file = read_motion_file(choice.clip, {}, "clip");
  std::optional<LoadedSign> sign;
  if (extras.sign.given()) sign = load_sign(extras.sign);

  RunWorkspace workspace(context);
  const Avatar& avatar = workspace->avatar(choice.avatar);
  LoadedSubject out{RenderSubject{avatar.skeleton, avatar.mesh, std::nullopt}, {}};
  context.check_stop();
  if (file) {
    out.subject.clip = bind_to_avatar(*file, out.subject.skeleton, choice.clip);
  } else if (choice.test_motion) {
    out.subject.clip = make_wave_clip(out.subject.skeleton);
  } else if (sign) {
    const SigningRig& rig = workspace->rig(choice.avatar);
    SignSynthesis result = synthesize_sign(sign->manual, sign->nonmanual, rig);
    for (const NonManualWarning& w : result.warnings) out.notices.push_back(warning(w.message, SourceLocation{sign->file, w.line}));
    if (const auto problem = synthesis_problem(result, rig)) out.notices.push_back(warning(*problem));
    out.subject.clip = std::move(result.clip);
  } else if (!extras.text.empty()) {
    SentencePerformance said = as_field_error(ErrorCategory::input, "text", [&] {
      return workspace->signer(choice.avatar).say(extras.text, SayOptions{});
    });
    for (const std::string& n : said.notes) out.notices.push_back(note(n));
    out.subject.clip = std::move(said.clip);
  }
  return out;
}

}  // namespace gestura::app
