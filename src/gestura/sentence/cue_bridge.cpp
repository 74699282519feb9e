#include "gestura/sentence/cue_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/movement_timing.hpp"

namespace gestura {

namespace {

std::vector<int> arm_joints(const Skeleton& skeleton) {
  std::vector<int> out;
  const char* arm[] = {"sternoclavicular", "acromioclavicular", "shoulder", "elbow", "wrist"};
  const char* fingers[] = {"thumb", "index", "middle", "ring", "pinky"};
  for (const char* side : {"l_", "r_"}) {
    for (const char* name : arm)
      if (int j = skeleton.find(std::string(side) + name); j >= 0) out.push_back(j);
    for (const char* finger : fingers)
      for (int k = 1; k <= 3; ++k)
        if (int j = skeleton.find(std::string(side) + finger + std::to_string(k)); j >= 0) out.push_back(j);
  }
  return out;
}

}  // namespace

void bridge_arms(Clip& clip, const Skeleton& skeleton, float from, float to, float fps) {
  if (!std::isfinite(from) || !std::isfinite(to) || !(from < to)) throw Error("bridge: needs a finite interval with from < to");
  const int steps = std::max(2, static_cast<int>(std::ceil((to - from) * fps)));
  for (int j : arm_joints(skeleton)) {
    QuatTrack& track = clip.rotations[joint_slot(j)];
    if (track.size() == 0) continue;
    const quat a = sample_track(track, from), b = sample_track(track, to);
    QuatTrack bridged;
    bridged.interpolation = track.interpolation;
    for (std::size_t k = 0; k < track.size(); ++k)
      if (track.times[k] < from) bridged.add(track.times[k], track.values[k]);
    for (int k = 0; k <= steps; ++k) {
      const float u = static_cast<float>(k) / static_cast<float>(steps);
      bridged.add(from + (to - from) * u, nlerp(a, b, minimum_jerk(u)));
    }
    for (std::size_t k = 0; k < track.size(); ++k)
      if (track.times[k] > to) bridged.add(track.times[k], track.values[k]);
    make_continuous(bridged);
    track = std::move(bridged);
  }
}

}  // namespace gestura
