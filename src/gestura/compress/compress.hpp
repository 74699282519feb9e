#pragma once
// The encoder of CompressedClip: error-driven key reduction plus per-track quantisation.
//
// 1. The clip is sampled uniformly (sample_rate) into local rotations, translations and scales.
// 2. Every track gets a tolerance from one global factor s and the hierarchy: a rotation error θ at
//    joint j moves the virtual points of j and its descendants by at most θ · lever(j), lever(j)
//    being the longest bone path below j plus the virtual-point distance; a translation error moves
//    them by itself. So tol_rotation(j) = s · max_error / lever(j), tol_translation = s · max_error.
// 3. Each track within tolerance of identity / a constant is stored as such. Otherwise, for every bit
//    depth 1..24 the track is quantised (rotations: the three components other than the one largest
//    over the whole track, which is rebuilt; per-track range) and key frames are chosen by recursive
//    splitting: a segment whose interpolation misses a frame by more than the tolerance is split at
//    its worst frame (Douglas–Peucker). The cheapest depth in bits wins.
// 4. The result is decoded and measured with the ACL metric — virtual points virtual_point_distance
//    along each joint's three axes, in model space, every frame — and s is searched (shrunk when the
//    bound is broken, grown while it holds) for the smallest clip that honours max_error.
#include <cstddef>

#include "gestura/anim/clip.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct CompressionSettings {
  float max_error = 1e-4f;               // metres, on the virtual points (0.01 cm)
  float sample_rate = 30.0f;             // Hz
  float virtual_point_distance = 0.03f;  // metres
};

struct CompressionReport {
  std::size_t raw_bytes = 0;     // frames × joints × 10 floats (rotation, translation, scale)
  std::size_t bytes = 0;         // the compressed clip
  float max_error = 0.0f;        // metres, ACL metric over all frames
  float p99_error = 0.0f;        // 99th percentile of the per-joint-per-frame error
  int passes = 0;                // encode + measure rounds (tolerance search, then per-track bit trimming)
  bool within_bound = false;     // max_error ≤ settings.max_error
};

// Throws gestura::Error when the clip does not fit the skeleton, settings are out of range
// (max_error ≤ 0, sample_rate ≤ 0), or the clip is longer than 65535 frames at sample_rate.
// When no tolerance meets the bound (a bound below float precision), the tightest encoding is
// returned and report->within_bound is false.
CompressedClip compress(const Clip& clip, const Skeleton& skeleton, const CompressionSettings& settings = {},
                        CompressionReport* report = nullptr);

// The ACL error of `compressed` against `clip` at the sample frames: per frame and joint the largest
// displacement of the joint's three virtual points in model space. Returns max and 99th percentile.
struct ClipError {
  float max = 0.0f, p99 = 0.0f;
};
ClipError measure_error(const Clip& clip, const Skeleton& skeleton, const CompressedClip& compressed,
                        float virtual_point_distance = 0.03f);

}  // namespace gestura
