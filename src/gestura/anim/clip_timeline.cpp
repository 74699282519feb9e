#include "gestura/anim/clip_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// Two keys closer than this are the same instant (a clip's own key wins over an added rest key).
constexpr float kSameTime = 1e-5f;

// A programme's clock is double: a placement's start and each key's time on the programme are
// added in double and rounded to the stored float once, so an hours-long programme drifts by no
// more than that one rounding (under half a millisecond at 3 hours).
float programme_time(double start, float local) { return static_cast<float>(start + static_cast<double>(local)); }

// The spacing of floats near `t`: two times this close are one instant at that magnitude.
float same_time_at(float t) {
  return std::max(kSameTime, 2.0f * (std::nextafter(std::abs(t), std::numeric_limits<float>::infinity()) - std::abs(t)));
}

template <class T>
void push_key(Track<T>& dest, float time, const T& value, const Tcb* tcb) {
  if (!dest.times.empty() && time <= dest.times.back() + same_time_at(time)) return;
  dest.add(time, value);
  if (!dest.tcb.empty() || tcb) {
    dest.tcb.resize(dest.times.size() - 1);
    dest.tcb.push_back(tcb ? *tcb : Tcb{});
  }
}

template <class T>
void check_track(const Track<T>& dest, const Track<T>& src, const std::string& what) {
  if (!src.empty() && !dest.empty() && (dest.interpolation != src.interpolation || dest.tension != src.tension))
    throw Error(what + ": the placed clip's interpolation differs from the timeline's");
}

template <class T>
void place_track(Track<T>& dest, const Track<T>& src, double start, float end, const T& rest) {
  if (src.empty()) return;
  if (dest.empty()) dest.interpolation = src.interpolation, dest.tension = src.tension;
  if (src.times.front() > kSameTime) push_key(dest, static_cast<float>(start), rest, nullptr);
  for (std::size_t k = 0; k < src.size(); ++k)
    push_key(dest, programme_time(start, src.times[k]), src.values[k], src.tcb.empty() ? nullptr : &src.tcb[k]);
  push_key(dest, end, rest, nullptr);
}

}  // namespace

Clip empty_timeline(const Skeleton& skeleton) {
  Clip clip;
  clip.resize_joints(skeleton.size());
  return clip;
}

void place_clip(Clip& timeline, const Clip& clip, double start, const Skeleton& skeleton) {
  const std::size_t n = skeleton.size();
  if (clip.rotations.size() != n || clip.translations.size() != n || clip.scales.size() != n)
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.rotations.size()) +
                " joints; the timeline's skeleton has " + std::to_string(n));
  if (!std::isfinite(start) || static_cast<float>(start) < timeline.duration - same_time_at(timeline.duration))
    throw Error("clip '" + clip.name + "' placed at " + std::to_string(start) + " s, before the timeline's end at " +
                std::to_string(timeline.duration) + " s");
  if (start + static_cast<double>(clip.duration) > kMaxTimelineSeconds)
    throw Error("clip '" + clip.name + "' placed at " + std::to_string(start) + " s would end past the longest timeline, " +
                std::to_string(static_cast<int>(kMaxTimelineSeconds / 3600.0)) + " hours (kMaxTimelineSeconds)");
  timeline.resize_joints(n);
  // Check everything first so that a refused clip leaves the timeline as it was.
  for (std::size_t j = 0; j < n; ++j) {
    const std::string who = "joint '" + skeleton.names[j] + "'";
    check_track(timeline.rotations[j], clip.rotations[j], who + " rotation");
    check_track(timeline.translations[j], clip.translations[j], who + " translation");
    check_track(timeline.scales[j], clip.scales[j], who + " scale");
  }
  for (std::size_t c = 0; c < clip.channels.size(); ++c)
    if (const int k = timeline.find_channel(clip.channel_names[c]); k >= 0)
      check_track(timeline.channels[static_cast<std::size_t>(k)], clip.channels[c],
                  "channel '" + clip.channel_names[c] + "'");
  const float end = programme_time(start, clip.duration);
  for (std::size_t j = 0; j < n; ++j) {
    place_track(timeline.rotations[j], clip.rotations[j], start, end, skeleton.rest_rotations[j]);
    place_track(timeline.translations[j], clip.translations[j], start, end, skeleton.rest_translations[j]);
    place_track(timeline.scales[j], clip.scales[j], start, end, skeleton.rest_scales[j]);
  }
  for (std::size_t c = 0; c < clip.channels.size(); ++c)
    place_track(timeline.channel(clip.channel_names[c]), clip.channels[c], start, end, 0.0f);
  timeline.duration = end;
}

}  // namespace gestura
