#pragma once
// A track: keys at arbitrary, strictly increasing times, and how to interpolate between them.
#include <span>
#include <vector>

#include "gestura/anim/interpolation.hpp"
#include "gestura/skeleton/rotation_order.hpp"

namespace gestura {

template <class T>
struct Track {
  std::vector<float> times;   // seconds, strictly increasing
  std::vector<T> values;      // one per time
  Interpolation interpolation = Interpolation::Linear;
  float tension = 0.0f;       // for Cardinal
  std::vector<Tcb> tcb;       // for KochanekBartels: one per key, or empty for all-zero

  bool empty() const { return times.empty(); }
  std::size_t size() const { return times.size(); }
  void add(float time, const T& value) { times.push_back(time), values.push_back(value); }
};

using FloatTrack = Track<float>;
using Vec3Track = Track<vec3>;
using QuatTrack = Track<quat>;

// Throws gestura::Error naming `what` and the key index when times are not strictly increasing,
// values are non-finite, sizes disagree, or an interpolation does not suit the value type.
void validate_track(const FloatTrack& track, const char* what);
void validate_track(const Vec3Track& track, const char* what);
void validate_track(const QuatTrack& track, const char* what);

// Normalises rotation keys and flips each onto the hemisphere of its predecessor, so interpolation
// always takes the short way and splines see a continuous curve. Idempotent.
void make_continuous(QuatTrack& track);

// Builds a rotation track from Euler-angle keys (radians, per axis) in `order`, without flips.
QuatTrack rotation_track_from_euler(std::span<const float> times, std::span<const vec3> angles,
                                    RotationOrder order, Interpolation interpolation = Interpolation::Slerp);

// Key index lookup: the last key with times[k] <= t, clamped to [0, size-2] (or 0 for one key).
// `cursor` is a hint from the previous call (forward playback moves it by O(1) amortised).
std::uint32_t find_segment(std::span<const float> times, float t, std::uint32_t cursor);

// Sampling one track at time t (clamped to the key range). `cursor` may be null.
float sample_track(const FloatTrack& track, float t, std::uint32_t* cursor = nullptr);
vec3 sample_track(const Vec3Track& track, float t, std::uint32_t* cursor = nullptr);
quat sample_track(const QuatTrack& track, float t, std::uint32_t* cursor = nullptr);

}  // namespace gestura
