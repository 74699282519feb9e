// gestura render: headless rendering of the avatar to PNG, a PNG contact sheet, GIF, MP4 or WebM.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/render_job.hpp"
#include "render_subject.hpp"

namespace gestura::cli {
namespace {

constexpr const char* kUsage = R"(usage: gestura render [CLIP.bvh | --rest | --test-motion] -o OUT.png|.gif|.mp4|.webm [options]

Renders the default avatar headless (EGL, no display needed). CLIP.bvh must be a motion on the
avatar's skeleton (H-Anim joint names, e.g. written by gestura convert or gestura reach -o);
its joints keep the avatar's proportions. A .png is one frame (at --time), or with --sheet a
4x4 contact sheet of 16 frames spread over the clip; .gif/.mp4/.webm get every frame at --fps.
The file appears only when complete.

  -o, --output PATH       output file (.png, .gif, .mp4, .webm)
  --camera LIST           front, side, three-quarter, top, side-section; a comma list
                          (front,side,top) renders a split view   [front]
  --orbit YAW,PITCH,DIST[,X,Y,Z]  free camera: degrees about +Y from the front, degrees up,
                          metres away from the target X,Y,Z (default: the body's centre)
  --size WxH              image size, 16..4096 per side, at most 4096x2304 pixels  [1280x720]
  --fps N                 frames per second, 1..120               [30]
  --background #rrggbb    background colour                       [#999ea3]
  --color MATERIAL=#rrggbb  colour of skin, cloth, hair, eye-white, iris, lips, teeth, tongue,
                          brow, pupil or mouth (repeatable)
  --sheet                 PNG contact sheet (16 frames, 4x4)
  --time S                the time a single PNG shows             [0]
  --seconds S             animation length with --rest            [2]
  --msaa N                samples per pixel for edge smoothing: 1, 2 or 4       [4]
  --cpu-skinning          skin on the CPU and upload (comparison path)
  --rest                  the rest pose, no clip (the default)
  --test-motion           the built-in test motion (the right hand waves, 2 s)
  --avatar SPEC                    default (generated), a built-in look (gestura avatar looks)
                                   or makehuman:DIR (MakeHuman assets)
  --height M, --build X, --sex S   the avatar, as in gestura avatar export)";

// Fills job.orbit (and whether it aims at the body) from "YAW,PITCH,DIST[,X,Y,Z]".
void parse_orbit(const std::string& text, RenderJob& job) {
  std::vector<float> values;
  std::stringstream in(text);
  bool ok = true;
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    try {
      values.push_back(std::stof(item, &used));
    } catch (const std::exception&) {
      ok = false;
    }
    ok = ok && used == item.size() && std::isfinite(values.back());
  }
  ok = ok && (values.size() == 3 || values.size() == 6) && values[2] > 0.0f && values[2] < 1000.0f;
  if (!ok) throw Error("bad --orbit '" + text + "' (expected YAW,PITCH,DISTANCE[,X,Y,Z], e.g. 30,10,2.5)");
  Orbit orbit;
  orbit.yaw = deg(values[0]);
  orbit.pitch = deg(values[1]);
  orbit.distance = values[2];
  job.orbit_about_body = values.size() == 3;
  if (values.size() == 6) orbit.target = vec3(values[3], values[4], values[5]);
  job.orbit = orbit;
}

int run(const std::vector<std::string>& args) {
  RenderJob job;
  Motion motion = Motion::Rest;
  AvatarParams avatar;
  std::string avatar_spec = "default";
  std::string clip_path;
  bool motion_given = false;
  auto set_motion = [&](Motion m) {
    if (motion_given) throw Error("give one of CLIP.bvh, --rest, --test-motion");
    motion = m, motion_given = true;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") job.output = flag_value(args, i);
    else if (a == "--camera") job.cameras = parse_camera_list(flag_value(args, i));
    else if (a == "--orbit") parse_orbit(flag_value(args, i), job);
    else if (a == "--size") job.size = parse_image_size(flag_value(args, i));
    else if (a == "--fps") job.fps = parse_fps(flag_value(args, i));
    else if (a == "--background") job.look.background = parse_hex_color(flag_value(args, i));
    else if (a == "--color") apply_color_setting(job.look, flag_value(args, i));
    else if (a == "--sheet") job.sheet = true;
    else if (a == "--time") job.still_time = parse_seconds(flag_value(args, i), "--time");
    else if (a == "--seconds") job.rest_seconds = parse_seconds(flag_value(args, i), "--seconds");
    else if (a == "--msaa") job.msaa_samples = parse_msaa(flag_value(args, i));
    else if (a == "--cpu-skinning") job.skinning = SkinningDevice::Cpu;
    else if (a == "--rest") set_motion(Motion::Rest);
    else if (a == "--test-motion") set_motion(Motion::TestMotion);
    else if (parse_avatar_flag(args, i, avatar, avatar_spec)) continue;
    else if (!a.empty() && a[0] == '-') throw Error("unknown flag " + a + " (see gestura render --help)");
    else clip_path = a, set_motion(Motion::ClipFile);
  }
  validate(job);
  const RenderSubject subject = load_render_subject(motion, clip_path, avatar, {}, avatar_spec);
  render_to_file(subject, job);
  return 0;
}

const Registration reg{{"render", "render the avatar to PNG, contact sheet, GIF, MP4 or WebM (headless)", kUsage, run}};

}  // namespace
}  // namespace gestura::cli
