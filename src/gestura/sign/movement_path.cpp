#include "gestura/sign/movement_path.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

constexpr float kTwoPi = 2.0f * kPi;

vec3 unit(vec3 v, const char* what) {
  if (!is_finite(v)) throw Error(std::string(what) + " is not finite");
  const float n = glm::length(v);
  if (n < 1e-6f) throw Error(std::string(what) + " is zero");
  return v / n;
}

// The unit part of `v` across the unit vector `axis`; `what` names v ("arc bulge direction") and
// `to` the axis, for the error when v (nearly) lies along it.
vec3 unit_across(vec3 v, vec3 axis, const char* what, const char* to) {
  const vec3 u = unit(v, what);
  const vec3 across = u - glm::dot(u, axis) * axis;
  if (glm::length(across) < 0.1f) throw Error(std::string(what) + " is parallel to " + to);
  return glm::normalize(across);
}

void check_positive(float value, const char* what) {
  if (!std::isfinite(value) || value <= 0.0f) throw Error(std::string(what) + " must be a positive finite number");
}

// `side` made orthogonal to the unit vector d; falls back to +Y, then +X, when nearly parallel.
vec3 perpendicular(vec3 side, vec3 d) {
  for (vec3 candidate : {side, vec3{0.0f, 1.0f, 0.0f}, vec3{1.0f, 0.0f, 0.0f}}) {
    if (!is_finite(candidate)) continue;
    const vec3 p = candidate - glm::dot(candidate, d) * d;
    if (glm::length(p) > 0.1f * std::max(glm::length(candidate), 1e-6f)) return glm::normalize(p);
  }
  return vec3{0.0f, 0.0f, 1.0f};  // unreachable: +Y and +X cannot both be parallel to d
}

// Per-segment weights of a corner-stopping polyline: the time each stroke takes.
std::vector<float> segment_weights(const std::vector<vec3>& points) {
  std::vector<float> w(points.size() - 1);
  float total = 0.0f;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) total += w[k] = straight_duration(glm::distance(points[k], points[k + 1]));
  for (float& x : w) x /= total;
  return w;
}

PathSample sample_polyline(const MovementPath& path, float s) {
  const std::vector<vec3>& p = path.points;
  const std::size_t segments = p.size() - 1;
  if (path.stop_at_corners) {
    const std::vector<float> w = segment_weights(p);
    float begin = 0.0f;
    for (std::size_t k = 0; k < segments; ++k) {
      if (s <= begin + w[k] || k + 1 == segments) {
        const float u = std::clamp((s - begin) / w[k], 0.0f, 1.0f);
        const vec3 chord = p[k + 1] - p[k];
        return {p[k] + chord * minimum_jerk(u), chord * (minimum_jerk_velocity(u) / w[k])};
      }
      begin += w[k];
    }
  }
  float total = 0.0f;
  for (std::size_t k = 0; k < segments; ++k) total += glm::distance(p[k], p[k + 1]);
  if (total <= 0.0f) return {p.front(), vec3{0.0f}};
  float at = s * total;
  for (std::size_t k = 0; k < segments; ++k) {
    const vec3 chord = p[k + 1] - p[k];
    const float len = glm::length(chord);
    if (at <= len || k + 1 == segments) {
      if (len <= 0.0f) return {p[k], vec3{0.0f}};
      return {p[k] + chord * std::min(at / len, 1.0f), chord * (total / len)};
    }
    at -= len;
  }
  return {p.back(), vec3{0.0f}};
}

