#include "gestura/face/eye_aim.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/head_motion.hpp"

namespace gestura::face {

namespace {

int required_joint(const Skeleton& skeleton, const char* name) {
  const int j = skeleton.find(name);
  if (j < 0) throw Error(std::string("eye gaze needs joint '") + name + "' in the skeleton");
  return j;
}

quat rotation_of(const mat4& m) { return glm::normalize(glm::quat_cast(mat3(m))); }

// How the joint's parent has turned from its bind pose: for an eye, the head frame.
quat parent_turn(const Skeleton& skeleton, int joint, std::span<const mat4> model, std::span<const mat4> bind) {
  const std::size_t p = static_cast<std::size_t>(skeleton.parents[static_cast<std::size_t>(joint)]);
  return rotation_of(model[p]) * glm::inverse(rotation_of(bind[p]));
}

vec3 position_of(std::span<const mat4> model, int joint) { return vec3(model[static_cast<std::size_t>(joint)][3]); }

// Adds `delta` (radians, the joint's axes) to the joint's angles in `pose`, within its limits.
void turn_joint(const Skeleton& skeleton, int joint, vec3 delta, Pose& pose) {
  const std::size_t j = static_cast<std::size_t>(joint);
  vec3 angles = joint_angles(skeleton, joint, pose.rotations[j]) + delta;
  const JointDofs& dofs = skeleton.dofs[j];
  for (int a = 0; a < 3; ++a)
    if (dofs.free(a)) angles[a] = std::clamp(angles[a], dofs.min_angle[a], dofs.max_angle[a]);
  pose.rotations[j] = joint_rotation(skeleton, joint, angles);
}

}  // namespace

vec2 gaze_angles(vec3 direction) {
  const vec3 d = glm::normalize(direction);
  return {std::asin(std::clamp(-d.y, -1.0f, 1.0f)), std::atan2(d.x, d.z)};
}

vec2 beyond_eyes(vec2 gaze) {
  const float eyes = glm::radians(kEyeOnlyDegrees);
  vec2 out(0.0f);
  for (int a = 0; a < 2; ++a) out[a] = gaze[a] > eyes ? gaze[a] - eyes : gaze[a] < -eyes ? gaze[a] + eyes : 0.0f;
  return out;
}

quat eye_rotation(const Skeleton& skeleton, int eye, std::span<const mat4> model, std::span<const mat4> bind,
                  vec3 target, float weight) {
  const std::size_t e = static_cast<std::size_t>(eye);
  const vec3 d = glm::inverse(parent_turn(skeleton, eye, model, bind)) * (target - position_of(model, eye));
  if (glm::length(d) < 1e-6f) return skeleton.rest_rotations[e];
  const vec2 gaze = gaze_angles(d);
  // Yaw outside, pitch inside, in the head frame; then into the joint's frame: the eye's model
  // rotation is turn · look · bind, so its local one is parent_bind⁻¹ · look · bind.
  const quat look = glm::angleAxis(gaze.y, vec3(0, 1, 0)) * glm::angleAxis(gaze.x, vec3(1, 0, 0));
  const quat parent_bind = rotation_of(bind[static_cast<std::size_t>(skeleton.parents[e])]);
  const quat local = glm::inverse(parent_bind) * look * rotation_of(bind[e]);
  vec3 angles = joint_angles(skeleton, eye, local);
  const JointDofs& dofs = skeleton.dofs[e];
  for (int a = 0; a < 3; ++a)
    angles[a] = dofs.free(a) ? std::clamp(angles[a], dofs.min_angle[a], dofs.max_angle[a]) * weight : 0.0f;
  return joint_rotation(skeleton, eye, angles);
}

void write_gaze(const Skeleton& skeleton, std::span<const float> times, const GazeAt& gaze, Clip& clip,
                std::span<const int> reads) {
  const std::array<int, 2> eyes{required_joint(skeleton, "l_eyeball_joint"), required_joint(skeleton, "r_eyeball_joint")};
  std::array<int, 2> head{skeleton.find("vc4"), skeleton.find("skullbase")};  // required once the head joins
  const std::array<float, 2> head_share{kNeckShare, 1.0f - kNeckShare};
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  if (clip.joint_count() != skeleton.size())
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.joint_count()) +
                " joints, the skeleton has " + std::to_string(skeleton.size()));
  for (int j : reads)
    if (j < 0 || static_cast<std::size_t>(j) >= skeleton.size()) throw Error("eye gaze reads joint " + std::to_string(j) + ", which the skeleton lacks");

  // The body without the eyes' old keys: they must not steer their own aim.
  for (int e : eyes) clip.rotations[static_cast<std::size_t>(e)] = {};

  // The pose is computed for the joints the aim needs: the eyes, the head and what `gaze` reads,
  // with their ancestors (a fifth of the body for the hands' gaze of a sentence); all of them
  // when `reads` is empty. They form a skeleton of their own, in the same order, whose clip borrows
  // the body clip's tracks (moved, given back below), so sampling and local_to_model run as they
  // would on the whole body and give the same numbers.
  const std::size_t n = skeleton.size();
  std::vector<char> needed(n, reads.empty() ? 1 : 0);
  for (int j : eyes) needed[static_cast<std::size_t>(j)] = 1;
  for (int j : head)
    if (j >= 0) needed[static_cast<std::size_t>(j)] = 1;
  for (int j : reads) needed[static_cast<std::size_t>(j)] = 1;
  for (std::size_t j = n; j-- > 0;)
    if (needed[j] && skeleton.parents[j] >= 0) needed[static_cast<std::size_t>(skeleton.parents[j])] = 1;
  std::vector<int> part;                // part joint → body joint
  std::vector<int> index(n, -1);        // body joint → part joint
  Skeleton sub;
  for (std::size_t j = 0; j < n; ++j) {
    if (!needed[j]) continue;
    index[j] = static_cast<int>(part.size());
    part.push_back(static_cast<int>(j));
    const int parent = skeleton.parents[j];
    sub.parents.push_back(static_cast<std::int16_t>(parent < 0 ? -1 : index[static_cast<std::size_t>(parent)]));
    sub.rest_translations.push_back(skeleton.rest_translations[j]);
    sub.rest_rotations.push_back(skeleton.rest_rotations[j]);
    sub.rest_scales.push_back(skeleton.rest_scales[j]);
    sub.dofs.push_back(skeleton.dofs[j]);
  }
  sub.names.resize(part.size());
  const auto in_part = [&](int j) { return j < 0 ? -1 : index[static_cast<std::size_t>(j)]; };
  const std::array<int, 2> part_eyes{in_part(eyes[0]), in_part(eyes[1])};

  Clip body;
  body.duration = clip.duration;
  body.resize_joints(part.size());
  // Lends the part's tracks to `body` and takes them back, also when `gaze` throws.
  struct Borrowed {
    Clip& clip;
    Clip& body;
    const std::vector<int>& part;
    bool lent = false;
    void swap() {
      for (std::size_t k = 0; k < part.size(); ++k) {
        const auto j = static_cast<std::size_t>(part[k]);
        std::swap(body.rotations[k], clip.rotations[j]);
        std::swap(body.translations[k], clip.translations[j]);
        std::swap(body.scales[k], clip.scales[j]);
      }
      lent = !lent;
    }
    ~Borrowed() {
      if (lent) swap();
    }
  } borrowed{clip, body, part};
  borrowed.swap();

  const Pose rest = rest_pose(sub);
  std::vector<mat4> bind(part.size()), model(part.size()), seen(reads.empty() ? 0 : n);
  local_to_model(sub, rest, bind);

  std::array<QuatTrack, 4> tracks;  // eyes, then vc4 and skullbase
  bool head_joins = false;
  Pose pose;
  Sampler sampler(body);
  for (float t : times) {
    if (!tracks[0].empty() && t <= tracks[0].times.back()) continue;
    sampler.sample(t, WrapMode::Clamp, rest, pose);
    local_to_model(sub, pose, model);
    if (!reads.empty())
      for (std::size_t k = 0; k < part.size(); ++k) seen[static_cast<std::size_t>(part[k])] = model[k];
    const GazeTarget target = gaze(t, reads.empty() ? std::span<const mat4>(model) : std::span<const mat4>(seen));
    const float eye_weight = std::clamp(target.eyes, 0.0f, 1.0f), head_weight = std::clamp(target.head, 0.0f, 1.0f);
    if (head_weight > 0.0f) {
      if (!head_joins) head = {required_joint(skeleton, "vc4"), required_joint(skeleton, "skullbase")};
      head_joins = true;
      const vec3 between_eyes = 0.5f * (position_of(model, part_eyes[0]) + position_of(model, part_eyes[1]));
      const vec3 d = glm::inverse(parent_turn(sub, part_eyes[0], model, bind)) * (target.point - between_eyes);
      const vec2 turn = head_weight * beyond_eyes(gaze_angles(d));
      for (std::size_t i = 0; i < 2; ++i) turn_joint(sub, in_part(head[i]), vec3(turn, 0.0f) * head_share[i], pose);
      local_to_model(sub, pose, model);
    }
    for (std::size_t i = 0; i < 2; ++i)
      tracks[i].add(t, eye_weight > 0.0f ? eye_rotation(sub, part_eyes[i], model, bind, target.point, eye_weight)
                                         : skeleton.rest_rotations[static_cast<std::size_t>(eyes[i])]);
    for (std::size_t i = 0; i < 2; ++i)
      if (head[i] >= 0) tracks[2 + i].add(t, pose.rotations[static_cast<std::size_t>(in_part(head[i]))]);
  }
  borrowed.swap();  // given back
  const std::array<int, 4> joints{eyes[0], eyes[1], head[0], head[1]};
  for (std::size_t i = 0; i < (head_joins ? 4u : 2u); ++i) {
    tracks[i].interpolation = Interpolation::Slerp;
    make_continuous(tracks[i]);
    clip.rotations[static_cast<std::size_t>(joints[i])] = std::move(tracks[i]);
  }
}

}  // namespace gestura::face
