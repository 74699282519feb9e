#include "gestura/anim/sampler.hpp"

#include <algorithm>
#include <cmath>

namespace gestura {

Sampler::Sampler(const Clip& clip)
    : clip_(&clip),
      rotation_cursors_(clip.rotations.size(), 0),
      translation_cursors_(clip.translations.size(), 0),
      scale_cursors_(clip.scales.size(), 0),
      channel_cursors_(clip.channels.size(), 0) {}

namespace {

// Forward-playback fast path for a linearly keyed rotation track (the common case): cursor step,
// then nlerp on the short arc. Everything else goes through sample_track.
quat sample_rotation(const QuatTrack& track, float t, std::uint32_t& cursor) {
  const std::size_t n = track.times.size();
  if (track.interpolation != Interpolation::Linear || n < 2) return sample_track(track, t, &cursor);
  const float* times = track.times.data();
  if (t <= times[0]) return track.values[0];
  if (t >= times[n - 1]) return track.values[n - 1];
  const std::uint32_t k = find_segment(track.times, t, cursor);
  cursor = k;
  const float u = (t - times[k]) / (times[k + 1] - times[k]);
  const quat& a = track.values[k];
  const quat& b = track.values[k + 1];
  const float d = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  const float ub = d < 0.0f ? -u : u, ua = 1.0f - u;
  const float x = ua * a.x + ub * b.x, y = ua * a.y + ub * b.y, z = ua * a.z + ub * b.z, w = ua * a.w + ub * b.w;
  const float inv = 1.0f / std::sqrt(x * x + y * y + z * z + w * w);
  return quat(w * inv, x * inv, y * inv, z * inv);
}

}  // namespace

void Sampler::sample(float time, WrapMode mode, const Pose& rest, Pose& out, std::span<float> channels) {
  const Clip& c = *clip_;
  const float t = wrap_time(time, c.duration, mode);
  const std::size_t n = rest.size();
  if (out.size() != n) out.resize(n);
  const std::size_t tracked = std::min(n, c.rotations.size());
  // One pass per component: rotations are nearly always keyed, translations and scales rarely.
  for (std::size_t j = 0; j < tracked; ++j) {
    const QuatTrack& r = c.rotations[j];
    out.rotations[j] = r.empty() ? rest.rotations[j] : sample_rotation(r, t, rotation_cursors_[j]);
  }
  for (std::size_t j = 0; j < tracked; ++j) {
    const Vec3Track& tr = c.translations[j];
    out.translations[j] = tr.empty() ? rest.translations[j] : sample_track(tr, t, &translation_cursors_[j]);
  }
  for (std::size_t j = 0; j < tracked; ++j) {
    const Vec3Track& s = c.scales[j];
    out.scales[j] = s.empty() ? rest.scales[j] : sample_track(s, t, &scale_cursors_[j]);
  }
  for (std::size_t j = tracked; j < n; ++j) {
    out.rotations[j] = rest.rotations[j];
    out.translations[j] = rest.translations[j];
    out.scales[j] = rest.scales[j];
  }
  const std::size_t nc = std::min(channels.size(), c.channels.size());
  for (std::size_t i = 0; i < nc; ++i) channels[i] = sample_track(c.channels[i], t, &channel_cursors_[i]);
}

void sample_clip(const Clip& clip, float time, WrapMode mode, const Pose& rest, Pose& out,
                 std::span<float> channels) {
  Sampler sampler(clip);
  sampler.sample(time, mode, rest, out, channels);
}

}  // namespace gestura
