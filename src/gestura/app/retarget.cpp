#include "gestura/app/retarget.hpp"

#include <optional>

#include "gestura/anim/retarget.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/body/avatar_skeleton.hpp"

namespace gestura::app {
namespace {

bool onto_avatar(const RetargetRequest& request) { return request.to == "avatar" || request.to.starts_with("makehuman:"); }

AvatarChoice avatar_of(const RetargetRequest& request) {
  AvatarChoice choice;
  if (request.to != "avatar") choice.avatar = request.to;
  return choice;
}

}  // namespace

void validate(const RetargetRequest& request) {
  check_fields(request);
  if (request.to.empty()) usage_error("to", "is empty (avatar, makehuman:DIR or FILE.bvh)");
  if (!is_motion_file(request.input))
    usage_error("input", request.input + ": cannot read this kind of file (" + motion_file_extensions() + ")");
  validate(request.output, true);
}

RetargetResult run(const RetargetRequest& request, const RunContext& context) {
  validate(request);
  const MotionFile source = read_motion_file(request.input, {request.scale, request.z_up, {}}, "input");
  RunWorkspace workspace(context);
  // The body, when retargeting onto an avatar and the output shows it.
  const Avatar* avatar = nullptr;
  if (onto_avatar(request) && output_shows_body(request.output)) avatar = &workspace->avatar(avatar_of(request));
  RetargetResult result;
  if (avatar) result.target = avatar->skeleton;
  else if (request.to == "avatar") result.target = build_avatar_skeleton();
  else if (onto_avatar(request)) result.target = workspace->avatar(avatar_of(request)).skeleton;
  else result.target = read_motion_file(request.to, {request.scale, request.z_up, {}}, "to").motion.skeleton;

  RetargetOptions options;
  options.frame_time = source.motion.frame_time;
  options.preserve_end_effectors = request.end_effectors;
  result.clip = retarget(source.motion.skeleton, source.motion.clip, result.target, options);
  for (const auto& track : result.clip.rotations) result.driven += !track.empty();
  context.check_stop();
  // .bvh/.json keep the source's rate unless a rate is asked for.
  const float frame_time = request.output.picture.fps ? 0.0f : source.motion.frame_time;
  result.written = write_motion(request.output, result.target, result.clip, avatar ? &avatar->mesh : nullptr,
                                0.5f * result.clip.duration, context, frame_time);
  return result;
}

nlohmann::json to_json(const RetargetResult& result) {
  return {{"joints", result.target.size()},
          {"driven", result.driven},
          {"duration", result.clip.duration},
          {"written", {{"path", result.written.path}, {"frames", result.written.frames}}}};
}

}  // namespace gestura::app
