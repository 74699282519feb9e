// Retargeting the MakeHuman pose files (their own rest pose, decimetres, Z-up) onto the default
// avatar (A-pose, metres): bone directions agree, the sitting pose sits, end effectors follow when
// asked, and a clip played on its own skeleton comes out unchanged.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <tuple>

#include "gestura/anim/retarget.hpp"
#include "gestura/anim/sampler.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/skeleton/joint_names.hpp"
#include "support/cli.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura;

using gestura::test::shared_data;

BvhFile load_pose(const std::string& name) {
  return load_bvh(shared_data() + "/makehuman/poses/" + name + ".bvh", {0.1f, true});
}

std::vector<vec3> positions_at(const Skeleton& s, const Clip& clip, float time) {
  Pose pose;
  sample_clip(clip, time, WrapMode::Clamp, rest_pose(s), pose);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  std::vector<vec3> out(s.size());
  model_positions(model, out);
  return out;
}

vec3 bone(const Skeleton& s, const std::vector<vec3>& p, const char* from, const char* to) {
  const int a = s.find(from), b = s.find(to);
  EXPECT_GE(a, 0) << from;
  EXPECT_GE(b, 0) << to;
  if (a < 0 || b < 0) return vec3(0.0f);
  return glm::normalize(p[static_cast<std::size_t>(b)] - p[static_cast<std::size_t>(a)]);
}

float angle_deg(const vec3& a, const vec3& b) { return to_degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f))); }

struct BonePair {
  const char *src_from, *src_to, *tgt_from, *tgt_to;
};

constexpr BonePair kBones[] = {
    {"upperarm01.L", "lowerarm01.L", "l_shoulder", "l_elbow"}, {"upperarm01.R", "lowerarm01.R", "r_shoulder", "r_elbow"},
    {"lowerarm01.L", "wrist.L", "l_elbow", "l_wrist"},         {"lowerarm01.R", "wrist.R", "r_elbow", "r_wrist"},
    {"upperleg01.L", "lowerleg01.L", "l_hip", "l_knee"},       {"upperleg01.R", "lowerleg01.R", "r_hip", "r_knee"},
    {"lowerleg01.L", "foot.L", "l_knee", "l_ankle"},           {"lowerleg01.R", "foot.R", "r_knee", "r_ankle"},
};

TEST(Retarget, MakeHumanPosesKeepBoneDirectionsOnTheAvatar) {
  const Skeleton avatar = build_avatar_skeleton();
  float worst = 0.0f;
  for (const char* name : {"sit01", "standing01", "standing02", "run01", "benchmark", "tpose"}) {
    const BvhFile src = load_pose(name);
    const Clip out = retarget(src.skeleton, src.clip, avatar);
    validate(out, avatar);
    const auto sp = positions_at(src.skeleton, src.clip, 0.0f);
    const auto tp = positions_at(avatar, out, 0.0f);
    for (const BonePair& b : kBones) {
      const float a = angle_deg(bone(src.skeleton, sp, b.src_from, b.src_to), bone(avatar, tp, b.tgt_from, b.tgt_to));
      EXPECT_LT(a, 3.0f) << name << " " << b.tgt_from;
      worst = std::max(worst, a);
    }
  }
  RecordProperty("worst_bone_angle_deg", std::to_string(worst));
}

