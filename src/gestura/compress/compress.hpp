#pragma once
// The encoder of CompressedClip: error-driven key reduction plus per-track quantisation.
//
// 1. The clip is sampled uniformly (sample_rate) into local rotations, translations and scales.
// 2. Every track gets a tolerance from one global factor s and the hierarchy (the "lever" of the
//    track): a rotation error θ at joint j moves j's virtual points by θ·d and the positions below
//    it by θ·bone, bone being its longest bone to a child; a translation error moves them by itself;
//    a scale error by up to the longest path below. tol = s · max_error / lever.
// 3. Rotations are quantised toward compensated targets: parents are encoded first, and a joint's
//    target is the local rotation that puts its decoded model orientation on the raw one given its
//    parent's decoded orientation (r* = R̂_parent⁻¹ · R_raw). Orientation errors then do not add up
//    down a chain, which is why a rotation's lever is its bone and not the whole path below it.
// 4. Each track within tolerance of identity / a constant is stored as such. Otherwise it is
//    quantised (rotations: the three components other than the one largest over the whole track,
//    which is rebuilt; per-track range) and key frames are chosen by recursive splitting: a segment
//    whose interpolation misses a frame by more than the tolerance is split at its worst frame
//    (Douglas–Peucker). Bit depths are searched from the previous round's depth; the cheapest wins.
// 5. Every track is decoded exactly as CompressedClip::sample decodes it, straight from its codes,
//    and measured with the ACL metric — virtual points virtual_point_distance along each joint's
//    three axes, in model space, every frame — and s is searched (shrunk when the bound is broken,
//    grown while it holds) for the smallest clip that honours max_error.
// 6. Then bits are taken away track by track, leaves first (same keys; from a track's depth, one
//    less, then galloping down and bisecting back), each trial re-measuring only the subtree it
//    changes (and re-aiming the rotations below a changed rotation), while the bound holds.
// The encoder aims slightly inside the bound (by a few float ulps of the clip's size) so that a
// measure computed in another order still finds it held; the report's error is measured on the
// assembled clip through CompressedClip::sample.
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
  int passes = 0;                // encode + measure rounds: tolerance search (whole clip), then bit trials (one subtree each)
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
