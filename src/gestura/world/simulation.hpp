#pragma once
// The world running: actors walking their planned paths, sensing each other and the environment,
// and their behaviours (behaviour.hpp) choosing where they look, whom they follow and how they get
// out of each other's way, tick by tick at a fixed step. It records what each actor's body does (the
// trajectory the walking skill turns into steps) and where it looks. Deterministic: the same
// commands and seed give the same world, whatever the machine.
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "gestura/world/behaviour.hpp"
#include "gestura/world/locomotion.hpp"
#include "gestura/world/path_planner.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/sensors.hpp"

namespace gestura {

struct ActorSpec {
  std::string name;
  vec3 position{0.0f};
  float yaw = 0.0f;
  float radius = 0.3f;
  float height = 1.7f;
  float speed = 1.3f;
};

struct LookSample {
  vec3 point{0.0f};
  float weight = 0.0f;
  int actor = -1;
};

struct SimActor {
  ActorSpec spec;
  ActorView view;
  Locomotor walker;
  LocomotionParams params;
  Percept percept;
  LookState look_state;
  AvoidState avoid_state;
  LookIntent look;
  // Commands in force.
  int follow = -1;
  float follow_distance = 1.2f;
  float follow_replan_at = 0.0f;
  vec3 follow_planned_to{1e30f};
  std::optional<vec3> look_at_point;
  int look_at_actor = -1;
  int addressee = -1;
  bool signing = false;
  // What was recorded, one sample per tick.
  RootTrajectory trajectory;
  std::vector<LookSample> looks;
  std::vector<int> touching;  // actors touched so far (sensed)
};

struct SimulationOptions {
  float tick = 1.0f / 60.0f;
  float hearing_range = 15.0f;
  VisionParams vision;
  int sense_every = 0;           // ticks between an actor's sensing (0: every tick below 12 actors, else 6, staggered)
  int vision_candidates = 10;    // in a crowd, the nearest this many are looked for
  bool record = true;            // keep trajectories and looks
  std::uint64_t seed = 1;
  NavMeshSettings navigation;
};

class Simulation {
 public:
  // Contract: `geometry` outlives the simulation (the environment is rebuilt from it when doors move).
  Simulation(const SceneGeometry& geometry, const SimulationOptions& options = {});

  int add_actor(const ActorSpec& spec);
  std::size_t actor_count() const { return actors_.size(); }
  SimActor& actor(int i) { return actors_[static_cast<std::size_t>(i)]; }
  const SimActor& actor(int i) const { return actors_[static_cast<std::size_t>(i)]; }
  float time() const { return time_; }
  int ticks() const { return ticks_; }
  const Environment& environment() const { return *env_; }
  PathPlanner& planner() { return *planner_; }

  // Plans a path and starts walking it; on NoPath nothing moves and the result says why.
  PlannedPath walk_to(int actor, const vec3& goal, bool approach = false, std::optional<float> facing = std::nullopt,
                      vec3 approach_extent = vec3(1.0f, 0.6f, 1.0f));
  void turn_to(int actor, float yaw);
  void stop(int actor);
  void follow(int actor, int target, float distance);
  void look_at(int actor, std::optional<vec3> point, int target_actor = -1);
  void set_signing(int actor, bool signing, int addressee = -1);
  void emit(const SoundEvent& event);
  // A door (or any object) moved: the environment and the planner are rebuilt from the geometry
  // with the new transform before the next walk.
  void set_object_transform(int object, const mat4& transform);

  void step();                          // one tick
  bool idle() const;                    // nobody walking or turning

  const std::vector<SoundEvent>& sounds() const { return sounds_; }
  std::mt19937_64& random() { return random_; }

 private:
  void sense(int i);
  void rebuild();
  const SceneGeometry* geometry_;
  SimulationOptions options_;
  std::vector<mat4> object_transforms_;
  std::unique_ptr<Environment> env_;
  std::unique_ptr<PathPlanner> planner_;
  bool dirty_ = false;
  std::vector<SimActor> actors_;
  std::vector<ActorView> views_;
  std::vector<SoundEvent> sounds_;
  std::vector<std::pair<int, vec3>> objects_;  // named objects and their centres, for vision
  float time_ = 0.0f;
  int ticks_ = 0;
  std::mt19937_64 random_;
};

}  // namespace gestura
