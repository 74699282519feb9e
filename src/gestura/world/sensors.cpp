#include "gestura/world/sensors.hpp"

#include <algorithm>

#include "gestura/world/clearance.hpp"
#include "gestura/world/trajectory.hpp"

namespace gestura {
namespace {

// Where segment a–b enters the vertical cylinder (centre c on the floor, radius r, height h):
// the fraction along the segment, or a value > 1 when it misses.
float segment_cylinder(const vec3& a, const vec3& b, const vec3& c, float r, float h) {
  const vec2 o(a.x - c.x, a.z - c.z), d(b.x - a.x, b.z - a.z);
  const float A = glm::dot(d, d), B = 2.0f * glm::dot(o, d), C = glm::dot(o, o) - r * r;
  if (A < 1e-12f) return 2.0f;
  const float disc = B * B - 4.0f * A * C;
  if (disc < 0.0f) return 2.0f;
  const float s = std::sqrt(disc);
  const float t0 = (-B - s) / (2.0f * A), t1 = (-B + s) / (2.0f * A);
  for (const float t : {t0, t1}) {
    if (t < 0.0f || t > 1.0f) continue;
    const float y = a.y + (b.y - a.y) * t;
    if (y >= c.y && y <= c.y + h) return t;
  }
  return 2.0f;
}

}  // namespace

vec3 eye_point(const ActorView& a) { return a.position + vec3(0.0f, a.height * 0.93f, 0.0f); }

bool sees_point(const Environment& env, std::span<const ActorView> actors, int self, const vec3& p, const VisionParams& vision,
                int ignore_actor, int ignore_object, std::span<const int> occluders) {
  const ActorView& me = actors[static_cast<std::size_t>(self)];
  const vec3 eye = eye_point(me);
  const vec3 d = p - eye;
  const float dist = glm::length(d);
  if (dist > vision.range) return false;
  if (dist < 1e-4f) return true;
  const float bearing = angle_difference(yaw_of(d), me.yaw);
  if (std::abs(bearing) > vision.horizontal_fov * 0.5f) return false;
  const float elevation = std::asin(std::clamp(d.y / dist, -1.0f, 1.0f));
  if (std::abs(elevation) > vision.vertical_fov * 0.5f) return false;
  auto blocks = [&](int k) {
    if (k == self || k == ignore_actor) return false;
    const ActorView& o = actors[static_cast<std::size_t>(k)];
    return segment_cylinder(eye, p, o.position, o.radius * 0.75f, o.height) < 0.999f;
  };
  if (occluders.empty()) {
    for (std::size_t k = 0; k < actors.size(); ++k)
      if (blocks(static_cast<int>(k))) return false;
  } else {
    for (int k : occluders)
      if (blocks(k)) return false;
  }
  return line_of_sight(env, eye, p, ignore_object);
}

void see(const Environment& env, std::span<const ActorView> actors, int self, std::span<const int> candidates,
         std::span<const std::pair<int, vec3>> objects, const VisionParams& vision, Percept& out) {
  out.actors.clear();
  out.objects.clear();
  const ActorView& me = actors[static_cast<std::size_t>(self)];
  const vec3 eye = eye_point(me);
  std::vector<int> all;
  if (candidates.empty()) {
    for (std::size_t k = 0; k < actors.size(); ++k) all.push_back(static_cast<int>(k));
    candidates = all;
  }
  for (const int ki : candidates) {
    const auto k = static_cast<std::size_t>(ki);
    if (ki == self) continue;
    const ActorView& o = actors[k];
    const vec3 flat = o.position - me.position;
    const float dist = glm::length(vec2(flat.x, flat.z));
    if (dist > vision.range) continue;
    // Head, chest, hips: seen when any of them is.
    bool seen = false;
    for (const float f : {0.93f, 0.72f, 0.55f}) {
      if (sees_point(env, actors, self, o.position + vec3(0.0f, o.height * f, 0.0f), vision, ki, -1, candidates)) {
        seen = true;
        break;
      }
    }
    if (!seen) continue;
    out.actors.push_back({ki, dist, angle_difference(yaw_of(o.position - me.position), me.yaw), o.signing});
  }
  std::sort(out.actors.begin(), out.actors.end(), [](const SeenActor& a, const SeenActor& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.actor < b.actor);
  });
  for (const auto& [object, point] : objects)
    if (sees_point(env, actors, self, point, vision, -1, object, candidates))
      out.objects.push_back({object, glm::length(point - eye), angle_difference(yaw_of(point - eye), me.yaw)});
}

void hear(const Environment& env, std::span<const ActorView> actors, int self, std::span<const SoundEvent> events, float hearing_range,
          Percept& out) {
  out.heard.clear();
  const vec3 ear = eye_point(actors[static_cast<std::size_t>(self)]);
  for (std::size_t e = 0; e < events.size(); ++e) {
    const SoundEvent& s = events[e];
    if (s.source_actor == self) continue;
    const float dist = glm::length(s.position - ear);
    const bool direct = line_of_sight(env, ear, s.position);
    const float range = hearing_range * s.loudness * (direct ? 1.0f : 0.5f);
    if (dist <= range) out.heard.push_back({static_cast<int>(e), dist, direct});
  }
}

void touch(const Environment& env, std::span<const ActorView> actors, int self, Percept& out) {
  out.touches.clear();
  const ActorView& me = actors[static_cast<std::size_t>(self)];
  for (std::size_t k = 0; k < actors.size(); ++k) {
    if (static_cast<int>(k) == self) continue;
    const ActorView& o = actors[k];
    const float gap = glm::length(vec2(o.position.x - me.position.x, o.position.z - me.position.z)) - (o.radius + me.radius) * 0.8f;
    if (gap < 0.0f) out.touches.push_back({static_cast<int>(k), -1, -gap});
  }
  const Clearance c = segment_clearance(env, me.position, me.position, me.height, me.radius);
  if (c.object >= 0 && c.distance < me.radius * 0.8f) out.touches.push_back({-1, c.object, me.radius * 0.8f - c.distance});
}

}  // namespace gestura
