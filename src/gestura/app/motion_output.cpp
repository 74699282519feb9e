#include "gestura/app/motion_output.hpp"

#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/holistic_landmarks.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/render/subject.hpp"

namespace gestura::app {

MotionFileKind motion_file_kind(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".json") return MotionFileKind::JointPositions;
  if (ext == ".bvh") return MotionFileKind::Bvh;
  if (ext == ".glb" || ext == ".gltf") return MotionFileKind::Gltf;
  if (ext == ".pose") return MotionFileKind::Pose;
  if (ext == ".png" || ext == ".gif" || ext == ".mp4" || ext == ".webm") return MotionFileKind::Pictures;
  return MotionFileKind::Unknown;
}

RenderJob render_job(const MotionOutput& out, float still_time) {
  RenderJob job;
  job.output = out.output;
  job.size = out.picture.size;
  job.fps = out.picture.rate();
  job.cameras = out.picture.camera;
  job.sheet = out.sheet;
  job.still_time = still_time;
  return job;
}

bool output_shows_body(const MotionOutput& out) {
  const MotionFileKind kind = motion_file_kind(out.output);
  return kind == MotionFileKind::Gltf || kind == MotionFileKind::Pictures;
}

void validate(const MotionOutput& out, bool required) {
  check_fields(out);
  if (out.output.empty()) {
    if (required) usage_error("output", "is required (.json, .bvh, .glb, .gltf, .pose, .png, .gif, .mp4, .webm)");
    if (out.sheet) usage_error("sheet", "needs a .png output");
    return;
  }
  const MotionFileKind kind = motion_file_kind(out.output);
  if (kind == MotionFileKind::Unknown)
    usage_error("output", out.output + ": cannot write this kind of file (.json, .bvh, .glb, .gltf, .pose, .png, .gif, .mp4 or .webm)");
  if (kind == MotionFileKind::Pictures) as_field_error(ErrorCategory::usage, "output", [&] { validate(render_job(out, 0.0f)); });
  else if (out.sheet) usage_error("sheet", "needs a .png output, not " + out.output);
}

RenderMonitor render_monitor(const RunContext& context, const std::string& stage) {
  RenderMonitor monitor;
  if (context.progress) monitor.frame_done = [&context, stage](int done, int total) { context.report(stage, done, total); };
  monitor.stop_requested = [&context] { return context.stop.stop_requested(); };
  return monitor;
}

WrittenFile write_motion(const MotionOutput& out, const Skeleton& skeleton, const Clip& clip, const Mesh* body,
                         float still_time, const RunContext& context, float frame_time) {
  validate(out, true);
  // The rate as asked (30, not 1/(1/30)) where no frame spacing of the source's own is kept.
  const float rate = frame_time > 0.0f ? 1.0f / frame_time : static_cast<float>(out.picture.rate());
  if (frame_time <= 0.0f) frame_time = 1.0f / static_cast<float>(out.picture.rate());
  WrittenFile written{out.output, static_cast<int>(std::lround(clip.duration / frame_time)) + 1};
  const MotionFileKind kind = motion_file_kind(out.output);
  if (kind == MotionFileKind::Pictures && !body)
    usage_error("output", out.output + ": pictures need the avatar's body (this motion is on another skeleton)");
  // What fails from here on is the writing (a path that cannot be written, a full disk).
  as_field_error(ErrorCategory::output, "output", [&] {
    switch (kind) {
      case MotionFileKind::JointPositions: write_joint_positions_json(out.output, skeleton, clip, 1.0f / frame_time); break;
      case MotionFileKind::Bvh: save_bvh(out.output, make_bvh(skeleton, clip, frame_time)); break;
      case MotionFileKind::Gltf: save_gltf(out.output, skeleton, clip, body); break;
      case MotionFileKind::Pose: {
        // MediaPipe Holistic landmarks as the pictures of the same fields would show them.
        const RenderJob job = render_job(out, still_time);
        const float fps = rate;
        const HolisticTrack track = holistic_track(skeleton, body, clip, fps);
        std::vector<PinholeCamera> cameras(1);
        cameras[0].width = job.size.width, cameras[0].height = job.size.height;
        if (body) cameras = job_pinhole_cameras(RenderSubject{skeleton, *body, clip}, job, fps, track.frames);
        save_pose(out.output, holistic_pose(track, cameras, fps));
        break;
      }
      case MotionFileKind::Pictures: {
        const RenderSubject subject{skeleton, *body, clip};
        const RenderJob job = render_job(out, still_time);
        written.frames = render_to_file(subject, job, render_monitor(context, "rendering " + out.output)).frames;
        break;
      }
      case MotionFileKind::Unknown: break;  // validate threw
    }
  });
  return written;
}

}  // namespace gestura::app
