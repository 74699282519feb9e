#include "gestura/face/eye_gaze.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gestura/core/error.hpp"
#include "gestura/face/eye_aim.hpp"
#include "gestura/face/face_channels.hpp"

namespace gestura::face {

void write_eye_gaze(const Skeleton& skeleton, Clip& clip, float fps) {
  const int channel = clip.find_channel(std::string(kGazeHands));
  if (channel < 0) return;
  if (!(fps >= 1.0f && fps <= 240.0f)) throw Error("eye gaze: fps " + std::to_string(fps) + " is outside 1–240");
  for (const char* name : {"vc4", "skullbase", "r_wrist", "r_middle1"})
    if (skeleton.find(name) < 0) throw Error(std::string("eye gaze needs joint '") + name + "' in the skeleton");
  const std::size_t wrist = static_cast<std::size_t>(skeleton.find("r_wrist"));
  const std::size_t knuckle = static_cast<std::size_t>(skeleton.find("r_middle1"));
  const FloatTrack weights = clip.channels[static_cast<std::size_t>(channel)];
  if (weights.empty()) return;

  const float end = std::max(clip.duration, clip.end_time());
  const int frames = static_cast<int>(std::ceil(end * fps)) + 1;
  std::vector<float> times(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f) times[static_cast<std::size_t>(f)] = std::min(static_cast<float>(f) / fps, end);
  write_gaze(skeleton, times, [&](float t, std::span<const mat4> model) {
    const float w = sample_track(weights, t);
    return GazeTarget{0.5f * (vec3(model[wrist][3]) + vec3(model[knuckle][3])), w, w};
  }, clip, std::array<int, 2>{static_cast<int>(wrist), static_cast<int>(knuckle)});
  clip.duration = std::max(clip.duration, end);
}

}  // namespace gestura::face
