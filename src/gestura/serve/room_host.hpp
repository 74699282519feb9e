#pragma once
// The room's host: an autonomous actor standing at the middle of the seats who turns head and eyes
// toward whoever is signing (realtime-virtual-humans.txt §3: autonomous actors perceive the others
// through virtual sensors). Choosing whom to watch is the world's look behaviour over what the
// host's virtual vision sees (world/behaviour.hpp, world/sensors.hpp): it keeps watching one signer
// until they stop, and glances at a newcomer. Turning the head and eyes is the world's look-at
// (world/character_motion.hpp), applied to the host's rest pose.
#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gestura/skeleton/skeleton.hpp"
#include "gestura/world/behaviour.hpp"
#include "gestura/world/environment.hpp"
#include "gestura/world/path_planner.hpp"
#include "gestura/world/trajectory.hpp"

namespace gestura::serve {

// Joint rotations (local, x y z w) by joint name, as a player sets them on its bones.
using JointRotations = std::vector<std::pair<std::string, std::array<float, 4>>>;

// One seat as the host perceives it.
struct SeatView {
  vec3 position{0.0f};  // on the floor, world
  float yaw = 0.0f;
  float height = 1.7f;
  bool signing = false;
  bool present = true;  // someone sits there (an empty seat is no body: it hides nothing)
};

struct HostLook {
  int seat = -1;            // the seat watched, or -1 (a glance at a sound, or straight ahead)
  vec3 point{0.0f, 1.55f, 2.0f};  // world point looked at
  std::string why;          // "signer", "sound", "" (ahead)
};

// The host's look for this moment. `host` stands at host_place facing +Z; `arrived` is the seat of a
// participant who just came in (a sound the host glances at), or -1. `state` is kept between calls.
HostLook choose_host_look(const SeatView& host, std::span<const SeatView> seats, int arrived, float now, LookState& state);

// Head, neck and eye rotations of the host turned toward `point` (world, the host at `host`).
class HostGaze {
 public:
  HostGaze(std::shared_ptr<const Skeleton> skeleton, std::vector<mat4> bind_model);
  JointRotations look_at(const SeatView& host, const vec3& point) const;

 private:
  std::shared_ptr<const Skeleton> skeleton_;
  std::vector<mat4> bind_;
};

// Where the host stands and the way it faces (yaw about +Y; 0 faces +Z).
struct HostStop {
  vec3 position{0.0f};
  float yaw = 0.0f;
};

// The spot the host walks to when someone signs: `distance` from the seat, toward the room's middle
// (which every seat faces) turned `aside` away from the viewers' side (+Z), so that the host does
// not stand between the page's camera and the signer; the host faces the signer.
HostStop stop_facing(const SeatView& seat, float distance = 1.2f, float aside = deg(35.0f));

// A walk of the host: the planned path (collision-free for the host's radius) and the body's
// trajectory along it (the world's locomotion: turn, start, walk, slow down, turn to face).
struct HostWalkPlan {
  std::vector<vec3> path;
  RootTrajectory body;
  float length = 0.0f;
};

// The room as the world sees it: a floor and, at every seat, a standing body's cylinder (the
// participants' places), in the world's environment; the host's paths are planned on it with the
// world's navigation (Recast/Detour, world/path_planner.hpp) and followed with the world's
// locomotion (world/locomotion.hpp). Built once per server; plan() may be called from any thread.
class RoomWorld {
 public:
  static constexpr float kHostRadius = 0.25f;  // the host's body, walking
  static constexpr float kSeatRadius = 0.3f;   // a participant standing at a seat

  explicit RoomWorld(std::span<const vec3> seats);
  RoomWorld(const RoomWorld&) = delete;
  RoomWorld& operator=(const RoomWorld&) = delete;
  const Environment& environment() const { return env_; }
  std::span<const vec3> seats() const { return seats_; }
  // None when the goal cannot be reached (then the host stays and only turns its head).
  std::optional<HostWalkPlan> plan(const HostStop& from, const HostStop& to);

 private:
  std::vector<vec3> seats_;
  Environment env_;
  std::mutex mutex_;  // the planner builds its navigation meshes on first use
  std::unique_ptr<PathPlanner> planner_;  // over env_ (so RoomWorld does not move)
};

}  // namespace gestura::serve
