// gestura retarget IN.bvh -o OUT [--to avatar|makehuman:DIR|FILE.bvh] [--scale S] [--z-up] [--end-effectors]
// Plays the motion of IN on another skeleton (the default avatar unless --to names the MakeHuman
// avatar or a BVH whose skeleton to use) and writes it by extension (motion_output.hpp).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "command.hpp"
#include "gestura/anim/retarget.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "motion_output.hpp"

namespace {

using gestura::Error;

float positive_number(const std::string& flag, const std::string& value) {
  std::size_t used = 0;
  float v = 0.0f;
  try {
    v = std::stof(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !std::isfinite(v) || !(v > 0.0f))
    throw Error(flag + " needs a positive number, got '" + value + "'");
  return v;
}

int run_retarget(const std::vector<std::string>& args) {
  std::string in, to = "avatar";
  gestura::cli::MotionOutput out;
  gestura::BvhReadOptions options;
  gestura::RetargetOptions retarget_options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (gestura::cli::parse_motion_output_flag(args, i, out)) continue;
    if (a == "--to") to = gestura::cli::flag_value(args, i);
    else if (a == "--scale") options.scale = positive_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--z-up") options.z_up = true;
    else if (a == "--end-effectors") retarget_options.preserve_end_effectors = true;
    else if (a.starts_with("-")) throw Error("unknown flag " + a);
    else if (in.empty()) in = a;
    else throw Error("more than one input file: " + a);
  }
  if (in.empty() || out.path.empty())
    throw Error("usage: gestura retarget IN.bvh -o OUT [--to avatar|makehuman:DIR|FILE.bvh] [--scale S] [--z-up] [--end-effectors]");
  gestura::cli::check_motion_output(out);
  const bool fps_given = std::find(args.begin(), args.end(), "--fps") != args.end();
  const gestura::BvhFile source = gestura::load_bvh(in, options);
  // The body, when retargeting onto an avatar and the output shows it.
  std::optional<gestura::Avatar> avatar;
  const bool onto_avatar = to == "avatar" || to.starts_with("makehuman:");
  if (onto_avatar && gestura::cli::output_shows_body(out)) avatar = gestura::load_avatar(to == "avatar" ? "default" : to);
  const gestura::Skeleton target = avatar                        ? avatar->skeleton
                                   : to == "avatar"              ? gestura::build_avatar_skeleton()
                                   : to.starts_with("makehuman:") ? gestura::load_avatar(to).skeleton
                                                                  : gestura::load_bvh(to, options).skeleton;
  retarget_options.frame_time = source.frame_time;
  const gestura::Clip clip = gestura::retarget(source.skeleton, source.clip, target, retarget_options);
  if (!fps_given) out.motion_frame_time = source.frame_time;  // .bvh/.json keep the source's rate
  const int frames = gestura::cli::write_motion(out, target, clip, avatar ? &avatar->mesh : nullptr, 0.5f * clip.duration);
  int paired = 0;
  for (const auto& track : clip.rotations) paired += !track.empty();
  std::cout << "wrote " << out.path << ": " << target.size() << " joints (" << paired << " driven), "
            << frames << " frames\n";
  return 0;
}

gestura::cli::Registration reg{
    {"retarget", "play a BVH motion on another skeleton (the avatar by default)",
     "usage: gestura retarget IN.bvh -o OUT [--to avatar|makehuman:DIR|FILE.bvh] [--scale S] [--z-up] [--end-effectors]\n"
     "                        [--fps N] [--size WxH] [--camera LIST] [--sheet]\n\n"
     "Joints are paired by name (H-Anim, VRM, MakeHuman, CMU spellings are recognised); each paired\n"
     "joint copies the source bone's model-space rotation change from its rest pose, so different rest\n"
     "poses (T-pose vs A-pose) line up. Root motion is scaled by the ratio of leg lengths.\n"
     "OUT keeps the source's frame rate unless --fps is given; pictures need --to avatar or\n"
     "makehuman:DIR (a .png shows the middle of the motion). " + std::string(gestura::cli::kMotionOutputUsage) + "\n"
     "--to T           avatar (default), makehuman:DIR (the MakeHuman avatar of gestura render --avatar)\n"
     "                 or a BVH file whose skeleton receives the motion\n"
     "--scale S        multiplies lengths of IN (and of a --to file), e.g. 0.1 for MakeHuman decimetres\n"
     "--z-up           IN (and a --to file) is Z-up facing -Y (MakeHuman, Blender)\n"
     "--end-effectors  keep wrists and ankles where the source has them relative to its root (scaled)",
     run_retarget}};

}  // namespace