TEST(Retarget, SittingPoseSitsOnTheAvatar) {
  // sit01 sits on the floor: right leg stretched forward, left knee drawn up (read off the file by
  // hand-written FK: right thigh and shin ~(−0.1, 0, 0.99), left thigh ~(0.29, 0.69, 0.67)).
  const Skeleton avatar = build_avatar_skeleton();
  const BvhFile src = load_pose("sit01");
  const auto tp = positions_at(avatar, retarget(src.skeleton, src.clip, avatar), 0.0f);
  for (const char* side : {"l_", "r_"}) {
    const vec3 thigh = bone(avatar, tp, (std::string(side) + "hip").c_str(), (std::string(side) + "knee").c_str());
    EXPECT_GT(thigh.z, 0.6f) << side << " thigh points forward";
  }
  EXPECT_GT(bone(avatar, tp, "r_knee", "r_ankle").z, 0.95f) << "right shin stretched forward";
  EXPECT_GT(bone(avatar, tp, "l_hip", "l_knee").y, 0.6f) << "left knee drawn up";
  // At rest the thighs hang down: the pose, not the rest, made them point forward.
  const auto rp = rest_joint_positions(avatar);
  EXPECT_LT(bone(avatar, rp, "l_hip", "l_knee").y, -0.9f);
}

TEST(Retarget, EndEffectorsFollowTheSourceScaledToTheBody) {
  const Skeleton avatar = build_avatar_skeleton();
  const auto rest = rest_joint_positions(avatar);
  auto length = [&](const char* a, const char* b) {
    return glm::length(rest[static_cast<std::size_t>(avatar.find(b))] - rest[static_cast<std::size_t>(avatar.find(a))]);
  };
  const float avatar_leg = length("l_hip", "l_knee") + length("l_knee", "l_ankle");
  const float avatar_arm = length("l_shoulder", "l_elbow") + length("l_elbow", "l_wrist");
  int checked = 0;
  for (const char* name : {"sit01", "standing01", "standing02", "run01"}) {
    const BvhFile src = load_pose(name);
    const auto srest = rest_joint_positions(src.skeleton);
    auto slength = [&](const char* a, const char* b) {
      return glm::length(srest[static_cast<std::size_t>(src.skeleton.find(b))] -
                         srest[static_cast<std::size_t>(src.skeleton.find(a))]);
    };
    const float k = avatar_leg / (slength("upperleg01.L", "lowerleg01.L") + slength("lowerleg01.L", "foot.L"));
    RetargetOptions options;
    options.preserve_end_effectors = true;
    const Clip out = retarget(src.skeleton, src.clip, avatar, options);
    const auto sp = positions_at(src.skeleton, src.clip, 0.0f);
    const auto tp = positions_at(avatar, out, 0.0f);
    const vec3 src_root = sp[static_cast<std::size_t>(src.skeleton.find("root"))];
    const vec3 tgt_root = tp[static_cast<std::size_t>(avatar.find("humanoid_root"))];
    for (const auto& [s, t, shoulder] : {std::tuple{"wrist.L", "l_wrist", "l_shoulder"}, std::tuple{"wrist.R", "r_wrist", "r_shoulder"},
                                        std::tuple{"foot.L", "l_ankle", "l_hip"}, std::tuple{"foot.R", "r_ankle", "r_hip"}}) {
      const vec3 goal = tgt_root + k * (sp[static_cast<std::size_t>(src.skeleton.find(s))] - src_root);
      const float reach = std::string(t).ends_with("wrist") ? avatar_arm : avatar_leg;
      if (glm::length(goal - tp[static_cast<std::size_t>(avatar.find(shoulder))]) > reach * 0.99f) continue;
      EXPECT_LT(glm::length(tp[static_cast<std::size_t>(avatar.find(t))] - goal), 0.001f) << name << " " << t;
      ++checked;
    }
  }
  EXPECT_GE(checked, 8) << "most end effectors are within reach";
}

// A moving clip: a MakeHuman pose blended in from rest over one second, root moving.
Clip blend_in(const BvhFile& src) {
  Clip clip = src.clip;
  const Pose rest = rest_pose(src.skeleton);
  for (std::size_t j = 0; j < clip.joint_count(); ++j) {
    QuatTrack& r = clip.rotations[j];
    if (r.empty()) continue;
    const quat end = r.values[0];
    r.times = {0.0f, 1.0f};
    r.values = {rest.rotations[j], end};
  }
  clip.translations[0].times = {0.0f, 1.0f};
  clip.translations[0].values = {rest.translations[0], rest.translations[0] + vec3(0.3f, -0.2f, 0.5f)};
  clip.duration = 1.0f;
  return clip;
}

