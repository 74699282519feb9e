#pragma once
// A facial action: one channel raised to a peak weight over [start, end], entering and leaving with
// sinusoidal ramps (realtime-virtual-humans.txt §5.2.5: a sinusoidal weight function over ~10% of
// the action's duration, so overlapping actions on the same channel compose without jumps).
//
// Composition: all actions on a channel add, and the sum is clamped to [0, 1].
#include <span>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"

namespace gestura::face {

struct FaceAction {
  std::string_view channel;  // a name from face_channels.hpp (static storage)
  float start = 0.0f, end = 0.0f;  // seconds
  float peak = 1.0f;         // weight held between the ramps
  float ramp_in = 0.0f, ramp_out = 0.0f;  // seconds; ramp_in + ramp_out <= end - start
};

// The §5.2.5 ramp for an action lasting `duration` seconds: 10% of it, at least 80 ms, at most half.
float default_ramp(float duration);

// An action with default ramps on both sides.
FaceAction make_action(std::string_view channel, float start, float end, float peak);

// Smooth 0→1 over [0, 1]: 0.5 − 0.5·cos(πx), clamped outside.
float sinusoidal_ramp(float x);

// The weight of one action at time t (0 outside [start, end]).
float action_weight(const FaceAction& action, float t);

// The composed, clamped weight of `channel` at time t.
float channel_weight(std::span<const FaceAction> actions, std::string_view channel, float t);

// Writes every channel that has actions into `clip` as linear keys that follow the composed curve
// (each ramp sampled at 8 steps, so the keyed curve is within 2% of the sinusoid), replacing any keys
// the channel had. Extends clip.duration to the last key. Throws gestura::Error naming the action
// index for non-finite times or peaks, end < start, negative or too long ramps.
void write_face_channels(std::span<const FaceAction> actions, Clip& clip);

}  // namespace gestura::face
