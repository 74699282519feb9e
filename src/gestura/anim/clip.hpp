#pragma once
// A clip: per-joint transform tracks (indexed like the skeleton it was made for) and named scalar
// channels (face weights, morph targets, anything that is one number over time).
// An empty track means "this joint keeps its rest value" for that component.
#include <string>
#include <vector>

#include "gestura/anim/track.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct Clip {
  std::string name;
  float duration = 0.0f;                 // seconds; sampling time is wrapped into [0, duration]
  std::vector<QuatTrack> rotations;      // one per joint (may be empty tracks)
  std::vector<Vec3Track> translations;   // one per joint
  std::vector<Vec3Track> scales;         // one per joint
  std::vector<std::string> channel_names;
  std::vector<FloatTrack> channels;

  std::size_t joint_count() const { return rotations.size(); }
  void resize_joints(std::size_t n);     // adds empty tracks / drops extras
  int find_channel(const std::string& channel) const;
  FloatTrack& channel(const std::string& channel);  // adds an empty channel when absent
  float end_time() const;                // the last key time over all tracks
};

// Throws gestura::Error naming the joint/channel and key when something is off.
void validate(const Clip& clip, const Skeleton& skeleton);

enum class WrapMode : std::uint8_t { Clamp, Loop, PingPong };

// Maps any time (negative, past the end, NaN → 0) into [0, duration].
float wrap_time(float t, float duration, WrapMode mode);

}  // namespace gestura