TEST(Retarget, ClipOnItsOwnSkeletonIsUnchanged) {
  const BvhFile src = load_pose("sit01");
  const Clip clip = blend_in(src);
  const Clip out = retarget(src.skeleton, clip, src.skeleton, {0.1f, false, {}});
  float worst = 0.0f;
  for (float t : {0.0f, 0.3f, 0.5f, 1.0f}) {
    const auto a = positions_at(src.skeleton, clip, t), b = positions_at(src.skeleton, out, t);
    for (std::size_t j = 0; j < a.size(); ++j) worst = std::max(worst, glm::length(a[j] - b[j]));
  }
  // Keys every 0.1 s sample the source exactly at 0, 0.3, 0.5, 1.0 (nlerp vs slerp between keys aside).
  EXPECT_LT(worst, 1e-3f);
  RecordProperty("self_retarget_worst_m", std::to_string(worst));
}

TEST(Retarget, EndEffectorPathsFollowOverTime) {
  // Wrists and ankles along a moving clip: at every output key the avatar's end effector sits
  // where the source's is relative to the root, scaled by the leg-length ratio.
  const Skeleton avatar = build_avatar_skeleton();
  const BvhFile src = load_pose("standing02");
  const Clip clip = blend_in(src);
  RetargetOptions options;
  options.preserve_end_effectors = true;
  options.frame_time = 0.05f;
  const Clip out = retarget(src.skeleton, clip, avatar, options);
  const float k = retarget_scale(src.skeleton, avatar, match_joints(src.skeleton, avatar));
  float worst = 0.0f;
  for (int f = 0; f <= 20; ++f) {
    const float t = 0.05f * float(f);
    const auto sp = positions_at(src.skeleton, clip, t), tp = positions_at(avatar, out, t);
    const vec3 src_root = sp[static_cast<std::size_t>(src.skeleton.find("root"))];
    const vec3 tgt_root = tp[static_cast<std::size_t>(avatar.find("humanoid_root"))];
    for (const auto& [s, tj] : {std::pair{"wrist.L", "l_wrist"}, std::pair{"wrist.R", "r_wrist"},
                                std::pair{"foot.L", "l_ankle"}, std::pair{"foot.R", "r_ankle"}}) {
      const vec3 goal = tgt_root + k * (sp[static_cast<std::size_t>(src.skeleton.find(s))] - src_root);
      worst = std::max(worst, glm::length(tp[static_cast<std::size_t>(avatar.find(tj))] - goal));
    }
  }
  EXPECT_LT(worst, 0.002f);
  RecordProperty("end_effector_path_worst_m", std::to_string(worst));
}

TEST(Retarget, NonIdentityRestRotationsGiveTheSameMotion) {
  // The avatar re-expressed with arbitrary joint frames (same rest positions, rest rotations far
  // from identity) must receive the same model-space motion as the plain avatar.
  const Skeleton plain = build_avatar_skeleton();
  Skeleton turned = plain;
  std::vector<quat> frame(plain.size());
  for (std::size_t j = 0; j < plain.size(); ++j) {
    const float a = 0.7f * float(j % 5) + 0.3f;
    frame[j] = glm::angleAxis(a, glm::normalize(vec3(std::sin(float(j)), 1.0f, std::cos(float(j) * 0.7f))));
    const int p = plain.parents[j];
    const quat parent = p < 0 ? quat(1, 0, 0, 0) : frame[static_cast<std::size_t>(p)];
    turned.rest_rotations[j] = glm::inverse(parent) * frame[j];
    turned.rest_translations[j] = glm::inverse(parent) * plain.rest_translations[j];
  }
  const auto rest_a = rest_joint_positions(plain), rest_b = rest_joint_positions(turned);
  for (std::size_t j = 0; j < plain.size(); ++j) ASSERT_LT(glm::length(rest_a[j] - rest_b[j]), 1e-5f);
  float worst = 0.0f;
  for (const char* name : {"sit01", "run01"}) {
    const BvhFile src = load_pose(name);
    for (bool ends : {false, true}) {
      RetargetOptions options;
      options.preserve_end_effectors = ends;
      const auto a = positions_at(plain, retarget(src.skeleton, src.clip, plain, options), 0.0f);
      const auto b = positions_at(turned, retarget(src.skeleton, src.clip, turned, options), 0.0f);
      for (std::size_t j = 0; j < a.size(); ++j) worst = std::max(worst, glm::length(a[j] - b[j]));
    }
  }
  EXPECT_LT(worst, 1e-4f);
  RecordProperty("turned_frames_worst_m", std::to_string(worst));
}

