// gestura sign: perform one sign written in HamNoSys (Unicode or symbol names) or SiGML on the
// default avatar, and write it as joint positions, motion or pictures/video (motion_output.hpp).
#include <cstdio>

#include "command.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "motion_output.hpp"
#include "sign_source.hpp"

namespace {

using namespace gestura;

int run_sign(const std::vector<std::string>& args) {
  cli::SignSource source;
  cli::MotionOutput out;
  std::string avatar_spec = "default";
  float speed = 1.0f;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (cli::parse_sign_source_flag(args, i, source) || cli::parse_motion_output_flag(args, i, out)) continue;
    if (a == "--avatar") avatar_spec = cli::flag_value(args, i);
    else if (a == "--speed") {
      const std::string v = cli::flag_value(args, i);
      char* end = nullptr;
      speed = std::strtof(v.c_str(), &end);
      if (end == v.c_str() || *end) throw Error("--speed needs a number, got '" + v + "'");
    } else throw Error("unknown argument '" + a + "' (see gestura sign --help)");
  }
  const sign::HamSign parsed = cli::load_sign(source);
  const std::vector<sign::NonManual> nonmanual = cli::load_nonmanuals(source);
  cli::check_motion_output(out);

  const Avatar avatar = load_avatar(avatar_spec);
  const SigningRig rig = make_signing_rig(avatar);
  PlanOptions plan;
  plan.speed = speed;
  const SignSynthesis result = synthesize_sign(parsed, nonmanual, rig, plan, PerformOptions{static_cast<float>(out.fps)});
  for (const NonManualWarning& w : result.warnings)
    std::fprintf(stderr, "warning: %s:%d: %s\n", source.sigml_path.c_str(), w.line, w.message.c_str());
  if (const auto problem = synthesis_problem(result, rig)) std::fprintf(stderr, "warning: %s\n", problem->c_str());

  cli::write_motion(out, avatar.skeleton, result.clip, &avatar.mesh, 0.5f * (result.plan.sign_start + result.plan.sign_end));
  std::printf("%s: %.2f s (sign %.2f–%.2f s), %d frames\n", out.path.c_str(), result.clip.duration, result.plan.sign_start,
              result.plan.sign_end, result.stats.frames);
  return 0;
}

const cli::Registration reg{{
    "sign",
    "perform one sign from HamNoSys or SiGML on the default avatar",
    "usage: gestura sign (--hamnosys TEXT | --names SYMBOLS | --sigml FILE [--gloss NAME]) -o OUT\n"
    "                    [--avatar SPEC] [--speed S] [--fps N] [--camera LIST] [--size WxH] [--sheet]\n\n"
    "TEXT is HamNoSys 4 in Unicode; SYMBOLS a comma-separated list of HamNoSys symbol names\n"
    "(hamflathand,hamextfingeru,...). --speed scales the tempo (0.25–4). The dominant hand is the\n"
    "right hand. A SiGML sign's non-manual tiers (head, shoulders, body, eye gaze, brows, eyelids,\n"
    "nose, cheeks, mouth gestures and pictures) are performed over the sign; values that cannot be\n"
    "are named with their line on stderr. --avatar is default (the generated avatar) or\n"
    "makehuman:DIR (MakeHuman base mesh and default rig). A single .png shows the middle of the sign.\n" +
        std::string(cli::kMotionOutputUsage),
    run_sign,
}};

}  // namespace
