#include "gestura/face/face_action.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura::face {
namespace {

constexpr int kRampSteps = 8;

void check(const FaceAction& a, std::size_t index) {
  const auto where = [&] { return "face action " + std::to_string(index) + " ('" + std::string(a.channel) + "')"; };
  if (!std::isfinite(a.start) || !std::isfinite(a.end) || !std::isfinite(a.peak) ||
      !std::isfinite(a.ramp_in) || !std::isfinite(a.ramp_out))
    throw Error(where() + ": non-finite time, ramp or peak");
  if (a.end < a.start) throw Error(where() + ": ends before it starts");
  if (a.ramp_in < 0 || a.ramp_out < 0 || a.ramp_in + a.ramp_out > (a.end - a.start) * 1.0001f + 1e-6f)
    throw Error(where() + ": ramps are negative or longer than the action");
}

}  // namespace

float default_ramp(float duration) {
  return std::min(std::max(0.1f * duration, 0.08f), 0.5f * std::max(duration, 0.0f));
}

FaceAction make_action(std::string_view channel, float start, float end, float peak) {
  const float ramp = default_ramp(end - start);
  return FaceAction{channel, start, end, peak, ramp, ramp};
}

float sinusoidal_ramp(float x) {
  if (x <= 0.0f) return 0.0f;
  if (x >= 1.0f) return 1.0f;
  return 0.5f - 0.5f * std::cos(std::numbers::pi_v<float> * x);
}

float action_weight(const FaceAction& a, float t) {
  if (t <= a.start || t >= a.end) {
    // A zero-length ramp means the action is at full weight right at its edge.
    if (t == a.start && a.ramp_in == 0.0f && a.end > a.start) return a.peak;
    if (t == a.end && a.ramp_out == 0.0f && a.end > a.start) return a.peak;
    return 0.0f;
  }
  float w = 1.0f;
  if (a.ramp_in > 0.0f) w = std::min(w, sinusoidal_ramp((t - a.start) / a.ramp_in));
  if (a.ramp_out > 0.0f) w = std::min(w, sinusoidal_ramp((a.end - t) / a.ramp_out));
  return a.peak * w;
}

float channel_weight(std::span<const FaceAction> actions, std::string_view channel, float t) {
  float sum = 0.0f;
  for (const FaceAction& a : actions)
    if (a.channel == channel) sum += action_weight(a, t);
  return std::clamp(sum, 0.0f, 1.0f);
}

void write_face_channels(std::span<const FaceAction> actions, Clip& clip) {
  for (std::size_t i = 0; i < actions.size(); ++i) check(actions[i], i);

  std::vector<std::string_view> channels;
  for (const FaceAction& a : actions)
    if (std::find(channels.begin(), channels.end(), a.channel) == channels.end()) channels.push_back(a.channel);

  std::vector<FaceAction> mine;
  std::vector<float> times, sums;
  for (std::string_view name : channels) {
    mine.clear();
    times.clear();
    for (const FaceAction& a : actions) {
      if (a.channel != name || a.end <= a.start) continue;
      mine.push_back(a);
      for (int k = 0; k <= kRampSteps; ++k) {
        const float f = static_cast<float>(k) / kRampSteps;
        times.push_back(a.start + f * a.ramp_in);
        times.push_back(a.end - f * a.ramp_out);
      }
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](float x, float y) { return y - x < 1e-5f; }),
                times.end());

    // Each action adds itself to the keys inside its own span only: cost is the keys each action
    // covers, not keys × actions.
    sums.assign(times.size(), 0.0f);
    for (const FaceAction& a : mine) {
      const auto lo = std::lower_bound(times.begin(), times.end(), a.start) - times.begin();
      const auto hi = std::upper_bound(times.begin(), times.end(), a.end) - times.begin();
      for (auto k = lo; k < hi; ++k) sums[static_cast<std::size_t>(k)] += action_weight(a, times[static_cast<std::size_t>(k)]);
    }

    FloatTrack track;
    track.interpolation = Interpolation::Linear;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const float t = times[k], w = std::clamp(sums[k], 0.0f, 1.0f);
      // Drop keys in the middle of a flat stretch: linear interpolation reproduces them.
      const std::size_t n = track.size();
      if (n >= 2 && track.values[n - 1] == w && track.values[n - 2] == w) {
        track.times[n - 1] = t;
        continue;
      }
      track.add(t, w);
    }
    if (!track.empty()) clip.duration = std::max(clip.duration, track.times.back());
    clip.channel(std::string(name)) = std::move(track);
  }
}

}  // namespace gestura::face