TEST(Retarget, BadMappingIsAnError) {
  const Skeleton avatar = build_avatar_skeleton();
  const BvhFile src = load_pose("sit01");
  RetargetOptions options;
  options.mapping = {1, 2, 3};
  EXPECT_THROW(retarget(src.skeleton, src.clip, avatar, options), Error);
  options.mapping.assign(avatar.size(), -1);
  options.mapping[5] = 100000;
  EXPECT_THROW(retarget(src.skeleton, src.clip, avatar, options), Error);
  options.mapping.assign(avatar.size(), -1);
  EXPECT_THROW(retarget(src.skeleton, src.clip, avatar, options), Error);  // nothing paired
  Skeleton other;
  other.add_joint("tail", -1, vec3(0.0f));
  EXPECT_THROW(retarget(src.skeleton, src.clip, other), Error);
}

using gestura::test::CliRun;
using gestura::test::run_cli;

TEST(RetargetCli, WritesTheAvatarSkeletonWithThePose) {
  const std::string out =
      (std::filesystem::temp_directory_path() / ("gestura_retarget_" + std::to_string(getpid()) + ".bvh")).string();
  const std::string in = shared_data() + "/makehuman/poses/sit01.bvh";
  const CliRun run = run_cli("retarget '" + in + "' -o '" + out + "' --scale 0.1 --z-up --end-effectors");
  ASSERT_EQ(run.status, 0) << run.output;
  const BvhFile written = load_bvh(out);
  std::filesystem::remove(out);
  const Skeleton avatar = build_avatar_skeleton();
  for (std::size_t j = 0; j < avatar.size(); ++j) EXPECT_GE(written.skeleton.find(avatar.names[j]), 0) << avatar.names[j];
  const auto p = positions_at(written.skeleton, written.clip, 0.0f);
  EXPECT_GT(bone(written.skeleton, p, "r_hip", "r_knee").z, 0.6f);

  const std::string glb = out + ".glb";
  const CliRun to_gltf = run_cli("retarget '" + in + "' -o '" + glb + "' --scale 0.1 --z-up");
  ASSERT_EQ(to_gltf.status, 0) << to_gltf.output;
  const GltfAnimation gltf = load_gltf_animation(glb);
  std::filesystem::remove(glb);
  EXPECT_EQ(gltf.skeleton.names, avatar.names);
  const auto gp = positions_at(gltf.skeleton, gltf.clip, 0.0f);
  EXPECT_GT(bone(gltf.skeleton, gp, "r_hip", "r_knee").z, 0.6f);

  EXPECT_EQ(run_cli("retarget '" + in + "' -o '" + out + ".fbx'").status, 2);
  EXPECT_EQ(run_cli("retarget '" + in + "' -o '" + out + "' --scale nope").status, 2);
  EXPECT_EQ(run_cli("retarget '" + in + "'").status, 2);
  EXPECT_EQ(run_cli("retarget /nonexistent.bvh -o '" + out + "'").status, 1);
}

}  // namespace