PathSample sample_base(const MovementPath& path, float s) {
  switch (path.kind) {
    case PathKind::Straight:
      return {path.direction * (path.length * s), path.direction * path.length};
    case PathKind::Arc: {
      const float L = path.length, h = path.bulge_ratio * L;
      const float R = (0.25f * L * L + h * h) / (2.0f * h);
      const float alpha = std::atan2(0.5f * L, R - h);
      const float phi = -alpha + 2.0f * alpha * s;
      const vec3 mid = path.direction * (0.5f * L);
      const vec3 centre = mid - (R - h) * path.bulge;
      const vec3 n = path.bulge, d = path.direction;
      return {centre + R * (std::cos(phi) * n + std::sin(phi) * d),
              2.0f * alpha * R * (-std::sin(phi) * n + std::cos(phi) * d)};
    }
    case PathKind::Circle: {
      const vec3 e1 = path.start_radial, e2 = glm::cross(path.axis, e1);
      const float theta = kTwoPi * path.turns * s, r = path.radius;
      return {r * ((std::cos(theta) - 1.0f) * e1 + std::sin(theta) * e2),
              kTwoPi * path.turns * r * (-std::sin(theta) * e1 + std::cos(theta) * e2)};
    }
    case PathKind::Polyline:
      return sample_polyline(path, s);
  }
  return {};
}

vec3 chord_of(const MovementPath& path) { return sample_base(path, 1.0f).position; }

// Triangle wave starting at 0 going up, period 1, range [−1, 1], and its slope.
float triangle(float x) {
  const float f = x - std::floor(x);
  if (f < 0.25f) return 4.0f * f;
  if (f < 0.75f) return 2.0f - 4.0f * f;
  return 4.0f * f - 4.0f;
}
float triangle_slope(float x) {
  const float f = x - std::floor(x);
  return (f < 0.25f || f >= 0.75f) ? 4.0f : -4.0f;
}

bool point_to_point(const MovementPath& path) {
  return path.modifier == PathModifier::None && path.kind != PathKind::Circle;
}

}  // namespace

float straight_length(MovementSize size) {
  switch (size) {
    case MovementSize::Small: return 0.08f;
    case MovementSize::Normal: return 0.15f;
    case MovementSize::Large: return 0.25f;
  }
  return 0.15f;
}

float circle_radius(MovementSize size) {
  switch (size) {
    case MovementSize::Small: return 0.03f;
    case MovementSize::Normal: return 0.05f;
    case MovementSize::Large: return 0.08f;
  }
  return 0.05f;
}

MovementPath straight_path(Direction direction, MovementSize size) {
  return straight_path(direction_vector(direction), straight_length(size));
}

MovementPath straight_path(vec3 direction, float length) {
  check_positive(length, "straight movement length");
  MovementPath path;
  path.kind = PathKind::Straight;
  path.direction = unit(direction, "straight movement direction");
  path.length = length;
  return path;
}

MovementPath arc_path(Direction direction, Direction bulge_toward, MovementSize size) {
  return arc_path(direction_vector(direction), straight_length(size), direction_vector(bulge_toward));
}

MovementPath arc_path(vec3 direction, float length, vec3 bulge_toward, float bulge_ratio) {
  check_positive(length, "arc length");
  if (!std::isfinite(bulge_ratio) || bulge_ratio <= 0.0f || bulge_ratio > 0.5f)
    throw Error("arc bulge ratio must be in (0, 0.5]");
  MovementPath path;
  path.kind = PathKind::Arc;
  path.direction = unit(direction, "arc direction");
  path.bulge = unit_across(bulge_toward, path.direction, "arc bulge direction", "the movement direction");
  path.length = length;
  path.bulge_ratio = bulge_ratio;
  return path;
}

MovementPath circle_path(vec3 axis, float radius, vec3 start_radial, float turns) {
  check_positive(radius, "circle radius");
  check_positive(turns, "circle turns");
  if (turns > 16.0f) throw Error("circle turns must be at most 16");
  MovementPath path;
  path.kind = PathKind::Circle;
  path.axis = unit(axis, "circle axis");
  path.start_radial = unit_across(start_radial, path.axis, "circle start direction", "its axis");
  path.radius = radius;
  path.turns = turns;
  return path;
}

