// The built-in "characters" view keeps every character whole in frame from inside a walled room,
// also when one stands by the wall the default (south-east) camera would stand at.
#include <gtest/gtest.h>

#include <vector>

#include "gestura/render/scene_cameras.hpp"
#include "gestura/world/scene_json.hpp"

namespace {

using namespace gestura;

CharacterView standing(const char* name, float x, float z) {
  CharacterView v;
  v.name = name;
  v.position = vec3(x, 0.0f, z);
  v.head = vec3(x, 1.6f, z);
  return v;
}

// Every corner of each character's body box lands inside the picture, in front of the eye, and the
// eye stays inside the room.
void expect_all_in_frame(const std::vector<CharacterView>& people, float aspect) {
  const Scene scene = parse_scene(R"({"characters": [{"name": "anna"}, {"name": "ben"}]})", "room.json");
  Aabb room;
  room.grow(vec3(-0.2f, 0.0f, -0.2f));
  room.grow(vec3(8.2f, 2.6f, 6.2f));
  const Camera c = scene_camera("characters", scene, room, people, aspect);
  EXPECT_GT(c.eye.x, room.min.x);
  EXPECT_LT(c.eye.x, room.max.x);
  EXPECT_GT(c.eye.z, room.min.z);
  EXPECT_LT(c.eye.z, room.max.z);
  for (const CharacterView& v : people)
    for (int k = 0; k < 8; ++k) {
      const vec3 p((k & 1) ? v.position.x + 0.25f : v.position.x - 0.25f, (k & 2) ? v.head.y + 0.1f : 0.0f,
                   (k & 4) ? v.position.z + 0.25f : v.position.z - 0.25f);
      const vec4 clip = c.projection * c.view * vec4(p, 1.0f);
      ASSERT_GT(clip.w, 0.0f) << v.name << " is behind the camera";
      EXPECT_LE(std::abs(clip.x / clip.w), 1.0f) << v.name << " corner " << k << " leaves the picture sideways";
      EXPECT_LE(std::abs(clip.y / clip.w), 1.0f) << v.name << " corner " << k << " leaves the picture up or down";
    }
}

TEST(SceneCameras, CharactersViewFramesEveryoneInTheMiddle) {
  expect_all_in_frame({standing("anna", 4.6f, 3.4f), standing("ben", 3.0f, 2.0f)}, 16.0f / 9.0f);
}

TEST(SceneCameras, CharactersViewTurnsRoundWhenOneStandsByTheWall) {
  // ben by the south-east walls, where the default camera would have to stand.
  expect_all_in_frame({standing("anna", 4.6f, 3.4f), standing("ben", 7.6f, 5.6f)}, 16.0f / 9.0f);
  expect_all_in_frame({standing("anna", 2.2f, 0.6f), standing("ben", 7.5f, 4.8f)}, 16.0f / 9.0f);
  // Opposite corners of the room, and a tall split pane.
  expect_all_in_frame({standing("anna", 0.5f, 0.5f), standing("ben", 7.5f, 5.5f)}, 16.0f / 9.0f);
  expect_all_in_frame({standing("anna", 4.6f, 3.4f), standing("ben", 7.6f, 5.6f)}, 0.9f);
}

}  // namespace
