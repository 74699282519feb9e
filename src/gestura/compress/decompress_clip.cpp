#include "gestura/compress/decompress_clip.hpp"

#include "gestura/compress/playback_context.hpp"

namespace gestura {

Clip decompress_clip(const CompressedClip& compressed, const std::string& name) {
  const std::size_t n = compressed.joint_count();
  const std::uint32_t frames = compressed.frame_count();
  Clip clip;
  clip.name = name;
  clip.resize_joints(n);
  clip.duration = compressed.duration();
  Pose pose;
  pose.resize(n);
  PlaybackContext context;  // frames in order: each key decoded once
  std::vector<std::uint8_t> scaled(n, 0);
  std::vector<std::vector<vec3>> scales(n);
  for (std::uint32_t f = 0; f < frames; ++f) {
    // Key times are frame / rate, the same times the encoder sampled.
    const float t = static_cast<float>(f) / compressed.sample_rate();
    context.sample(compressed, t, pose);
    for (std::size_t j = 0; j < n; ++j) {
      clip.rotations[j].add(t, pose.rotations[j]);
      clip.translations[j].add(t, pose.translations[j]);
      scales[j].push_back(pose.scales[j]);
      if (pose.scales[j] != vec3(1.0f)) scaled[j] = 1;
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (!scaled[j]) continue;
    clip.scales[j].times = clip.rotations[j].times;
    clip.scales[j].values = std::move(scales[j]);
  }
  return clip;
}

}  // namespace gestura