MovementPath circle_in_plane(BodyPlane plane, Rotation rotation, MovementSize size) {
  // Clockwise as seen looking along v is a positive rotation about v.
  vec3 view, start;
  switch (plane) {
    case BodyPlane::Frontal: view = {0, 0, 1}; start = {0, -1, 0}; break;
    case BodyPlane::Horizontal: view = {0, -1, 0}; start = {0, 0, -1}; break;
    case BodyPlane::Sagittal: view = {1, 0, 0}; start = {0, -1, 0}; break;
  }
  return circle_path(rotation == Rotation::Clockwise ? view : -view, circle_radius(size), start);
}

MovementPath polyline_path(std::vector<vec3> points, bool stop_at_corners) {
  if (points.size() < 2) throw Error("polyline movement needs at least two points");
  if (points.size() > 1024) throw Error("polyline movement has more than 1024 points");
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!is_finite(points[k])) throw Error("polyline point " + std::to_string(k) + " is not finite");
  MovementPath path;
  path.kind = PathKind::Polyline;
  const vec3 origin = points.front();
  for (vec3& p : points) p -= origin;
  path.points = std::move(points);
  path.stop_at_corners = stop_at_corners;
  if (stop_at_corners)
    for (std::size_t k = 0; k + 1 < path.points.size(); ++k)
      if (glm::distance(path.points[k], path.points[k + 1]) <= 0.0f)
        throw Error("polyline point " + std::to_string(k + 1) + " repeats the previous point");
  return path;
}

MovementPath with_modifier(MovementPath path, PathModifier modifier, float amplitude, int cycles, vec3 side) {
  if (modifier == PathModifier::None) {
    path.modifier = modifier;
    return path;
  }
  if (path.kind == PathKind::Circle) throw Error("wavy, zigzag and spiral modifiers need a path with a chord, not a circle");
  check_positive(amplitude, "modifier amplitude");
  if (cycles < 1 || cycles > 32) throw Error("modifier cycles must be in 1..32");
  const vec3 chord = chord_of(path);
  if (glm::length(chord) < 1e-4f) throw Error("modifier needs a path whose end differs from its start");
  path.modifier = modifier;
  path.modifier_amplitude = amplitude;
  path.modifier_cycles = cycles;
  path.modifier_axis = perpendicular(side, glm::normalize(chord));
  path.modifier_binormal = glm::cross(glm::normalize(chord), path.modifier_axis);
  return path;
}

MovementPath with_modifier(MovementPath path, PathModifier modifier) {
  switch (modifier) {
    case PathModifier::None: return with_modifier(std::move(path), modifier, 0.0f, 0);
    case PathModifier::Wavy:
    case PathModifier::Zigzag: return with_modifier(std::move(path), modifier, 0.02f, 3);
    case PathModifier::Spiral: return with_modifier(std::move(path), modifier, 0.025f, 2);
  }
  return path;
}

PathSample sample_path(const MovementPath& path, float s) {
  s = std::isfinite(s) ? std::clamp(s, 0.0f, 1.0f) : 0.0f;
  PathSample out = sample_base(path, s);
  if (path.modifier == PathModifier::None) return out;
  const float a = path.modifier_amplitude, k = static_cast<float>(path.modifier_cycles);
  const vec3 m = path.modifier_axis;
  switch (path.modifier) {
    case PathModifier::None: break;
    case PathModifier::Wavy:
      out.position += a * std::sin(kTwoPi * k * s) * m;
      out.tangent += a * kTwoPi * k * std::cos(kTwoPi * k * s) * m;
      break;
    case PathModifier::Zigzag:
      out.position += a * triangle(k * s) * m;
      out.tangent += a * k * triangle_slope(k * s) * m;
      break;
    case PathModifier::Spiral: {
      const vec3 e = path.modifier_binormal;
      const float theta = kTwoPi * k * s;
      out.position += a * ((std::cos(theta) - 1.0f) * m + std::sin(theta) * e);
      out.tangent += a * kTwoPi * k * (-std::sin(theta) * m + std::cos(theta) * e);
      break;
    }
  }
  return out;
}

vec3 path_end(const MovementPath& path) { return sample_path(path, 1.0f).position; }

