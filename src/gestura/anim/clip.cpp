#include "gestura/anim/clip.hpp"

#include <algorithm>

#include "gestura/core/error.hpp"

namespace gestura {

void Clip::resize_joints(std::size_t n) {
  rotations.resize(n);
  translations.resize(n);
  scales.resize(n);
}

int Clip::find_channel(const std::string& channel_name) const {
  for (std::size_t i = 0; i < channel_names.size(); ++i)
    if (channel_names[i] == channel_name) return static_cast<int>(i);
  return -1;
}

FloatTrack& Clip::channel(const std::string& channel_name) {
  const int i = find_channel(channel_name);
  if (i >= 0) return channels[static_cast<std::size_t>(i)];
  channel_names.push_back(channel_name);
  channels.emplace_back();
  return channels.back();
}

float Clip::end_time() const {
  float end = 0.0f;
  auto take = [&](const auto& tracks) {
    for (const auto& tr : tracks)
      if (!tr.times.empty()) end = std::max(end, tr.times.back());
  };
  take(rotations);
  take(translations);
  take(scales);
  take(channels);
  return end;
}

void validate(const Clip& clip, const Skeleton& skeleton) {
  if (clip.rotations.size() != skeleton.size() || clip.translations.size() != skeleton.size() ||
      clip.scales.size() != skeleton.size())
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.rotations.size()) +
                " joints, skeleton has " + std::to_string(skeleton.size()));
  if (!std::isfinite(clip.duration) || clip.duration < 0)
    throw Error("clip '" + clip.name + "' has an invalid duration");
  if (clip.channel_names.size() != clip.channels.size())
    throw Error("clip '" + clip.name + "': channel names and tracks disagree");
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    const std::string who = "joint '" + skeleton.names[j] + "'";
    validate_track(clip.rotations[j], (who + " rotation").c_str());
    validate_track(clip.translations[j], (who + " translation").c_str());
    validate_track(clip.scales[j], (who + " scale").c_str());
  }
  for (std::size_t c = 0; c < clip.channels.size(); ++c)
    validate_track(clip.channels[c], ("channel '" + clip.channel_names[c] + "'").c_str());
}

float wrap_time(float t, float duration, WrapMode mode) {
  if (!std::isfinite(t)) return 0.0f;
  if (duration <= 0.0f) return 0.0f;
  switch (mode) {
    case WrapMode::Clamp: return std::clamp(t, 0.0f, duration);
    case WrapMode::Loop: {
      const float r = std::fmod(t, duration);
      return r < 0 ? r + duration : r;
    }
    case WrapMode::PingPong: {
      float r = std::fmod(t, 2 * duration);
      if (r < 0) r += 2 * duration;
      return r <= duration ? r : 2 * duration - r;
    }
  }
  return 0.0f;
}

}  // namespace gestura
