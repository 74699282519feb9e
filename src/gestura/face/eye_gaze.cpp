#include "gestura/face/eye_gaze.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/face/head_motion.hpp"

namespace gestura::face {

namespace {

int required_joint(const Skeleton& skeleton, const char* name) {
  const int j = skeleton.find(name);
  if (j < 0) throw Error(std::string("eye gaze needs joint '") + name + "' in the skeleton");
  return j;
}

// The eye's local rotation that looks along `direction` (model space) turned `weight` of the way
// from its rest, within its limits. `parent` is the parent's model matrix.
quat aim(const Skeleton& skeleton, int eye, const mat4& parent, vec3 direction, float weight) {
  const std::size_t e = static_cast<std::size_t>(eye);
  const quat rest = skeleton.rest_rotations[e];
  // The direction in the eye's rest frame, where +Z is straight ahead.
  const vec3 d = glm::normalize(glm::inverse(rest) * (glm::inverse(glm::quat_cast(mat3(parent))) * direction));
  const float pitch = std::asin(std::clamp(-d.y, -1.0f, 1.0f));  // + looks down (rotation about +X)
  const float yaw = std::atan2(d.x, d.z);
  // Yaw outside, pitch inside: no roll of the eye about its line of sight.
  const quat look = glm::angleAxis(yaw, vec3(0, 1, 0)) * glm::angleAxis(pitch, vec3(1, 0, 0));
  vec3 angles = joint_angles(skeleton, eye, rest * look);
  const JointDofs& dofs = skeleton.dofs[e];
  for (int a = 0; a < 3; ++a)
    angles[a] = dofs.free(a) ? std::clamp(angles[a], dofs.min_angle[a], dofs.max_angle[a]) * weight : 0.0f;
  return joint_rotation(skeleton, eye, angles);
}

// Angle beyond the eyes' own share, with its sign.
float beyond_eyes(float angle) {
  const float eyes = glm::radians(kEyeOnlyDegrees);
  return angle > eyes ? angle - eyes : angle < -eyes ? angle + eyes : 0.0f;
}

void turn_joint(const Skeleton& skeleton, int joint, vec3 delta, Pose& pose) {
  const std::size_t j = static_cast<std::size_t>(joint);
  vec3 angles = joint_angles(skeleton, joint, pose.rotations[j]) + delta;
  const JointDofs& dofs = skeleton.dofs[j];
  for (int a = 0; a < 3; ++a)
    if (dofs.free(a)) angles[a] = std::clamp(angles[a], dofs.min_angle[a], dofs.max_angle[a]);
  pose.rotations[j] = joint_rotation(skeleton, joint, angles);
}

}  // namespace

void write_eye_gaze(const Skeleton& skeleton, Clip& clip, float fps) {
  const int channel = clip.find_channel(std::string(kGazeHands));
  if (channel < 0) return;
  if (!(fps >= 1.0f && fps <= 240.0f)) throw Error("eye gaze: fps " + std::to_string(fps) + " is outside 1–240");
  const std::array<int, 2> eyes{required_joint(skeleton, "l_eyeball_joint"), required_joint(skeleton, "r_eyeball_joint")};
  const std::array<int, 2> head{required_joint(skeleton, "vc4"), required_joint(skeleton, "skullbase")};
  const std::array<float, 2> head_share{kNeckShare, 1.0f - kNeckShare};
  const int wrist = required_joint(skeleton, "r_wrist"), knuckle = required_joint(skeleton, "r_middle1");
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  if (clip.joint_count() != skeleton.size())
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.joint_count()) +
                " joints, the skeleton has " + std::to_string(skeleton.size()));

  const FloatTrack weights = clip.channels[static_cast<std::size_t>(channel)];
  if (weights.empty()) return;
  // The body without the eyes' old keys: they must not steer their own aim.
  for (int e : eyes) clip.rotations[static_cast<std::size_t>(e)] = {};
  const Pose rest = rest_pose(skeleton);
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest, model);
  const quat head_bind = glm::quat_cast(mat3(model[static_cast<std::size_t>(head[1])]));

  std::array<QuatTrack, 4> tracks;  // eyes, then vc4 and skullbase
  const float end = std::max(clip.duration, clip.end_time());
  const int frames = static_cast<int>(std::ceil(end * fps)) + 1;
  Pose pose;
  Sampler sampler(clip);
  auto position = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };
  for (int f = 0; f < frames; ++f) {
    const float t = std::min(static_cast<float>(f) / fps, end);
    if (!tracks[0].empty() && t <= tracks[0].times.back()) continue;
    const float w = std::clamp(sample_track(weights, t), 0.0f, 1.0f);
    sampler.sample(t, WrapMode::Clamp, rest, pose);
    if (w > 0.0f) {
      local_to_model(skeleton, pose, model);
      const vec3 hand = 0.5f * (position(wrist) + position(knuckle));
      const vec3 between_eyes = 0.5f * (position(eyes[0]) + position(eyes[1]));
      // The hand's direction as seen from the head, in the head's bind frame (+Z ahead).
      const quat head_turn = glm::quat_cast(mat3(model[static_cast<std::size_t>(head[1])])) * glm::inverse(head_bind);
      const vec3 d = glm::normalize(glm::inverse(head_turn) * (hand - between_eyes));
      const vec3 turn = w * vec3(beyond_eyes(std::asin(std::clamp(-d.y, -1.0f, 1.0f))), beyond_eyes(std::atan2(d.x, d.z)), 0.0f);
      for (std::size_t i = 0; i < 2; ++i) turn_joint(skeleton, head[i], turn * head_share[i], pose);
      local_to_model(skeleton, pose, model);
      for (std::size_t i = 0; i < 2; ++i) {
        const std::size_t e = static_cast<std::size_t>(eyes[i]);
        const mat4& parent = model[static_cast<std::size_t>(skeleton.parents[e])];
        tracks[i].add(t, aim(skeleton, eyes[i], parent, hand - position(eyes[i]), w));
      }
    } else {
      for (std::size_t i = 0; i < 2; ++i) tracks[i].add(t, skeleton.rest_rotations[static_cast<std::size_t>(eyes[i])]);
    }
    for (std::size_t i = 0; i < 2; ++i) tracks[2 + i].add(t, pose.rotations[static_cast<std::size_t>(head[i])]);
  }
  const std::array<int, 4> joints{eyes[0], eyes[1], head[0], head[1]};
  for (std::size_t i = 0; i < 4; ++i) {
    make_continuous(tracks[i]);
    clip.rotations[static_cast<std::size_t>(joints[i])] = std::move(tracks[i]);
  }
  clip.duration = std::max(clip.duration, end);
}

}  // namespace gestura::face
