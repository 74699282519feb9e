#pragma once
// A scene performed: every character's motion baked into a clip on its own avatar (world space: the
// root walks), doors' openings over time, and a log of what happened. What `gestura scene` renders
// and `gestura view --scene` plays; plain data, so a server or the studio can keep and replay it.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/avatar.hpp"
#include "gestura/world/scene.hpp"
#include "gestura/world/scene_geometry.hpp"

namespace gestura {

struct PerformedCharacter {
  std::string name;
  std::shared_ptr<const Avatar> avatar;
  std::map<std::string, vec3> colors;  // material name → sRGB (the scene's colours for this character)
  Clip clip;                           // on avatar->skeleton; face channels named like the mesh's morphs
};

struct DoorMotion {
  int object = -1;        // top-level object index
  FloatTrack angle;       // degrees opened over time
};

struct LogEntry {
  float time = 0.0f;
  std::string text;
  bool warning = false;  // an action that could not be done (no path, …), with its place in the script
};

struct ScenePerformance {
  std::vector<PerformedCharacter> characters;
  std::vector<DoorMotion> doors;
  float duration = 0.0f;
  std::vector<LogEntry> log;
};

// Each top-level object's transform at time t (doors turned as they are then).
std::vector<mat4> object_transforms_at(const Scene& scene, const ScenePerformance& performance, float t);

}  // namespace gestura
