#include "gestura/compress/playback_context.hpp"

#include <algorithm>
#include <string>

#include "gestura/compress/playback_kernel.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

namespace playback_detail {

#if defined(__SSE2__)
void sample_portable(const Group& group, std::uint32_t frame, float x, float* out) { sample_group<F4>(group, frame, x, out); }
#else
void sample_portable(const Group& group, std::uint32_t frame, float x, float* out) { sample_group<F1>(group, frame, x, out); }
#endif

}  // namespace playback_detail

namespace {

constexpr std::size_t kPad = 8;  // the widest block

}  // namespace

void PlaybackContext::bind(const CompressedClip& clip) {
  const std::size_t n = clip.joint_count();
  base_.resize(n);
  for (Tracks& t : tracks_) t = Tracks{};
  const std::span<const GclTrack> tracks = clip.tracks();
  for (std::size_t j = 0; j < n; ++j) {
    const GclTrack* track = &tracks[j * 3];
    const vec4 r = track[0].constant;
    base_.rotations[j] = quat(r.w, r.x, r.y, r.z);
    base_.translations[j] = vec3(track[1].constant);
    base_.scales[j] = vec3(track[2].constant);
    for (std::size_t c = 0; c < 3; ++c) {
      const GclTrack& g = track[c];
      if (g.kind != GclTrackKind::Animated) continue;
      Tracks& t = tracks_[c];
      ++t.count;
      t.data.push_back(g.data);
      t.keyset.push_back(g.keyset);
      t.rank.push_back(g.rank);
      t.bits.push_back(g.bits);
      t.joint.push_back(static_cast<std::uint32_t>(j));
      t.dropped.push_back(static_cast<float>(g.dropped));
      for (int k = 0; k < 3; ++k) t.min[k].push_back(g.min[k]), t.scale[k].push_back(g.scale[k]);
    }
  }
  // Padding tracks: a pair that holds every frame (never refreshed), values never stored.
  for (Tracks& t : tracks_) {
    const std::size_t padded = (t.count + kPad - 1) / kPad * kPad;
    t.data.resize(padded, nullptr), t.keyset.resize(padded, nullptr), t.rank.resize(padded, nullptr);
    t.bits.resize(padded, 1), t.joint.resize(padded, 0), t.dropped.resize(padded, 3.0f);
    for (int k = 0; k < 3; ++k) t.min[k].resize(padded, 0.0f), t.scale[k].resize(padded, 0.0f);
    t.k0.assign(padded, 0);
    t.f0.assign(padded, 0.0f);
    t.f1.assign(padded, 1e30f);
    for (int k = 0; k < 4; ++k) t.a[k].assign(padded, k == 3 ? 1.0f : 0.0f), t.b[k].assign(padded, k == 3 ? 1.0f : 0.0f);
    for (int k = 0; k < 3; ++k) t.code_a[k].assign(padded, 0), t.code_b[k].assign(padded, 0);
    t.need_a.assign(padded, 0), t.shift.assign(padded, 0), t.need_b.assign(padded, 0);
    t.dirty.assign(padded / kPad * 2 + 1, 0);  // blocks of 4 at the narrowest
  }
  clip_ = &clip;
  clip_bytes_ = clip.bytes().data();
  invalidate();
}

void PlaybackContext::invalidate() {
  for (Tracks& t : tracks_) {
    // Stale for every frame: f1 ≤ any frame; and no key index that a new first key could follow.
    std::fill_n(t.f0.begin(), t.count, -1.0f);
    std::fill_n(t.f1.begin(), t.count, -1.0f);
    std::fill_n(t.k0.begin(), t.count, ~std::uint32_t{0} - 1);
  }
}

void PlaybackContext::sample(const CompressedClip& clip, float time, Pose& out, SimdPath path) {
  const std::size_t n = clip.joint_count();
  if (out.size() != n || out.translations.size() != n || out.scales.size() != n)
    throw Error("PlaybackContext::sample: the pose has " + std::to_string(out.size()) + " joints, the clip " +
                std::to_string(n));
  if (clip_ != &clip || clip_bytes_ != clip.bytes().data() || base_.size() != n) bind(clip);

  const std::uint32_t frames = clip.frame_count();
  const auto [x, frame] = frame_position(time, clip.sample_rate(), frames);

  std::copy(base_.rotations.begin(), base_.rotations.end(), out.rotations.begin());
  std::copy(base_.translations.begin(), base_.translations.end(), out.translations.begin());
  std::copy(base_.scales.begin(), base_.scales.end(), out.scales.begin());
  float* targets[3] = {&out.rotations[0].x, &out.translations[0].x, &out.scales[0].x};
#ifdef GESTURA_HAS_AVX2_PATH
  const bool avx2 = resolve_simd_path(path, "PlaybackContext::sample") == SimdPath::Avx2;
#else
  resolve_simd_path(path, "PlaybackContext::sample");
  const bool avx2 = false;
#endif
  for (std::size_t c = 0; c < 3; ++c) {
    Tracks& t = tracks_[c];
    if (t.count == 0) continue;
    const playback_detail::Group g{t.count, c == 0, frames, t.data.data(), t.keyset.data(), t.rank.data(), t.bits.data(),
                                   t.dropped.data(), {t.min[0].data(), t.min[1].data(), t.min[2].data()},
                                   {t.scale[0].data(), t.scale[1].data(), t.scale[2].data()}, t.joint.data(), t.f0.data(),
                                   t.f1.data(), t.k0.data(), {t.a[0].data(), t.a[1].data(), t.a[2].data(), t.a[3].data()},
                                   {t.b[0].data(), t.b[1].data(), t.b[2].data(), t.b[3].data()},
                                   {t.code_a[0].data(), t.code_a[1].data(), t.code_a[2].data()},
                                   {t.code_b[0].data(), t.code_b[1].data(), t.code_b[2].data()},
                                   t.need_a.data(), t.shift.data(), t.need_b.data(), t.dirty.data()};
#ifdef GESTURA_HAS_AVX2_PATH
    if (avx2) {
      playback_detail::sample_avx2(g, frame, x, targets[c]);
      continue;
    }
#endif
    (void)avx2;
    playback_detail::sample_portable(g, frame, x, targets[c]);
  }
}

}  // namespace gestura
