#include "gestura/app/convert.hpp"

#include <algorithm>
#include <functional>
#include <map>

#include "gestura/anim/retarget.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/io/bap_bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/io/openpose_json.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/skeleton/joint_names.hpp"

namespace gestura::app {
namespace {

// The motion on the default avatar's H-Anim skeleton, as BAP needs it. A motion already on H-Anim
// names goes as it is (its angles are the avatar's); any other is paired by the joint-name tables
// and retargeted, since its rest pose and joint frames are its own.
BvhFile on_avatar_joints(const BvhFile& motion, std::vector<Notice>& notices) {
  const Skeleton avatar = build_avatar_skeleton();
  int same = 0, joints = 0;
  for (std::size_t j = 0; j < motion.skeleton.size(); ++j) {
    if (motion.end_site[j]) continue;
    ++joints;
    same += avatar.find(motion.skeleton.names[j]) >= 0;
  }
  if (same * 2 > joints) return motion;
  const std::vector<std::string> guessed = guess_hanim_names(motion.skeleton);
  const auto named = std::count_if(guessed.begin(), guessed.end(), [](const std::string& n) { return !n.empty(); });
  if (named == 0)
    usage_error("input", "no joint has an H-Anim name or one the joint-name tables map to H-Anim (MakeHuman, CMU, VRM), "
                         "so BAP angles cannot be assigned");
  RetargetOptions options;
  options.frame_time = motion.frame_time;
  const Clip clip = retarget(motion.skeleton, motion.clip, avatar, options);
  notices.push_back(note(std::to_string(named) + " of " + std::to_string(joints) +
                         " joints mapped to H-Anim by name and retargeted onto the default avatar's skeleton"));
  return make_bvh(avatar, clip, motion.frame_time);
}

using Writer = std::function<std::vector<std::string>(const std::string& path, const BvhFile& motion)>;

std::vector<std::string> write_gltf(const std::string& path, const BvhFile& motion) {
  save_gltf(path, motion.skeleton, motion.clip);
  return {path};
}

const std::map<std::string, std::pair<std::string, Writer>>& writers() {
  static const std::map<std::string, std::pair<std::string, Writer>> table{
      {".bvh", {"BVH", [](const std::string& path, const BvhFile& motion) {
                  save_bvh(path, motion);
                  return std::vector<std::string>{path};
                }}},
      {".glb", {"glTF", write_gltf}},
      {".gltf", {"glTF", write_gltf}},
      // Joint positions in model space (metres) for the pose-format toolkit.
      {".pose", {"pose", [](const std::string& path, const BvhFile& motion) {
                   save_pose(path, pose_from_clip(motion.skeleton, motion.clip, 1.0f / motion.frame_time, PoseLayout::Skeleton3D));
                   return std::vector<std::string>{path};
                 }}},
      // OpenPose keypoints seen by the default front camera, one file per frame.
      {".json", {"OpenPose", [](const std::string& path, const BvhFile& motion) {
                   return save_openpose_json(path, motion.skeleton, motion.clip, 1.0f / motion.frame_time);
                 }}},
      // Contract: the motion is on the avatar's H-Anim joints (on_avatar_joints).
      {".bap", {"BAP", [](const std::string& path, const BvhFile& motion) {
                  save_bap(path, bvh_to_bap(motion, "gestura"));
                  return std::vector<std::string>{path};
                }}}};
  return table;
}

std::string writer_extensions() {
  std::string list;
  for (const auto& [ext, writer] : writers()) list += (list.empty() ? "" : ", ") + ext;
  return list;
}

}  // namespace

void validate(const ConvertRequest& request) {
  check_fields(request);
  // A .pose holds point positions, not joint rotations: it is re-encoded (0.1 → 0.2), not made into a motion.
  if (lower_extension(request.input) == ".pose") {
    if (lower_extension(request.output) != ".pose")
      usage_error("output", request.input + ": a .pose file holds point positions, not joint rotations; it converts to .pose only");
    return;
  }
  if (!is_motion_file(request.input))
    usage_error("input", request.input + ": cannot read '" + lower_extension(request.input) + "' files (supported: " +
                             motion_file_extensions() + ")");
  const std::string out = lower_extension(request.output);
  if (!writers().contains(out))
    usage_error("output", request.output + ": cannot write '" + (out.empty() ? "(no extension)" : out) +
                              "' files (supported: " + writer_extensions() + ")");
  if ((out == ".json") != request.openpose)
    usage_error(request.openpose ? "openpose" : "output",
                request.openpose ? "writes .json files" : request.output + ": JSON output is OpenPose keypoints; say --openpose");
}

ConvertResult run(const ConvertRequest& request, const RunContext&) {
  validate(request);
  if (lower_extension(request.input) == ".pose") {
    require_file("input", request.input);
    const PoseData pose = as_field_error(ErrorCategory::input, "input", [&] { return load_pose(request.input); });
    as_field_error(ErrorCategory::output, "output", [&] { save_pose(request.output, pose); });
    ConvertResult result;
    result.format_in = result.format_out = "pose";
    result.joints = pose.point_count();
    result.frames = static_cast<int>(pose.frames);
    result.written = {request.output};
    return result;
  }
  MotionFile in = read_motion_file(request.input, MotionReadOptions{request.scale, request.z_up, request.skeleton}, "input");
  const std::string ext = lower_extension(request.output);
  // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in the lambda below.
  const auto& writer = writers().at(ext);
  const std::string& format = writer.first;
  const Writer& write = writer.second;
  ConvertResult result;
  result.format_in = in.format;
  result.format_out = format;
  if (ext == ".bap") in.motion = on_avatar_joints(in.motion, result.notices);
  result.joints = in.motion.skeleton.size();
  result.frames = in.motion.frame_count;
  result.written = as_field_error(ErrorCategory::output, "output", [&] { return write(request.output, in.motion); });
  return result;
}

nlohmann::json to_json(const ConvertResult& result) {
  nlohmann::json out{{"from", result.format_in}, {"to", result.format_out}, {"joints", result.joints},
                     {"frames", result.frames}, {"written", result.written}};
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const Notice& n : result.notices) notes.push_back(n.text());
  return out;
}

}  // namespace gestura::app
