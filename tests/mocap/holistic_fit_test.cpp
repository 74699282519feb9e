// Motion capture: a known pose of the avatar is "filmed" (its joints placed where MediaPipe
// Holistic would report them, for a person turned and scaled in the picture), and the fitted pose
// must put the elbows, wrists, hands and head back where the known pose had them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/mocap/holistic_fit.hpp"

namespace gestura {
namespace {

const Skeleton& avatar() {
  static const Skeleton s = build_avatar_skeleton();
  return s;
}

// A pose within the joints' limits: right arm forward and bent with the forearm turned, left arm
// out to the side and bent, the head turned left and tilted.
Pose known_pose() {
  const Skeleton& s = avatar();
  Pose pose = rest_pose(s);
  const auto set = [&](const char* name, vec3 degrees) {
    const int j = s.find(name);
    pose.rotations[joint_slot(j)] = joint_rotation(s, j, vec3(deg(degrees.x), deg(degrees.y), deg(degrees.z)));
  };
  set("r_shoulder", {-55, 10, -25});
  set("r_elbow", {-75, 35, 0});
  set("r_wrist", {-10, 0, 25});
  set("l_shoulder", {-25, 0, 45});
  set("l_elbow", {-95, -25, 0});
  set("l_wrist", {5, 0, -35});
  set("vc4", {4, 10, 3});
  set("skullbase", {-4, 14, 6});
  return pose;
}

struct Camera {
  float yaw = deg(20.0f);   // the person turned in front of the camera
  float scale = 0.28f;      // picture widths per metre
  vec3 offset{0.45f, -0.05f, 0.1f};
  float aspect = 16.0f / 9.0f;
  // model space (metres) → MediaPipe's picture coordinates
  vec3 image(const vec3& m) const {
    const vec3 c = glm::angleAxis(yaw, vec3(0, 1, 0)) * m * scale + offset;
    return vec3(c.x, -c.y * aspect, -c.z);
  }
};

// Where Holistic would put the body, hands and face of the skeleton in `pose`.
HolisticFrame film(const Pose& pose, const Camera& camera = {}) {
  const Skeleton& s = avatar();
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const auto at = [&](const char* name) { return vec3(model[joint_slot(s.find(name))][3]); };
  const auto rotation = [&](const char* name) { return glm::normalize(glm::quat_cast(mat3(model[joint_slot(s.find(name))]))); };
  HolisticFrame f;
  f.aspect = camera.aspect;
  f.pose.assign(kHolisticPosePoints, camera.image(at("vt1")));
  const vec3 skull = at("skullbase");
  const quat head = rotation("skullbase");
  f.pose[7] = camera.image(skull + head * vec3(0.075f, 0.03f, 0.0f));
  f.pose[8] = camera.image(skull + head * vec3(-0.075f, 0.03f, 0.0f));
  f.pose[11] = camera.image(at("l_shoulder"));
  f.pose[12] = camera.image(at("r_shoulder"));
  f.pose[13] = camera.image(at("l_elbow"));
  f.pose[14] = camera.image(at("r_elbow"));
  f.pose[15] = camera.image(at("l_wrist"));
  f.pose[16] = camera.image(at("r_wrist"));
  f.pose[23] = camera.image(at("l_hip"));
  f.pose[24] = camera.image(at("r_hip"));
  for (const char side : {'l', 'r'}) {
    const std::string p(1, side);
    std::vector<vec3>& hand = side == 'l' ? f.left_hand : f.right_hand;
    hand.assign(kHolisticHandPoints, camera.image(at((p + "_wrist").c_str())));
    hand[5] = camera.image(at((p + "_index1").c_str()));
    hand[9] = camera.image(at((p + "_middle1").c_str()));
    hand[17] = camera.image(at((p + "_pinky1").c_str()));
  }
  // The face: outer eye corners, the top of the forehead and the chin, carried by the skull.
  f.face.assign(kHolisticFacePoints, camera.image(skull));
  f.face[33] = camera.image(skull + head * vec3(-0.045f, 0.06f, 0.08f));
  f.face[263] = camera.image(skull + head * vec3(0.045f, 0.06f, 0.08f));
  f.face[10] = camera.image(skull + head * vec3(0.0f, 0.16f, 0.09f));
  f.face[152] = camera.image(skull + head * vec3(0.0f, -0.06f, 0.09f));
  return f;
}

struct Placed {
  std::vector<mat4> model;
  vec3 at(const char* name) const { return vec3(model[joint_slot(avatar().find(name))][3]); }
  quat rotation(const char* name) const { return glm::normalize(glm::quat_cast(mat3(model[joint_slot(avatar().find(name))]))); }
};
Placed place(const Pose& pose) {
  Placed p;
  p.model.resize(avatar().size());
  local_to_model(avatar(), pose, p.model);
  return p;
}
float angle_between(const quat& a, const quat& b) { return 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(a, b)))); }

