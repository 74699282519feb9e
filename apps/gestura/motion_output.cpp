#include "motion_output.hpp"

#include <cmath>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/holistic_landmarks.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/subject.hpp"

namespace gestura::cli {
namespace {

enum class Kind { JointPositions, Bvh, Gltf, Pose, Pictures, Unknown };

Kind kind_of(const std::string& path) {
  if (path.ends_with(".json")) return Kind::JointPositions;
  if (path.ends_with(".bvh")) return Kind::Bvh;
  if (path.ends_with(".glb") || path.ends_with(".gltf")) return Kind::Gltf;
  if (path.ends_with(".pose")) return Kind::Pose;
  for (const char* ext : {".png", ".gif", ".mp4", ".webm"})
    if (path.ends_with(ext)) return Kind::Pictures;
  return Kind::Unknown;
}

RenderJob render_job(const MotionOutput& out, float still_time) {
  RenderJob job;
  job.output = out.path;
  job.size = parse_image_size(out.size);
  job.fps = out.fps;
  job.cameras = parse_camera_list(out.camera);
  job.sheet = out.sheet;
  job.still_time = still_time;
  return job;
}

}  // namespace

bool parse_motion_output_flag(const std::vector<std::string>& args, std::size_t& i, MotionOutput& out) {
  const std::string& a = args[i];
  if (a == "-o" || a == "--output") out.path = flag_value(args, i);
  else if (a == "--size") out.size = flag_value(args, i);
  else if (a == "--camera") out.camera = flag_value(args, i);
  else if (a == "--fps") out.fps = parse_fps(flag_value(args, i));
  else if (a == "--sheet") out.sheet = true;
  else return false;
  return true;
}

bool output_shows_body(const MotionOutput& out) {
  const Kind kind = kind_of(out.path);
  return kind == Kind::Gltf || kind == Kind::Pictures;
}

void check_motion_output(const MotionOutput& out) {
  if (out.path.empty()) throw Error("-o OUT is required (.json, .bvh, .glb, .gltf, .pose, .png, .gif, .mp4, .webm)");
  const Kind kind = kind_of(out.path);
  if (kind == Kind::Unknown)
    throw Error(out.path + ": cannot write this kind of file (OUT must end in .json, .bvh, .glb, .gltf, .pose, .png, .gif, .mp4 or .webm)");
  if (kind == Kind::Pictures) validate(render_job(out, 0.0f));
  else if (kind == Kind::Pose) parse_image_size(out.size), parse_camera_list(out.camera);
  else if (out.sheet) throw Error("--sheet needs a .png output, not " + out.path);
}

int write_motion(const MotionOutput& out, const Skeleton& skeleton, const Clip& clip, const Mesh* body,
                 float still_time) {
  check_motion_output(out);
  const float frame_time = out.motion_frame_time > 0.0f ? out.motion_frame_time : 1.0f / static_cast<float>(out.fps);
  switch (kind_of(out.path)) {
    case Kind::JointPositions: write_joint_positions_json(out.path, skeleton, clip, 1.0f / frame_time); break;
    case Kind::Bvh: save_bvh(out.path, make_bvh(skeleton, clip, frame_time)); break;
    case Kind::Gltf: save_gltf(out.path, skeleton, clip, body); break;
    case Kind::Pose: {
      // MediaPipe Holistic landmarks as the pictures of the same flags would show them.
      const RenderJob job = render_job(out, still_time);
      const float fps = out.motion_frame_time > 0.0f ? 1.0f / out.motion_frame_time : static_cast<float>(out.fps);
      const HolisticTrack track = holistic_track(skeleton, body, clip, fps);
      std::vector<PinholeCamera> cameras(1);
      cameras[0].width = job.size.width, cameras[0].height = job.size.height;
      if (body) cameras = job_pinhole_cameras(RenderSubject{skeleton, *body, clip}, job, fps, track.frames);
      save_pose(out.path, holistic_pose(track, cameras, fps));
      break;
    }
    case Kind::Pictures: {
      if (!body) throw Error(out.path + ": pictures need the avatar's body (this motion is on another skeleton)");
      const RenderSubject subject{skeleton, *body, clip};
      return render_to_file(subject, render_job(out, still_time)).frames;
    }
    case Kind::Unknown: break;  // check_motion_output threw
  }
  return static_cast<int>(std::lround(clip.duration / frame_time)) + 1;
}

}  // namespace gestura::cli
