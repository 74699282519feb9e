// gestura sign: perform one sign written in HamNoSys (Unicode or symbol names) or SiGML on the
// default avatar, and write it as joint positions (.json), motion (.bvh) or pictures/video.
#include <cstdio>

#include "command.hpp"
#include "gestura/body/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace {

using namespace gestura;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int run_sign(const std::vector<std::string>& args) {
  std::string avatar_spec = "default", hamnosys, names, sigml_path, gloss, output, camera = "front", size = "1280x720";
  float speed = 1.0f;
  bool sheet = false;
  int fps = 30;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--hamnosys") hamnosys = cli::flag_value(args, i);
    else if (a == "--names") names = cli::flag_value(args, i);
    else if (a == "--sigml") sigml_path = cli::flag_value(args, i);
    else if (a == "--gloss") gloss = cli::flag_value(args, i);
    else if (a == "--avatar") avatar_spec = cli::flag_value(args, i);
    else if (a == "-o" || a == "--output") output = cli::flag_value(args, i);
    else if (a == "--camera") camera = cli::flag_value(args, i);
    else if (a == "--size") size = cli::flag_value(args, i);
    else if (a == "--sheet") sheet = true;
    else if (a == "--fps") fps = parse_fps(cli::flag_value(args, i));
    else if (a == "--speed") {
      const std::string v = cli::flag_value(args, i);
      char* end = nullptr;
      speed = std::strtof(v.c_str(), &end);
      if (end == v.c_str() || *end) throw Error("--speed needs a number, got '" + v + "'");
    } else throw Error("unknown argument '" + a + "' (see gestura sign --help)");
  }
  const int sources = !hamnosys.empty() + !names.empty() + !sigml_path.empty();
  if (sources != 1) throw Error("give exactly one of --hamnosys, --names, --sigml");
  if (output.empty()) throw Error("-o OUT is required (.json, .bvh, .png, .gif, .mp4, .webm)");

  sign::HamSign parsed;
  if (!hamnosys.empty()) parsed = sign::parse_hamnosys_unicode(hamnosys);
  else if (!names.empty()) parsed = sign::parse_hamnosys_names(names);
  else {
    const std::vector<sign::SigmlSign> signs = sign::read_sigml(sign::read_text_file(sigml_path), sigml_path);
    const sign::SigmlSign* chosen = nullptr;
    for (const sign::SigmlSign& s : signs)
      if (gloss.empty() || s.gloss == gloss) { chosen = &s; break; }
    if (!chosen) throw Error(sigml_path + ": no sign" + (gloss.empty() ? std::string() : " with gloss '" + gloss + "'"));
    parsed = chosen->manual;
  }

  const Avatar avatar = load_avatar(avatar_spec);
  const SigningRig rig = make_signing_rig(avatar);
  PlanOptions plan;
  plan.speed = speed;
  const SignSynthesis result = synthesize_sign(parsed, rig, plan, PerformOptions{static_cast<float>(fps)});
  if (const auto problem = synthesis_problem(result, rig)) std::fprintf(stderr, "warning: %s\n", problem->c_str());

  if (ends_with(output, ".json")) write_joint_positions_json(output, avatar.skeleton, result.clip, static_cast<float>(fps));
  else if (ends_with(output, ".bvh")) save_bvh(output, make_bvh(avatar.skeleton, result.clip, 1.0f / static_cast<float>(fps)));
  else {
    RenderJob job;
    job.output = output;
    job.size = parse_image_size(size);
    job.fps = fps;
    job.cameras = parse_camera_list(camera);
    job.sheet = sheet;
    job.still_time = 0.5f * (result.plan.sign_start + result.plan.sign_end);
    validate(job);
    RenderSubject subject{avatar.skeleton, avatar.mesh, result.clip};
    render_to_file(subject, job);
  }
  std::printf("%s: %.2f s (sign %.2f–%.2f s), %d frames\n", output.c_str(), result.clip.duration, result.plan.sign_start,
              result.plan.sign_end, result.stats.frames);
  return 0;
}

const cli::Registration reg{{
    "sign",
    "perform one sign from HamNoSys or SiGML on the default avatar",
    "usage: gestura sign (--hamnosys TEXT | --names SYMBOLS | --sigml FILE [--gloss NAME]) -o OUT\n"
    "                    [--avatar SPEC] [--speed S] [--fps N] [--camera LIST] [--size WxH] [--sheet]\n\n"
    "TEXT is HamNoSys 4 in Unicode; SYMBOLS a comma-separated list of HamNoSys symbol names\n"
    "(hamflathand,hamextfingeru,...). OUT by extension: .json joint positions\n"
    "({\"fps\", \"joints\", \"frames\"}; metres, +Y up, facing +Z, H-Anim names), .bvh motion, or a\n"
    ".png (the middle of the sign; --sheet: 16 frames in a 4x4 grid), .gif, .mp4, .webm.\n"
    "--speed scales the tempo (0.25–4). The dominant hand is the right hand. --avatar is default\n"
    "(the generated avatar) or makehuman:DIR (MakeHuman base mesh and default rig).",
    run_sign,
}};

}  // namespace
