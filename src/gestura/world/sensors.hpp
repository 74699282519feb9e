#pragma once
// Virtual sensors (realtime-virtual-humans.txt §3.1: autonomous actors "perceive the objects and the
// other actors in the environment through virtual sensors: visual, tactile and auditory"):
//   vision   what lies in the actor's field of view and range and is not hidden — a ray from the
//            eyes to a few points of the other body (head, chest, hips) or the object must pass the
//            environment and the other bodies (synthetic vision by ray casting)
//   hearing  sound events within their range (quieter through walls)
//   touch    bodies touching (another actor's, or the environment within the actor's radius)
// Sensing reads a snapshot of every actor (ActorView) and the environment; it changes nothing.
#include <span>
#include <string>
#include <vector>

#include "gestura/world/environment.hpp"

namespace gestura {

// What any actor can see of another from outside.
struct ActorView {
  vec3 position{0.0f};   // on the floor under the pelvis
  float yaw = 0.0f;
  float radius = 0.3f;
  float height = 1.7f;
  vec3 velocity{0.0f};   // horizontal, m/s
  bool signing = false;  // its hands are saying something now
};

struct VisionParams {
  float range = 12.0f;
  float horizontal_fov = deg(200.0f);  // both eyes with the head's small turns
  float vertical_fov = deg(120.0f);
};

struct SeenActor {
  int actor = -1;
  float distance = 0.0f;
  float bearing = 0.0f;   // radians from straight ahead, + to the left
  bool signing = false;
};

struct SeenObject {
  int object = -1;
  float distance = 0.0f;
  float bearing = 0.0f;
};

struct SoundEvent {
  vec3 position{0.0f};
  float loudness = 1.0f;  // range multiplier (1 = a door, heard up to `hearing_range`)
  std::string what;       // "door", "knock", …
  int source_actor = -1;
  float time = 0.0f;
};

struct Heard {
  int event = -1;         // index into the events given
  float distance = 0.0f;
  bool direct = true;     // false: through a wall (muffled)
};

struct Touch {
  int actor = -1;         // another actor, or -1 for the environment
  int object = -1;        // the environment object touched
  float depth = 0.0f;     // how far the bodies overlap (m)
};

struct Percept {
  std::vector<SeenActor> actors;
  std::vector<SeenObject> objects;
  std::vector<Heard> heard;
  std::vector<Touch> touches;
};

// The eye point of an actor (its height × 0.93 above its floor position).
vec3 eye_point(const ActorView& a);

// Whether actor `self` sees point `p` (field of view, range, line of sight through the environment
// and the bodies of the actors in `occluders` — every other actor when empty — which are vertical
// cylinders).
bool sees_point(const Environment& env, std::span<const ActorView> actors, int self, const vec3& p, const VisionParams& vision,
                int ignore_actor = -1, int ignore_object = -1, std::span<const int> occluders = {});

// Vision: the actors among `candidates` (every other actor when empty; in a crowd, the nearest few)
// that `self` sees, nearest first, and the objects in `objects` (object index and a point on it).
void see(const Environment& env, std::span<const ActorView> actors, int self, std::span<const int> candidates,
         std::span<const std::pair<int, vec3>> objects, const VisionParams& vision, Percept& out);

// Hearing: the events within range (range × loudness; half as far through walls).
void hear(const Environment& env, std::span<const ActorView> actors, int self, std::span<const SoundEvent> events,
          float hearing_range, Percept& out);

// Touch: other bodies whose cylinders overlap this one's, and the environment nearer than the radius.
void touch(const Environment& env, std::span<const ActorView> actors, int self, Percept& out);

}  // namespace gestura
