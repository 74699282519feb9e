#pragma once
// Cameras on a scene: the scene's own (perspective or orthographic, fixed or aimed at a character
// every frame) and built-in views framed from the environment's bounds — the four views of the
// ALIAS environment editor (alias-movement-through-environments.txt ch. 7: two perspective views,
// a plan and a section) and a view that keeps every character in frame.
#include <span>
#include <string>
#include <vector>

#include "gestura/render/renderer.hpp"
#include "gestura/world/bvh.hpp"
#include "gestura/world/scene.hpp"

namespace gestura {

// Names a user can give besides the scene's cameras.
//   plan          orthographic, looking down on the whole environment
//   section       orthographic, from the south (+Z) side, cut through the middle (its near half
//                 is not drawn), the whole height
//   perspective   from high in the south-west corner of the scene's box, looking across it
//   perspective2  from high in the north-east corner
//   characters    perspective, framing every character whole (follows them) from inside the
//                 scene's box: from the south-east, or the nearest direction round them that fits
//                 everyone when walls keep the camera too close
//   alias         the four ALIAS views as a 2×2 split: perspective, perspective2, plan, section
//   CHARACTER     a character's name: over that character's shoulder toward where it looks
inline constexpr const char* kBuiltInSceneCameras[] = {"plan", "section", "perspective", "perspective2", "characters", "alias"};

// What a frame's cameras need to know about the characters.
struct CharacterView {
  std::string name;
  vec3 position{0.0f};  // on the floor
  vec3 head{0.0f};      // eye height
  float facing = 0.0f;  // radians about +Y, 0 = +Z
};

// Expands `alias` and checks every name (scene camera, built-in or character); throws
// gestura::Error listing what exists otherwise.
std::vector<std::string> expand_scene_cameras(const std::vector<std::string>& names, const Scene& scene);

// One view per name, split like the avatar renderer's camera lists.
std::vector<View> scene_views(const std::vector<std::string>& names, const Scene& scene, const Aabb& bounds,
                              std::span<const CharacterView> characters, int width, int height);

Camera scene_camera(const std::string& name, const Scene& scene, const Aabb& bounds, std::span<const CharacterView> characters,
                    float aspect);

}  // namespace gestura
