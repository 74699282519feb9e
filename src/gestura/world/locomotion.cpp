#include "gestura/world/locomotion.hpp"

#include <algorithm>

#include "gestura/world/clearance.hpp"

namespace gestura {
namespace {

std::size_t segment_of(const PathTrack& t, float s) {
  if (t.points.size() < 2) return 0;
  const auto it = std::upper_bound(t.lengths.begin(), t.lengths.end(), s);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - t.lengths.begin()));
  return std::min(i, t.points.size() - 1) - 1;
}

vec3 left_of(const vec3& t) { return {t.z, 0.0f, -t.x}; }

// Speeds along the track every few centimetres: limited by the bends, starting from the walker's
// speed, reaching 0 at the end, within the acceleration limits.
constexpr float kProfileStep = 0.05f;

float limit_at(const std::vector<float>& v, float s) {
  if (v.empty()) return 0.0f;
  const float x = std::max(0.0f, s / kProfileStep);
  const auto i = static_cast<std::size_t>(x);
  if (i + 1 >= v.size()) return v.back();
  return glm::mix(v[i], v[i + 1], x - static_cast<float>(i));
}

std::vector<float> profile_of(const PathTrack& t, const LocomotionParams& p) {
  const float total = t.total();
  const auto n = static_cast<std::size_t>(std::ceil(total / kProfileStep)) + 1;
  std::vector<float> v(n, p.speed);
  for (std::size_t i = 0; i < n; ++i) {
    const float at = static_cast<float>(i) * kProfileStep;
    const float k = t.curvature_at(at);
    if (k > 1e-4f) v[i] = std::min(v[i], std::sqrt(p.lateral_acceleration / k));
    // Stairs and ramps: slower, by the rise over the half metre around.
    const float rise = std::abs(t.ground_at(at + 0.25f) - t.ground_at(at - 0.25f)) / 0.5f;
    v[i] = std::min(v[i], p.speed / (1.0f + p.climb_slowing * rise));
  }
  v.back() = 0.0f;
  for (std::size_t i = n - 1; i-- > 0;)  // arriving: v² ≤ v_next² + 2·a·ds
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2.0f * p.deceleration * kProfileStep));
  return v;
}

}  // namespace

vec3 PathTrack::point_at(float s) const {
  if (points.empty()) return vec3(0.0f);
  if (points.size() == 1) return points[0];
  s = std::clamp(s, 0.0f, total());
  const std::size_t i = segment_of(*this, s);
  const float len = lengths[i + 1] - lengths[i];
  const float f = len > 0.0f ? (s - lengths[i]) / len : 0.0f;
  return glm::mix(points[i], points[i + 1], f);
}

vec3 PathTrack::tangent_at(float s) const {
  if (points.size() < 2) return vec3(0, 0, 1);
  s = std::clamp(s, 0.0f, total());
  std::size_t i = segment_of(*this, s);
  // Skip zero-length segments.
  for (std::size_t k = i; k + 1 < points.size(); ++k) {
    vec3 d = points[k + 1] - points[k];
    d.y = 0.0f;
    if (glm::length(d) > 1e-6f) return glm::normalize(d);
  }
  for (std::size_t k = i + 1; k-- > 0;) {
    vec3 d = points[k + 1] - points[k];
    d.y = 0.0f;
    if (glm::length(d) > 1e-6f) return glm::normalize(d);
  }
  return vec3(0, 0, 1);
}

float PathTrack::curvature_at(float s) const {
  constexpr float w = 0.25f;
  const vec3 a = tangent_at(s - w), b = tangent_at(s + w);
  const float turn = std::abs(angle_difference(yaw_of(b), yaw_of(a)));
  const float span = std::min(s + w, total()) - std::max(s - w, 0.0f);
  return span > 1e-4f ? turn / span : 0.0f;
}

float PathTrack::ground_at(float s) const {
  if (ground.empty()) return point_at(s).y;
  const float x = std::clamp(s, 0.0f, total()) / 0.1f;
  const auto i = static_cast<std::size_t>(x);
  if (i + 1 >= ground.size()) return ground.back();
  return glm::mix(ground[i], ground[i + 1], x - static_cast<float>(i));
}

float PathTrack::clearance_at(float s) const {
  if (clearances.empty()) return 0.0f;
  const std::size_t i = segment_of(*this, std::clamp(s, 0.0f, total()));
  return std::min(clearances[i], clearances[std::min(i + 1, clearances.size() - 1)]);
}

PathTrack make_track(std::span<const vec3> points, const Environment* env, float radius, float body_height) {
  PathTrack t;
  for (const vec3& p : points) {
    if (!t.points.empty() && glm::length(vec2(p.x - t.points.back().x, p.z - t.points.back().z)) < 1e-5f) continue;
    t.points.push_back(p);
  }
  if (t.points.size() == 1) t.points.push_back(t.points[0]);
  t.lengths.assign(t.points.size(), 0.0f);
  for (std::size_t i = 1; i < t.points.size(); ++i)
    t.lengths[i] = t.lengths[i - 1] + glm::length(vec2(t.points[i].x - t.points[i - 1].x, t.points[i].z - t.points[i - 1].z));
  t.clearances.assign(t.points.size(), 0.0f);
  if (env) {
    // The floor along the track, found below it (a straight path up stairs runs above the treads).
    for (float s = 0.0f;; s += 0.1f) {
      const vec3 p = t.point_at(s);
      const float previous = t.ground.empty() ? p.y : t.ground.back();
      const auto g = ground_below(*env, vec3(p.x, std::max(p.y, previous) + env->max_climb + 0.1f, p.z), 2.0f * env->max_climb + 0.5f);
      t.ground.push_back(g ? g->height : p.y);
      if (s >= t.total()) break;
    }
  }
  if (env)
    for (std::size_t i = 0; i < t.points.size(); ++i) {
      // The room beside the path: measured at the segments' midpoints too, so a wall along a long
      // segment is seen.
      float room = segment_clearance(*env, t.points[i], t.points[i], body_height, radius + 1.0f).distance;
      if (i + 1 < t.points.size())
        room = std::min(room, segment_clearance(*env, t.points[i], t.points[i + 1], body_height, radius + 1.0f).distance);
      t.clearances[i] = std::max(0.0f, room - radius);
    }
  return t;
}

