#pragma once
// Samples a clip into a pose. A Sampler keeps one key cursor per track, so forward playback costs
// O(1) per track per frame; seeking backwards falls back to a binary search.
#include <cstdint>
#include <span>
#include <vector>

#include "gestura/anim/clip.hpp"

namespace gestura {

class Sampler {
 public:
  // Contract: `clip` outlives the sampler and is valid for the skeleton that `rest` comes from.
  explicit Sampler(const Clip& clip);

  // Writes every joint of `out` (resized if needed): tracked components from the clip, the rest
  // from `rest`. Writes clip channel values into `channels` (size must be >= clip.channels.size(),
  // or empty to skip). Time is wrapped by `mode`.
  void sample(float time, WrapMode mode, const Pose& rest, Pose& out, std::span<float> channels = {});

  const Clip& clip() const { return *clip_; }

 private:
  const Clip* clip_;
  std::vector<std::uint32_t> rotation_cursors_, translation_cursors_, scale_cursors_, channel_cursors_;
};

// Convenience without a cursor (stateless; binary search per track).
void sample_clip(const Clip& clip, float time, WrapMode mode, const Pose& rest, Pose& out,
                 std::span<float> channels = {});

}  // namespace gestura
