// The eye-aiming core (face/eye_aim.hpp) on the avatar skeleton: angles in the head frame, the
// eyes' limits, the head's share beyond the eyes' own range.
#include "gestura/face/eye_aim.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"

using namespace gestura;
using namespace gestura::face;

namespace {

const Skeleton& skeleton() {
  static const Skeleton s = build_avatar_skeleton();
  return s;
}

std::vector<mat4> model_of(const Pose& pose) {
  std::vector<mat4> model(skeleton().size());
  local_to_model(skeleton(), pose, model);
  return model;
}

std::size_t index(const char* name) { return static_cast<std::size_t>(skeleton().find(name)); }

float degrees_between(vec3 a, vec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// Where the eye looks once its local rotation is `local`: the bind pose's +Z carried along.
vec3 sight(const char* eye, Pose pose, quat local) {
  const std::vector<mat4> bind = model_of(rest_pose(skeleton()));
  pose.rotations[index(eye)] = local;
  const std::vector<mat4> m = model_of(pose);
  return glm::quat_cast(mat3(m[index(eye)])) * (glm::inverse(glm::quat_cast(mat3(bind[index(eye)]))) * vec3(0, 0, 1));
}

TEST(EyeGazeAim, AnglesArePitchDownAndYawToTheLeft) {
  EXPECT_NEAR(gaze_angles(vec3(0, -1, 1)).x, deg(45.0f), 1e-5f);
  EXPECT_NEAR(gaze_angles(vec3(0, -1, 1)).y, 0.0f, 1e-5f);
  EXPECT_NEAR(gaze_angles(vec3(2, 0, 2)).y, deg(45.0f), 1e-5f);  // +X is the avatar's left
  EXPECT_NEAR(gaze_angles(vec3(-1, 0, 0)).y, deg(-90.0f), 1e-5f);
  const vec2 head = beyond_eyes(vec2(deg(30.0f), deg(-10.0f)));
  EXPECT_NEAR(head.x, deg(30.0f - kEyeOnlyDegrees), 1e-5f);
  EXPECT_EQ(head.y, 0.0f);
  EXPECT_NEAR(beyond_eyes(vec2(0.0f, deg(-50.0f))).y, deg(-50.0f + kEyeOnlyDegrees), 1e-5f);
}

TEST(EyeGazeAim, EachEyeLooksAtAReachableTargetEvenWithTheHeadTurned) {
  const Pose rest = rest_pose(skeleton());
  const std::vector<mat4> bind = model_of(rest);
  Pose turned = rest;
  turned.rotations[index("skullbase")] = joint_rotation(skeleton(), skeleton().find("skullbase"), vec3(deg(10), deg(25), 0));
  // The target is 17° to the left in the model: 8° to the right of the turned head.
  for (const Pose& pose : {rest, turned}) {
    const std::vector<mat4> m = model_of(pose);
    const vec3 target = vec3(m[index("skullbase")][3]) + vec3(0.25f, -0.1f, 0.8f);
    for (const char* eye : {"l_eyeball_joint", "r_eyeball_joint"}) {
      const quat q = eye_rotation(skeleton(), skeleton().find(eye), m, bind, target, 1.0f);
      EXPECT_LT(degrees_between(sight(eye, pose, q), target - vec3(m[index(eye)][3])), 0.5f) << eye;
    }
  }
  // Half the weight, half the turn.
  const std::vector<mat4> m = model_of(rest);
  const int eye = skeleton().find("l_eyeball_joint");
  const vec3 target = vec3(m[index("l_eyeball_joint")][3]) + vec3(0.3f, 0.0f, 1.0f);
  const float full = joint_angles(skeleton(), eye, eye_rotation(skeleton(), eye, m, bind, target, 1.0f)).y;
  EXPECT_NEAR(full, std::atan2(0.3f, 1.0f), 1e-3f);
  EXPECT_NEAR(joint_angles(skeleton(), eye, eye_rotation(skeleton(), eye, m, bind, target, 0.5f)).y, 0.5f * full, 1e-3f);
}

TEST(EyeGazeAim, EyesStopAtTheirLimitsAndNeverRoll) {
  const Pose rest = rest_pose(skeleton());
  const std::vector<mat4> m = model_of(rest);
  for (const char* name : {"l_eyeball_joint", "r_eyeball_joint"}) {
    const int eye = skeleton().find(name);
    const JointDofs& dofs = skeleton().dofs[index(name)];
    // Far to the left and far down: both axes at their limits, no roll.
    const vec3 a = joint_angles(skeleton(), eye,
                                eye_rotation(skeleton(), eye, m, m, vec3(m[index(name)][3]) + vec3(3.0f, -3.0f, 0.5f), 1.0f));
    EXPECT_NEAR(a.y, dofs.max_angle[1], 1e-4f) << name;  // + yaw: to the avatar's left
    EXPECT_NEAR(a.x, dofs.max_angle[0], 1e-4f) << name;  // + pitch: down
    EXPECT_NEAR(a.z, 0.0f, 1e-5f);
  }
}

TEST(EyeGazeAim, TheHeadTakesOnlyWhatIsBeyondTheEyes) {
  // A point 50° below straight ahead of the eyes: the head pitches ~30°, the eyes the last ~20°.
  const std::vector<mat4> bind = model_of(rest_pose(skeleton()));
  const vec3 between = 0.5f * (vec3(bind[index("l_eyeball_joint")][3]) + vec3(bind[index("r_eyeball_joint")][3]));
  const vec3 target = between + 0.6f * vec3(0.0f, -std::sin(deg(50)), std::cos(deg(50)));
  const std::vector<float> times{0.0f, 0.5f, 1.0f};
  auto aimed = [&](float head) {
    Clip clip;
    write_gaze(skeleton(), times, [&](float, std::span<const mat4>) { return GazeTarget{target, 1.0f, head}; }, clip);
    return clip;
  };
  auto angles = [&](const Clip& clip, const char* name) {
    const QuatTrack& tr = clip.rotations[index(name)];
    return tr.empty() ? vec3(0.0f) : joint_angles(skeleton(), skeleton().find(name), sample_track(tr, 0.5f));
  };
  const Clip with_head = aimed(1.0f);
  EXPECT_NEAR(glm::degrees(angles(with_head, "vc4").x + angles(with_head, "skullbase").x), 50.0f - kEyeOnlyDegrees, 1.0f);
  EXPECT_NEAR(glm::degrees(angles(with_head, "l_eyeball_joint").x), kEyeOnlyDegrees, 3.0f);
  // Eyes only: the head's tracks are left alone, the eyes stop at their limit.
  const Clip eyes_only = aimed(0.0f);
  EXPECT_TRUE(eyes_only.rotations[index("vc4")].empty());
  EXPECT_TRUE(eyes_only.rotations[index("skullbase")].empty());
  EXPECT_NEAR(angles(eyes_only, "l_eyeball_joint").x, skeleton().dofs[index("l_eyeball_joint")].max_angle[0], 1e-4f);
}

TEST(EyeGazeAim, ReadingOnlySomeJointsGivesTheSameAimAndKeepsTheBody) {
  // The body moves (spine, neck, right arm keyed over a second); the eyes follow the right wrist
  // and the head joins half the time. Told that gaze reads only the wrist, write_gaze computes a
  // part of the body each frame: the result must be the same, bit for bit, and the body's tracks
  // must come back untouched.
  Clip body;
  body.resize_joints(skeleton().size());
  const char* moving[] = {"vl3", "vt6", "vc4", "skullbase", "r_shoulder", "r_elbow", "r_wrist", "l_shoulder"};
  for (int k = 0; k < 8; ++k) {
    QuatTrack& track = body.rotations[index(moving[k])];
    for (int f = 0; f <= 10; ++f) {
      const float a = 0.3f * std::sin(0.7f * static_cast<float>(f) + static_cast<float>(k));
      track.add(0.1f * static_cast<float>(f), skeleton().rest_rotations[index(moving[k])] * glm::angleAxis(a, glm::normalize(vec3(1.0f, 0.5f * k, 0.3f))));
    }
  }
  body.translations[0].add(0.0f, vec3(0.0f, 1.0f, 0.0f));
  body.translations[0].add(1.0f, vec3(0.1f, 1.0f, 0.05f));
  body.duration = 1.0f;
  std::vector<float> times;
  for (int f = 0; f <= 30; ++f) times.push_back(static_cast<float>(f) / 30.0f);
  const std::size_t wrist = index("r_wrist");
  auto gaze = [&](float t, std::span<const mat4> model) {
    return GazeTarget{vec3(model[wrist][3]), 1.0f, t > 0.5f ? 0.8f : 0.0f};
  };
  Clip all = body, part = body;
  write_gaze(skeleton(), times, gaze, all);
  write_gaze(skeleton(), times, gaze, part, std::vector<int>{static_cast<int>(wrist)});
  for (const char* name : {"l_eyeball_joint", "r_eyeball_joint", "vc4", "skullbase"}) {
    const QuatTrack& a = all.rotations[index(name)];
    const QuatTrack& b = part.rotations[index(name)];
    ASSERT_EQ(a.times, b.times) << name;
    ASSERT_EQ(a.values.size(), b.values.size()) << name;
    for (std::size_t i = 0; i < a.values.size(); ++i) EXPECT_EQ(a.values[i], b.values[i]) << name << " key " << i;
  }
  EXPECT_EQ(part.rotations[index("vc4")].size(), times.size());  // the head joined
  for (std::size_t j = 0; j < skeleton().size(); ++j) {
    if (j == index("l_eyeball_joint") || j == index("r_eyeball_joint") || j == index("vc4") || j == index("skullbase")) continue;
    EXPECT_EQ(part.rotations[j].values, body.rotations[j].values) << skeleton().names[j];
    EXPECT_EQ(part.translations[j].values, body.translations[j].values) << skeleton().names[j];
  }
  EXPECT_THROW(write_gaze(skeleton(), times, gaze, part, std::vector<int>{9999}), Error);
}

TEST(EyeGazeAim, BadInputIsRefused) {
  Skeleton bare;
  bare.add_joint("humanoid_root", -1, vec3(0.0f));
  const std::vector<float> times{0.0f};
  auto ahead = [](float, std::span<const mat4>) { return GazeTarget{vec3(0, 1.6f, 1), 1.0f, 0.0f}; };
  Clip clip;
  EXPECT_THROW(write_gaze(bare, times, ahead, clip), Error);
  clip.resize_joints(3);
  EXPECT_THROW(write_gaze(skeleton(), times, ahead, clip), Error);
}

}  // namespace
