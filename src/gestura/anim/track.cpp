#include "gestura/anim/track.hpp"

#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

bool finite(float v) { return std::isfinite(v); }
bool finite(const vec3& v) { return is_finite(v); }
bool finite(const quat& q) { return is_finite(q); }

template <class T>
void validate_common(const Track<T>& track, const char* what) {
  if (track.values.size() != track.times.size())
    throw Error(std::string(what) + ": " + std::to_string(track.times.size()) + " times but " +
                std::to_string(track.values.size()) + " values");
  if (!track.tcb.empty() && track.tcb.size() != track.times.size())
    throw Error(std::string(what) + ": TCB parameters must be given for every key");
  for (std::size_t k = 0; k < track.times.size(); ++k) {
    if (!std::isfinite(track.times[k]) || !finite(track.values[k]))
      throw Error(std::string(what) + ": key " + std::to_string(k) + " is not finite");
    if (k > 0 && !(track.times[k] > track.times[k - 1]))
      throw Error(std::string(what) + ": key " + std::to_string(k) + " time " + std::to_string(track.times[k]) +
                  " does not increase");
  }
}

}  // namespace

void validate_track(const FloatTrack& track, const char* what) {
  validate_common(track, what);
  if (track.interpolation == Interpolation::Slerp || track.interpolation == Interpolation::Squad)
    throw Error(std::string(what) + ": slerp/squad apply to rotations only");
}
void validate_track(const Vec3Track& track, const char* what) {
  validate_common(track, what);
  if (track.interpolation == Interpolation::Slerp || track.interpolation == Interpolation::Squad)
    throw Error(std::string(what) + ": slerp/squad apply to rotations only");
}
void validate_track(const QuatTrack& track, const char* what) {
  validate_common(track, what);
  for (std::size_t k = 0; k < track.values.size(); ++k)
    if (glm::length(track.values[k]) < 1e-6f)
      throw Error(std::string(what) + ": key " + std::to_string(k) + " is a zero quaternion");
}

void make_continuous(QuatTrack& track) {
  for (std::size_t k = 0; k < track.values.size(); ++k) {
    quat q = glm::normalize(track.values[k]);
    if (k > 0 && glm::dot(q, track.values[k - 1]) < 0) q = -q;
    track.values[k] = q;
  }
}

QuatTrack rotation_track_from_euler(std::span<const float> times, std::span<const vec3> angles,
                                    RotationOrder order, Interpolation interpolation) {
  QuatTrack track;
  track.interpolation = interpolation;
  track.times.assign(times.begin(), times.end());
  track.values.reserve(angles.size());
  for (const vec3& a : angles) track.values.push_back(euler_to_quat(a, order));
  make_continuous(track);
  return track;
}

std::uint32_t find_segment(std::span<const float> times, float t, std::uint32_t cursor) {
  const auto n = static_cast<std::uint32_t>(times.size());
  if (n < 2) return 0;
  const std::uint32_t last = n - 2;
  if (cursor > last) cursor = last;
  std::uint32_t lo = 0, hi = cursor;
  if (t >= times[cursor]) {
    // Forward playback: usually zero or one step; a long jump ahead falls back to bisection.
    for (int step = 0; step < 4; ++step) {
      if (cursor >= last || t < times[cursor + 1]) return cursor;
      ++cursor;
    }
    lo = cursor;
    hi = last;
  }
  // Bisection for the last key with times[k] <= t in [lo, hi].
  while (lo < hi) {
    const std::uint32_t mid = (lo + hi + 1) / 2;
    if (times[mid] <= t) lo = mid; else hi = mid - 1;
  }
  return lo;
}

namespace {

template <class T>
T sample_hermite(const Track<T>& track, std::uint32_t k, float u) {
  const std::size_t n = track.times.size();
  const std::size_t k0 = k > 0 ? k - 1 : k, k3 = k + 2 < n ? k + 2 : k + 1;
  const T &p0 = track.values[k0], &p1 = track.values[k], &p2 = track.values[k + 1], &p3 = track.values[k3];
  const float t0 = track.times[k0], t1 = track.times[k], t2 = track.times[k + 1], t3 = track.times[k3];
  Tcb tcb1, tcb2;
  if (track.interpolation == Interpolation::KochanekBartels && !track.tcb.empty()) {
    tcb1 = track.tcb[k];
    tcb2 = track.tcb[k + 1];
  } else if (track.interpolation == Interpolation::Cardinal) {
    tcb1.tension = tcb2.tension = track.tension;
  }
  T in1, out1, in2, out2;
  kb_tangents(p0, p1, p2, t1 - t0, t2 - t1, tcb1, in1, out1);
  kb_tangents(p1, p2, p3, t2 - t1, t3 - t2, tcb2, in2, out2);
  // At the first/last key there is no previous/next segment: the one-sided difference is used.
  if (k0 == k) kb_tangents(p1, p1, p2, 0.0f, t2 - t1, tcb1, in1, out1);
  if (k3 == k + 1) kb_tangents(p1, p2, p2, t2 - t1, 0.0f, tcb2, in2, out2);
  return hermite(p1, out1, p2, in2, u);
}

template <class T>
T sample_vector(const Track<T>& track, float t, std::uint32_t* cursor) {
  const std::size_t n = track.times.size();
  if (n == 0) return T(0);
  if (n == 1 || t <= track.times[0]) return track.values[0];
  if (t >= track.times[n - 1]) return track.values[n - 1];
  const std::uint32_t k = find_segment(track.times, t, cursor ? *cursor : 0);
  if (cursor) *cursor = k;
  const float u = (t - track.times[k]) / (track.times[k + 1] - track.times[k]);
  switch (track.interpolation) {
    case Interpolation::Step: return track.values[k];
    case Interpolation::Cardinal:
    case Interpolation::CatmullRom:
    case Interpolation::KochanekBartels: return sample_hermite(track, k, u);
    default: return track.values[k] + (track.values[k + 1] - track.values[k]) * u;
  }
}

}  // namespace

float sample_track(const FloatTrack& track, float t, std::uint32_t* cursor) { return sample_vector(track, t, cursor); }
vec3 sample_track(const Vec3Track& track, float t, std::uint32_t* cursor) { return sample_vector(track, t, cursor); }

quat sample_track(const QuatTrack& track, float t, std::uint32_t* cursor) {
  const std::size_t n = track.times.size();
  if (n == 0) return quat(1, 0, 0, 0);
  if (n == 1 || t <= track.times[0]) return track.values[0];
  if (t >= track.times[n - 1]) return track.values[n - 1];
  const std::uint32_t k = find_segment(track.times, t, cursor ? *cursor : 0);
  if (cursor) *cursor = k;
  const float u = (t - track.times[k]) / (track.times[k + 1] - track.times[k]);
  const quat& a = track.values[k];
  const quat& b = track.values[k + 1];
  switch (track.interpolation) {
    case Interpolation::Step: return a;
    case Interpolation::Slerp: return glm::slerp(a, b, u);
    case Interpolation::Squad:
    case Interpolation::CatmullRom:
    case Interpolation::Cardinal:
    case Interpolation::KochanekBartels: {
      // Rotation splines are squad through the keys (the spherical analogue of Catmull-Rom).
      const quat& prev = track.values[k > 0 ? k - 1 : k];
      const quat& next = track.values[k + 2 < n ? k + 2 : k + 1];
      return squad(a, b, squad_control(prev, a, b), squad_control(a, b, next), u);
    }
    default: return nlerp(a, b, u);
  }
}

}  // namespace gestura
