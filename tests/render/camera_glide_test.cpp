// The characters view glides between shots: where the framing rule jumps (a walker reaching the wall
// the camera stood by), the glided camera moves a bounded distance per frame, turns a bounded angle
// per frame, never overshoots, and settles on the shot once the shot holds.
#include <gtest/gtest.h>

#include <vector>

#include "gestura/render/camera_glide.hpp"
#include "gestura/render/scene_cameras.hpp"
#include "gestura/world/scene_json.hpp"

namespace gestura {
namespace {

CharacterView standing(const char* name, const vec3& at) {
  CharacterView v;
  v.name = name;
  v.position = at;
  v.head = at + vec3(0.0f, 1.6f, 0.0f);
  return v;
}

float turn_degrees(const Camera& a, const Camera& b) {
  const vec3 da = glm::normalize(a.target - a.eye), db = glm::normalize(b.target - b.eye);
  return to_degrees(std::acos(std::clamp(glm::dot(da, db), -1.0f, 1.0f)));
}

TEST(CameraGlide, TheCharactersViewGlidesWhereItsFramingCuts) {
  const Scene scene = parse_scene(R"({"characters": [{"name": "anna"}, {"name": "ben"}]})", "room.json");
  Aabb room;
  room.grow(vec3(-0.2f, 0.0f, -0.2f));
  room.grow(vec3(8.2f, 2.6f, 6.2f));
  const float fps = 30.0f, aspect = 16.0f / 9.0f;
  // ben walks from the middle into the south-east corner in 3 s, then stands there 3 s.
  CameraGlide glide;
  glide.keep_inside(room.min + vec3(0.35f), room.max - vec3(0.35f));
  std::vector<Camera> shots, glided;
  for (int i = 0; i <= 6 * 30; ++i) {
    const float s = std::min(1.0f, static_cast<float>(i) / (3.0f * fps));
    const std::vector<CharacterView> people{standing("anna", vec3(4.6f, 0, 3.4f)), standing("ben", glm::mix(vec3(3.0f, 0, 2.0f), vec3(7.6f, 0, 5.6f), s))};
    shots.push_back(scene_camera("characters", scene, room, people, aspect));
    glided.push_back(glide.follow(shots.back(), i == 0 ? 0.0f : 1.0f / fps));
  }
  float shot_jump = 0.0f, glide_jump = 0.0f, glide_turn = 0.0f, glide_accel = 0.0f;
  for (std::size_t i = 1; i < shots.size(); ++i) {
    shot_jump = std::max(shot_jump, glm::length(shots[i].eye - shots[i - 1].eye));
    glide_jump = std::max(glide_jump, glm::length(glided[i].eye - glided[i - 1].eye));
    glide_turn = std::max(glide_turn, turn_degrees(glided[i], glided[i - 1]));
    // Inside the room all the way round (a wall between the eye and the people would fill the picture).
    EXPECT_GT(glided[i].eye.x, room.min.x + 0.3f);
    EXPECT_LT(glided[i].eye.x, room.max.x - 0.3f);
    EXPECT_GT(glided[i].eye.z, room.min.z + 0.3f);
    EXPECT_LT(glided[i].eye.z, room.max.z - 0.3f);
    if (i > 1)
      glide_accel = std::max(glide_accel, glm::length((glided[i].eye - glided[i - 1].eye) - (glided[i - 1].eye - glided[i - 2].eye)));
  }
  // The framing rule itself cuts here (this is the case the glide is for)...
  EXPECT_GT(shot_jump, 1.0f) << "the shot never jumps: the scenario does not test the glide";
  // ...the glided camera moves at most 15 cm (4.5 m/s, a brisk dolly) and turns at most 5° in a frame,
  // a tenth of the cut, and its speed changes by at most 5 cm per frame from one frame to the next.
  EXPECT_LT(glide_jump, 0.15f) << "the shot jumps " << shot_jump << " m";
  EXPECT_LT(glide_jump, shot_jump * 0.1f);
  EXPECT_LT(glide_turn, 5.0f);
  EXPECT_LT(glide_accel, 0.05f);
  // Once the shot holds (ben standing), the glide settles on it.
  EXPECT_LT(glm::length(glided.back().eye - shots.back().eye), 0.01f);
  EXPECT_LT(glm::length(glided.back().target - shots.back().target), 0.01f);
  EXPECT_LT(turn_degrees(glided.back(), shots.back()), 0.2f);
}

TEST(CameraGlide, ACriticallyDampedStepNeverOvershootsAndTheFirstCallCuts) {
  Camera a;
  a.eye = vec3(0, 2, 5), a.target = vec3(0, 1, 0);
  a.view = glm::lookAt(a.eye, a.target, vec3(0, 1, 0));
  a.projection = glm::perspective(deg(40.0f), 1.5f, 0.05f, 50.0f);
  Camera b = a;
  b.target = vec3(3, 1, 0), b.eye = vec3(3, 2, 5);
  b.view = glm::lookAt(b.eye, b.target, vec3(0, 1, 0));
  CameraGlide glide(0.5f);
  EXPECT_EQ(a.eye, glide.follow(a, 0.1f).eye);  // the first call takes the shot
  float last = 0.0f;
  for (int i = 0; i < 120; ++i) {
    const float x = glide.follow(b, 1.0f / 30.0f).target.x;
    EXPECT_GE(x, last - 1e-5f);  // heads there without turning back
    EXPECT_LE(x, 3.0f + 1e-4f);  // and never past it
    last = x;
  }
  EXPECT_NEAR(3.0f, last, 0.01f);
  glide.reset();
  EXPECT_EQ(a.eye, glide.follow(a, 1.0f / 30.0f).eye);  // after reset: a cut again
  Camera ortho = a;
  ortho.orthographic = true;
  EXPECT_EQ(ortho.view, glide.follow(ortho, 1.0f / 30.0f).view);  // passed through
}

}  // namespace
}  // namespace gestura
