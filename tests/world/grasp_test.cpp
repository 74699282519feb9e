// Reaching and grasping: the grasp follows the object's size and shape, the pseudo-inverse Jacobian
// brings the palm within 1 cm of its target with the hand turned as the grasp asks, and the closing
// fingers touch the object's surface without entering it (measured on the skinned fingers against
// the object's exact shape).
#include <gtest/gtest.h>

#include "support/signing_avatar.hpp"

#include "gestura/world/grasp.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/scene_json.hpp"

namespace {

using namespace gestura;

struct Table {
  Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0]},
      {"name": "counter", "shape": "box", "size": [1.2, 0.05, 0.5], "position": [0, 0.925, 0.55]},
      {"name": "bottle", "shape": "cylinder", "radius": 0.035, "height": 0.26, "position": [-0.16, 1.08, 0.36]},
      {"name": "ball", "shape": "sphere", "radius": 0.055, "position": [0.2, 1.005, 0.36]},
      {"name": "marble", "shape": "sphere", "radius": 0.015, "position": [-0.02, 0.965, 0.34]},
      {"name": "rail", "shape": "cylinder", "radius": 0.016, "height": 0.8, "position": [0, 1.15, 0.42], "rotation": [0, 0, 90]},
      {"name": "board", "shape": "box", "size": [0.6, 0.5, 0.03], "position": [0.3, 1.3, 0.5]}
    ]})", "table.json");
  SceneGeometry geometry = build_scene_geometry(scene);
  Environment env = build_environment(geometry);
};

// The avatar standing at the origin facing +Z (its bind pose is in world place already).
Pose standing() { return rest_pose(test::signing_avatar().avatar.skeleton); }

struct Checked {
  GraspPlan grasp;
  ReachResult reach;
  FingerClosure closure;
  std::array<float, 5> distances{};
};

Checked grasp_object(const Table& t, const char* name, Hand hand) {
  const SigningRig& rig = test::signing_avatar().rig;
  Pose pose = standing();
  std::vector<mat4> model(rig.skeleton().size());
  local_to_model(rig.skeleton(), pose, model);
  const vec3 shoulder = vec3(model[static_cast<std::size_t>(rig.hand(hand).shoulder)][3]);
  const auto grasp = choose_object_grasp(t.env, t.geometry.find_object(name), shoulder, hand, rig);
  EXPECT_TRUE(grasp) << name;
  Checked out;
  out.grasp = *grasp;
  const GraspResult r = perform_grasp(rig, out.grasp, pose);
  out.reach = r.reach;
  out.closure = r.closure;
  out.distances = r.distances;
  // The palm centre where the solver says.
  local_to_model(rig.skeleton(), pose, model);
  const HandRig& h = rig.hand(hand);
  const vec3 palm = vec3(model[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
  EXPECT_NEAR(glm::length(palm - out.grasp.palm_centre), out.reach.position_error, 1e-4f);
  std::printf("%s: %s grasp of a %.1f cm part, palm %.2f mm off, hand turned %.1f° off, fingers", name, grasp_name(grasp->type),
              grasp->size * 100.0f, out.reach.position_error * 1000.0f, to_degrees(out.reach.orientation_error));
  for (int f = 0; f < 5; ++f) std::printf(" %.1f", out.distances[static_cast<std::size_t>(f)] * 1000.0f);
  std::printf(" mm from the surface\n");
  return out;
}

void expect_touching(const Checked& c, std::initializer_list<int> fingers, const char* name) {
  for (int f : fingers) {
    EXPECT_TRUE(c.closure.touching[static_cast<std::size_t>(f)]) << name << " finger " << f;
    EXPECT_LE(c.distances[static_cast<std::size_t>(f)], 0.003f) << name << " finger " << f << " does not touch";
  }
  for (int f = 0; f < 5; ++f) EXPECT_GE(c.distances[static_cast<std::size_t>(f)], -0.002f) << name << " finger " << f << " enters";
}

TEST(Grasp, PowerGraspRoundABottle) {
  const Table t;
  const Checked c = grasp_object(t, "bottle", Hand::Right);
  EXPECT_EQ(c.grasp.type, GraspType::Power);
  EXPECT_TRUE(c.reach.reached);
  EXPECT_LT(c.reach.position_error, 0.01f);
  EXPECT_LT(c.reach.orientation_error, deg(15.0f));
  expect_touching(c, {0, 1, 2, 3}, "bottle");
}

TEST(Grasp, PowerGraspRoundALyingRail) {
  const Table t;
  const Checked c = grasp_object(t, "rail", Hand::Left);
  EXPECT_EQ(c.grasp.type, GraspType::Power);
  EXPECT_LT(c.reach.position_error, 0.01f);
  expect_touching(c, {1, 2, 3}, "rail");
}

TEST(Grasp, SphericalGraspOfABallAndPrecisionGraspOfAMarble) {
  const Table t;
  const Checked ball = grasp_object(t, "ball", Hand::Right);
  EXPECT_EQ(ball.grasp.type, GraspType::Spherical);
  EXPECT_LT(ball.reach.position_error, 0.01f);
  expect_touching(ball, {1, 2}, "ball");
  const Checked marble = grasp_object(t, "marble", Hand::Right);
  EXPECT_EQ(marble.grasp.type, GraspType::Precision);
  EXPECT_LT(marble.reach.position_error, 0.01f);
  expect_touching(marble, {1}, "marble");
}

TEST(Grasp, FlatPalmOnABoard) {
  const Table t;
  const Checked c = grasp_object(t, "board", Hand::Right);
  EXPECT_EQ(c.grasp.type, GraspType::Flat);
  EXPECT_LT(c.reach.position_error, 0.01f);
  for (int f = 0; f < 5; ++f) EXPECT_GE(c.distances[static_cast<std::size_t>(f)], -0.002f);
}

}  // namespace