void Locomotor::follow(PathTrack path, std::optional<float> facing_at_end) {
  track = std::move(path);
  speed_limits.clear();
  progress = 0.0f;
  offset = 0.0f;
  final_yaw = facing_at_end;
  turn_goal.reset();
  if (track.total() < 0.02f) {
    mode = final_yaw ? Mode::TurnLast : Mode::Idle;
    turn_goal = final_yaw;
    return;
  }
  mode = Mode::Walk;
}

void Locomotor::turn_to(float goal) {
  track = PathTrack{};
  speed_limits.clear();
  turn_goal = goal;
  final_yaw.reset();
  mode = Mode::TurnLast;
}

void Locomotor::stop() {
  mode = Mode::Idle;
  speed = 0.0f;
  turn_goal.reset();
}

void step_locomotor(Locomotor& w, const LocomotionParams& p, float dt, float speed_scale, float desired_offset) {
  auto turn_toward = [&](float goal, float rate) {
    const float d = angle_difference(goal, w.yaw);
    const float step = rate * dt;
    if (std::abs(d) <= step) {
      w.yaw = goal;
      return true;
    }
    w.yaw += d > 0.0f ? step : -step;
    return false;
  };
  switch (w.mode) {
    case Locomotor::Mode::Idle: w.speed = 0.0f; return;
    case Locomotor::Mode::TurnFirst:
    case Locomotor::Mode::TurnLast: {
      w.speed = 0.0f;
      if (!w.turn_goal || turn_toward(*w.turn_goal, p.turn_in_place_rate)) {
        if (w.mode == Locomotor::Mode::TurnFirst) w.mode = Locomotor::Mode::Walk, w.turn_goal.reset();
        else w.stop();
      }
      return;
    }
    case Locomotor::Mode::Walk: break;
  }
  const float total = w.track.total();
  // Setting off toward a way that lies behind: turn on the spot first.
  if (w.progress == 0.0f && w.speed == 0.0f) {
    const float first = yaw_of(w.track.tangent_at(0.0f));
    if (std::abs(angle_difference(first, w.yaw)) > p.turn_in_place_above) {
      w.mode = Locomotor::Mode::TurnFirst;
      w.turn_goal = first;
      return;
    }
  }
  // Speed: the profile's limit ahead (bends, the stop at the end), reached within the acceleration.
  if (w.speed_limits.empty()) w.speed_limits = profile_of(w.track, p);
  float limit = std::min(limit_at(w.speed_limits, w.progress), p.speed * std::clamp(speed_scale, 0.0f, 1.0f));
  // Never stall short of the goal: the last centimetres at a creep.
  const float remaining = total - w.progress;
  if (speed_scale > 0.5f && remaining > 0.0f) limit = std::max(limit, std::min(0.08f, remaining / dt));
  if (w.speed < limit) w.speed = std::min(limit, w.speed + p.acceleration * dt);
  else w.speed = std::max(limit, w.speed - std::max(p.deceleration, (w.speed - limit) / 0.25f) * dt);
  w.progress = std::min(total, w.progress + w.speed * dt);
  // Sideways shift, kept within the room beside the track.
  const float room = w.track.clearance_at(w.progress);
  const float goal = std::clamp(desired_offset, -room, room);
  const float max_shift = 0.6f * dt;
  w.offset += std::clamp(goal - w.offset, -max_shift, max_shift);
  w.offset = std::clamp(w.offset, -room, room);
  const vec3 t = w.track.tangent_at(w.progress);
  const vec3 previous = w.position;
  w.position = w.track.point_at(w.progress) + left_of(t) * w.offset;
  w.position.y = w.track.ground_at(w.progress);
  vec3 moved = w.position - previous;
  moved.y = 0.0f;
  const float heading_goal = glm::length(moved) > 1e-4f ? yaw_of(moved) : yaw_of(t);
  turn_toward(heading_goal, p.turn_rate);
  if (w.progress >= total - 1e-4f) {
    w.speed = 0.0f;
    w.offset = 0.0f;
    if (w.final_yaw && std::abs(angle_difference(*w.final_yaw, w.yaw)) > deg(2.0f)) {
      w.mode = Locomotor::Mode::TurnLast;
      w.turn_goal = w.final_yaw;
    } else {
      w.stop();
    }
  }
}

RootTrajectory follow_path(std::span<const vec3> path, float start_yaw, std::optional<float> end_yaw, const LocomotionParams& params,
                           float dt, float hold, const Environment* env) {
  RootTrajectory out;
  out.dt = dt;
  Locomotor w;
  w.position = path.empty() ? vec3(0.0f) : path.front();
  w.yaw = start_yaw;
  const int held = static_cast<int>(std::round(hold / dt));
  for (int i = 0; i < held; ++i) out.push(w.position, w.yaw);
  if (path.size() >= 2) {
    w.follow(make_track(path, env), end_yaw);
    for (int guard = 0; w.busy() && guard < 200000; ++guard) {
      step_locomotor(w, params, dt);
      out.push(w.position, w.yaw);
    }
  }
  for (int i = 0; i < held; ++i) out.push(w.position, w.yaw);
  return out;
}

}  // namespace gestura
