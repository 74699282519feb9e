#pragma once
// Sampling a CompressedClip for playback: a context per player keeps, for every animated track, the
// key pair the playhead sits between, decoded (the role of ozz-animation's SamplingJob::Context).
// Playing forward then decodes each key once, when the playhead reaches it, instead of two keys
// per track per frame; a jump decodes afresh, as CompressedClip::sample does every time. The
// clip's constant and identity tracks are gathered once into a pose that each sample starts from.
//
// Tracks are decoded and interpolated a block at a time (8 tracks with AVX2, 4 with SSE2), with the
// same operations as CompressedClip::sample: both give bit-identical poses, on either path.
#include <cstdint>
#include <vector>

#include "gestura/compress/compressed_clip.hpp"
#include "gestura/core/simd_path.hpp"

namespace gestura {

class PlaybackContext {
 public:
  // Writes the local transform of every joint of `clip` at `time` (clamped to [0, duration]): what
  // clip.sample(time, out) writes. The context binds to `clip` on first use and rebinds when given
  // another clip. Throws gestura::Error when out.size() != clip.joint_count(). Never allocates once
  // bound.
  void sample(const CompressedClip& clip, float time, Pose& out, SimdPath path = SimdPath::Auto);

  // Forgets the cached keys (the next sample decodes every track); needed only if the bound clip's
  // bytes were changed in place.
  void invalidate();

 private:
  // The animated tracks of one kind, structure of arrays padded to a multiple of 8 (see
  // playback_kernel.hpp, which reads them through a plain view).
  struct Tracks {
    std::size_t count = 0;
    std::vector<const std::uint8_t*> data;
    std::vector<const std::uint64_t*> keyset;
    std::vector<const std::uint16_t*> rank;
    std::vector<int> bits, code_a[3], code_b[3], need_a, shift, need_b;
    std::vector<std::uint32_t> joint, k0, dirty;
    std::vector<float> dropped, min[3], scale[3], f0, f1, a[4], b[4];
  };

  void bind(const CompressedClip& clip);

  const CompressedClip* clip_ = nullptr;
  const std::uint8_t* clip_bytes_ = nullptr;
  Tracks tracks_[3];  // rotations, translations, scales
  Pose base_;         // every joint's constant or identity values
};

}  // namespace gestura
