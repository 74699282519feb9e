#pragma once
// The room's host: an autonomous actor standing at the middle of the seats who turns head and eyes
// toward whoever is signing (realtime-virtual-humans.txt §3: autonomous actors perceive the others
// through virtual sensors). Choosing whom to watch is the world's look behaviour over what the
// host's virtual vision sees (world/behaviour.hpp, world/sensors.hpp): it keeps watching one signer
// until they stop, and glances at a newcomer. Turning the head and eyes is the world's look-at
// (world/character_motion.hpp), applied to the host's rest pose.
#include <array>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gestura/skeleton/skeleton.hpp"
#include "gestura/world/behaviour.hpp"

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

}  // namespace gestura::serve