float path_length(const MovementPath& path) {
  constexpr int kPieces = 512;
  float total = 0.0f;
  vec3 previous = sample_path(path, 0.0f).position;
  for (int k = 1; k <= kPieces; ++k) {
    const vec3 p = sample_path(path, static_cast<float>(k) / kPieces).position;
    total += glm::distance(previous, p);
    previous = p;
  }
  return total;
}

MovementPath mirror_left_right(MovementPath path) {
  auto flip = [](vec3& v) { v.x = -v.x; };
  flip(path.direction);
  flip(path.bulge);
  flip(path.start_radial);
  flip(path.modifier_axis);
  flip(path.modifier_binormal);
  for (vec3& p : path.points) flip(p);
  // A mirror reverses the sense of rotation: the mirrored axis is the flipped axis negated.
  flip(path.axis);
  path.axis = -path.axis;
  return path;
}

VelocityProfile default_profile(const MovementPath& path) {
  if (path.kind == PathKind::Polyline && path.stop_at_corners && path.modifier == PathModifier::None)
    return VelocityProfile::Linear;
  return point_to_point(path) ? VelocityProfile::MinimumJerk : VelocityProfile::ConstantRamped;
}

Movement make_movement(MovementPath path, MovementSpeed speed, int passes, RepeatMode repeat) {
  if (passes < 1 || passes > 64) throw Error("movement repetitions must be in 1..64");
  float pass_duration = 0.0f;
  if (path.kind == PathKind::Polyline && path.stop_at_corners && path.modifier == PathModifier::None) {
    for (std::size_t k = 0; k + 1 < path.points.size(); ++k)
      pass_duration += straight_duration(glm::distance(path.points[k], path.points[k + 1]), speed);
  } else {
    const float length = path_length(path);
    pass_duration = point_to_point(path) ? straight_duration(length, speed) : continuous_duration(length, speed);
  }
  Movement m;
  m.profile = default_profile(path);
  m.path = std::move(path);
  m.passes = passes;
  m.repeat = repeat;
  const float returns = repeat == RepeatMode::FromStart ? 0.5f * static_cast<float>(passes - 1) : 0.0f;
  m.duration = pass_duration * (static_cast<float>(passes) + returns);
  return m;
}

MotionSample sample(const Movement& movement, float time) {
  const int n = std::max(movement.passes, 1);
  const bool returns = movement.repeat == RepeatMode::FromStart;
  const float units = static_cast<float>(n) + (returns ? 0.5f * static_cast<float>(n - 1) : 0.0f);
  if (!(movement.duration > 0.0f)) return {sample_path(movement.path, time > 0.0f ? 1.0f : 0.0f).position, vec3{0.0f}};
  const float t = std::isfinite(time) ? std::clamp(time / movement.duration, 0.0f, 1.0f) : 0.0f;
  const float per_unit = units / movement.duration;  // units per second
  float u = t * units;
  const vec3 end = path_end(movement.path);
  for (int pass = 0; pass < n; ++pass) {
    const bool last = pass + 1 == n;
    if (u <= 1.0f || last) {
      const float local = std::clamp(u, 0.0f, 1.0f);
      const bool backward = movement.repeat == RepeatMode::Reverse && pass % 2 == 1;
      const float progress = profile_progress(movement.profile, local);
      const float rate = profile_velocity(movement.profile, local);
      const PathSample ps = sample_path(movement.path, backward ? 1.0f - progress : progress);
      const vec3 offset = movement.repeat == RepeatMode::Continue ? static_cast<float>(pass) * end : vec3{0.0f};
      return {offset + ps.position, ps.tangent * ((backward ? -rate : rate) * per_unit)};
    }
    u -= 1.0f;
    if (returns) {
      if (u <= 0.5f) {
        const float local = u / 0.5f;
        return {end * (1.0f - minimum_jerk(local)), -end * (minimum_jerk_velocity(local) * 2.0f * per_unit)};
      }
      u -= 0.5f;
    }
  }
  return {end, vec3{0.0f}};
}

}  // namespace gestura