TEST(HolisticFit, PutsArmsHandsAndHeadBackWhereTheFilmedPoseHadThem) {
  const HolisticFit fit(avatar());
  const Pose truth = known_pose();
  HolisticFitParts parts;
  const Pose fitted = fit.fit(film(truth), &parts);
  EXPECT_TRUE(parts.left_arm && parts.right_arm && parts.left_hand && parts.right_hand && parts.head);
  const Placed want = place(truth), got = place(fitted);
  const Placed rest = place(rest_pose(avatar()));
  for (const char* joint : {"l_elbow", "r_elbow", "l_wrist", "r_wrist", "r_middle1", "l_middle1"}) {
    EXPECT_LT(glm::length(got.at(joint) - want.at(joint)), 0.03f) << joint;
    EXPECT_GT(glm::length(want.at(joint) - rest.at(joint)), 0.10f) << joint << ": the known pose moves it";
  }
  for (const char* joint : {"l_wrist", "r_wrist"}) EXPECT_LT(angle_between(got.rotation(joint), want.rotation(joint)), deg(10.0f)) << joint;
  EXPECT_LT(angle_between(got.rotation("skullbase"), want.rotation("skullbase")), deg(5.0f));
  EXPECT_GT(angle_between(want.rotation("skullbase"), rest.rotation("skullbase")), deg(20.0f));
  // Only the joints it names move, and every one stays within its limits.
  const Pose rest_pose_ = rest_pose(avatar());
  for (std::size_t j = 0; j < avatar().size(); ++j) {
    EXPECT_TRUE(within_limits(avatar(), static_cast<int>(j), fitted.rotations[j])) << avatar().names[j];
    const bool driven = std::find(fit.driven_joints().begin(), fit.driven_joints().end(), static_cast<int>(j)) != fit.driven_joints().end();
    if (!driven) {
      EXPECT_LT(angle_between(fitted.rotations[j], rest_pose_.rotations[j]), 1e-4f) << avatar().names[j];
    }
  }
}

TEST(HolisticFit, WhereThePersonStandsAndHowTheCameraIsTurnedDoNotMatter) {
  const HolisticFit fit(avatar());
  const Pose truth = known_pose();
  Camera near, far;
  far.yaw = deg(-25.0f);
  far.scale = 0.12f;
  far.offset = vec3(0.7f, -0.2f, -0.3f);
  far.aspect = 4.0f / 3.0f;
  const Placed a = place(fit.fit(film(truth, near))), b = place(fit.fit(film(truth, far)));
  for (const char* joint : {"l_wrist", "r_wrist", "skullbase"}) EXPECT_LT(glm::length(a.at(joint) - b.at(joint)), 0.005f) << joint;
}

TEST(HolisticFit, WithoutHandsOrFaceTheArmsFollowTheBodyAndTheEarsTurnTheHead) {
  const HolisticFit fit(avatar());
  const Pose truth = known_pose();
  HolisticFrame f = film(truth);
  f.left_hand.clear();
  f.right_hand.clear();
  f.face.clear();
  HolisticFitParts parts;
  const Placed got = place(fit.fit(f, &parts)), want = place(truth);
  EXPECT_TRUE(parts.left_arm && parts.right_arm && parts.head);
  EXPECT_FALSE(parts.left_hand || parts.right_hand);
  EXPECT_LT(glm::length(got.at("r_wrist") - want.at("r_wrist")), 0.03f);
  // The ears give the turn and tilt (not the nod): the face's forward direction within 10°.
  const vec3 forward_got = got.rotation("skullbase") * vec3(0, 0, 1), forward_want = want.rotation("skullbase") * vec3(0, 0, 1);
  EXPECT_LT(std::acos(std::min(1.0f, glm::dot(forward_got, forward_want))), deg(10.0f));
}

TEST(HolisticFit, AnArmOutOfThePictureStaysAtRest) {
  const HolisticFit fit(avatar());
  HolisticFrame f = film(known_pose());
  f.pose_visibility.assign(kHolisticPosePoints, 0.95f);
  f.pose_visibility[13] = f.pose_visibility[15] = 0.1f;  // the left elbow and wrist unseen
  f.left_hand.clear();
  HolisticFitParts parts;
  const Placed got = place(fit.fit(f, &parts)), rest = place(rest_pose(avatar()));
  EXPECT_FALSE(parts.left_arm);
  EXPECT_TRUE(parts.right_arm);
  EXPECT_LT(glm::length(got.at("l_wrist") - rest.at("l_wrist")), 1e-4f);
  EXPECT_GT(glm::length(got.at("r_wrist") - rest.at("r_wrist")), 0.10f);
}

TEST(HolisticFit, MalformedFramesAreErrorsNamingThePoint) {
  const HolisticFit fit(avatar());
  const auto message = [&](HolisticFrame f) {
    try {
      fit.fit(f);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  HolisticFrame f = film(known_pose());
  HolisticFrame short_pose = f;
  short_pose.pose.pop_back();
  EXPECT_NE(message(short_pose).find("pose has 32 points"), std::string::npos) << message(short_pose);
  HolisticFrame nan_hand = f;
  nan_hand.right_hand[4].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(message(nan_hand).find("right_hand[4]"), std::string::npos) << message(nan_hand);
  HolisticFrame small_face = f;
  small_face.face.resize(100);
  EXPECT_NE(message(small_face).find("face has 100 points"), std::string::npos) << message(small_face);
  HolisticFrame one_spot = f;
  one_spot.pose[12] = one_spot.pose[11];
  EXPECT_NE(message(one_spot).find("shoulders"), std::string::npos) << message(one_spot);
  Skeleton no_neck = avatar();
  no_neck.names[joint_slot(no_neck.find("skullbase"))] = "head";
  try {
    HolisticFit bad(no_neck);
    FAIL() << "a skeleton without skullbase was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("skullbase"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gestura
