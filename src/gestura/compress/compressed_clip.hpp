#pragma once
// A compressed clip (.gcl): per-joint tracks sampled uniformly, reduced to the key frames they need,
// quantised to the fewest bits that keep the error bound (mpeg4-humanoid-animation.txt §4: key
// values plus interpolation as a compression tool).
//
// File layout (little-endian; "u8/u16/u32" unsigned, "f32" IEEE float):
//   header   magic "GCL\0" | u16 version (1) | u16 reserved (0) | u32 joint_count | u32 frame_count
//            | f32 sample_rate (Hz) | f32 max_error (m, as requested) | u32 data_bytes
//   tracks   joint_count × 3 descriptors, per joint: rotation, translation, scale. Each starts with
//            u8 kind:
//              0 identity  — nothing follows (rotation (0,0,0,1), translation 0, scale 1)
//              1 constant  — f32 × 3 (translation/scale) or f32 × 4 (rotation x, y, z, w)
//              2 animated  — u8 bits (1..24) | u8 dropped (rotation: quaternion component 0..3
//                            x,y,z,w left out and rebuilt as +sqrt(1 − |rest|²); else 0)
//                            | u16 key_count (2..frame_count) | f32 min × 3 | f32 extent × 3
//   keysets  for every animated track with key_count < frame_count, in track order: a bitset of
//            frame_count bits (u64 words, bit f set = frame f is a key; first and last always set)
//   data     for every animated track, in track order: key_count × 3 components of `bits` bits,
//            packed LSB first, each track starting on a byte boundary; value = min + q · extent /
//            (2^bits − 1). Then 8 zero bytes of padding (so decoding may read 8 bytes at once).
// Between key frames values are interpolated linearly (rotations by normalised lerp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr std::uint16_t kGclVersion = 1;

enum class GclTrackKind : std::uint8_t { Identity = 0, Constant = 1, Animated = 2 };

// One track as the decoder uses it (pointers into the clip's bytes).
struct GclTrack {
  GclTrackKind kind = GclTrackKind::Identity;
  std::uint8_t bits = 0;
  std::uint8_t dropped = 0;
  std::uint32_t key_count = 0;
  vec4 constant{0.0f, 0.0f, 0.0f, 1.0f};
  vec3 min{0.0f}, scale{0.0f};          // scale = extent / (2^bits − 1)
  const std::uint64_t* keyset = nullptr; // null when every frame is a key
  const std::uint16_t* rank = nullptr;   // keys before each 64-frame word (built on load)
  const std::uint8_t* data = nullptr;
};

class CompressedClip {
 public:
  // Move-only: the track table points into the owned buffers (moving a vector keeps its buffer).
  CompressedClip() = default;
  CompressedClip(CompressedClip&&) = default;
  CompressedClip& operator=(CompressedClip&&) = default;
  CompressedClip(const CompressedClip&) = delete;
  CompressedClip& operator=(const CompressedClip&) = delete;

  // Validates and indexes `bytes`. Throws gestura::Error naming `source`, the byte offset and what
  // is wrong (bad magic, unsupported version, truncated section, bad kind/bits/key count, keysets
  // without their first/last key or with a wrong key count, trailing bytes).
  static CompressedClip from_bytes(std::vector<std::uint8_t> bytes, const std::string& source = "<memory>");

  std::size_t joint_count() const { return joint_count_; }
  std::uint32_t frame_count() const { return frame_count_; }
  float sample_rate() const { return sample_rate_; }
  float duration() const { return static_cast<float>(frame_count_ - 1) / sample_rate_; }
  float max_error() const { return max_error_; }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::span<const GclTrack> tracks() const { return tracks_; }  // 3 per joint: rotation, translation, scale

  // Writes the local transform of every joint at `time` (clamped to [0, duration]).
  // Contract: out.size() == joint_count(). Never allocates.
  void sample(float time, Pose& out) const;

 private:
  std::vector<std::uint8_t> bytes_;
  std::vector<GclTrack> tracks_;
  std::vector<std::uint16_t> ranks_;
  std::vector<std::uint64_t> keysets_;  // aligned copy of the file's keysets
  std::size_t joint_count_ = 0;
  std::uint32_t frame_count_ = 0;
  float sample_rate_ = 30.0f;
  float max_error_ = 0.0f;
};

CompressedClip load_gcl(const std::string& path);
void save_gcl(const std::string& path, const CompressedClip& clip);

// --- Shared by the encoder and the decoder, so both reconstruct bit-identical values ----------

inline std::uint32_t read_bits(const std::uint8_t* data, std::uint64_t bit, unsigned bits) {
  std::uint64_t word;
  __builtin_memcpy(&word, data + (bit >> 3), 8);
  return static_cast<std::uint32_t>((word >> (bit & 7)) & ((1ull << bits) - 1));
}

// Where `time` falls in a clip of `frame_count` frames at `rate` Hz: the frame position x, clamped to
// [0, frame_count − 1] (NaN → 0), and the first frame of the pair of frames around it (at most
// frame_count − 2, so the last frame is reached as the end of the last pair).
struct FramePosition {
  float x;
  std::uint32_t frame;
};
inline FramePosition frame_position(float time, float rate, std::uint32_t frame_count) {
  const float last = static_cast<float>(frame_count - 1);
  float x = time * rate;
  x = x > 0.0f ? (x < last ? x : last) : 0.0f;  // also maps NaN to 0
  std::uint32_t frame = static_cast<std::uint32_t>(x);
  if (frame_count >= 2 && frame > frame_count - 2) frame = frame_count - 2;
  return {x, frame};
}

// Rebuilds a quaternion (x, y, z, w in glm's storage order) from its three stored components.
inline quat rebuild_quat(const vec3& kept, unsigned dropped) {
  const float missing = std::sqrt(std::max(0.0f, 1.0f - glm::dot(kept, kept)));
  float c[4];
  unsigned k = 0;
  for (unsigned i = 0; i < 4; ++i) c[i] = i == dropped ? missing : kept[k++];
  return quat(c[3], c[0], c[1], c[2]);
}

}  // namespace gestura
