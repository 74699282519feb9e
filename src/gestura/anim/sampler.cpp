#include "gestura/anim/sampler.hpp"

namespace gestura {

Sampler::Sampler(const Clip& clip)
    : clip_(&clip),
      rotation_cursors_(clip.rotations.size(), 0),
      translation_cursors_(clip.translations.size(), 0),
      scale_cursors_(clip.scales.size(), 0),
      channel_cursors_(clip.channels.size(), 0) {}

void Sampler::sample(float time, WrapMode mode, const Pose& rest, Pose& out, std::span<float> channels) {
  const Clip& c = *clip_;
  const float t = wrap_time(time, c.duration, mode);
  const std::size_t n = rest.size();
  if (out.size() != n) out.resize(n);
  const std::size_t tracked = std::min(n, c.rotations.size());
  for (std::size_t j = 0; j < tracked; ++j) {
    const QuatTrack& r = c.rotations[j];
    out.rotations[j] = r.empty() ? rest.rotations[j] : sample_track(r, t, &rotation_cursors_[j]);
    const Vec3Track& tr = c.translations[j];
    out.translations[j] = tr.empty() ? rest.translations[j] : sample_track(tr, t, &translation_cursors_[j]);
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
