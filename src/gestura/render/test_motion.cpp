#include "gestura/render/test_motion.hpp"

#include <array>

#include "gestura/core/error.hpp"

namespace gestura {

Clip make_wave_clip(const Skeleton& skeleton) {
  auto joint = [&](const char* name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error(std::string("test motion: the skeleton has no joint '") + name + "'");
    return j;
  };
  const int shoulder = joint("r_shoulder"), elbow = joint("r_elbow"), wrist = joint("r_wrist");
  Clip clip;
  clip.name = "test_wave";
  clip.duration = 2.0f;
  clip.resize_joints(skeleton.size());
  // Right side: flexion is −x, abduction −z, wrist extension −z (the mirror of the left side).
  struct Key {
    float time;
    vec3 shoulder, elbow, wrist;  // degrees
  };
  const std::array<Key, 7> keys{{
      {0.00f, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
      {0.50f, {-55, 0, -25}, {-95, 40, 0}, {0, 0, -15}},
      {0.75f, {-55, 0, -30}, {-95, 40, 0}, {0, 0, 20}},
      {1.00f, {-55, 0, -20}, {-95, 40, 0}, {0, 0, -25}},
      {1.25f, {-55, 0, -30}, {-95, 40, 0}, {0, 0, 20}},
      {1.50f, {-55, 0, -25}, {-95, 40, 0}, {0, 0, -15}},
      {2.00f, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
  }};
  auto radians = [](vec3 degrees) { return vec3(deg(degrees.x), deg(degrees.y), deg(degrees.z)); };
  for (const Key& k : keys) {
    clip.rotations[static_cast<std::size_t>(shoulder)].add(k.time, joint_rotation(skeleton, shoulder, radians(k.shoulder)));
    clip.rotations[static_cast<std::size_t>(elbow)].add(k.time, joint_rotation(skeleton, elbow, radians(k.elbow)));
    clip.rotations[static_cast<std::size_t>(wrist)].add(k.time, joint_rotation(skeleton, wrist, radians(k.wrist)));
  }
  for (QuatTrack& track : clip.rotations) {
    if (track.empty()) continue;
    track.interpolation = Interpolation::Slerp;
    make_continuous(track);
  }
  return clip;
}

}  // namespace gestura
