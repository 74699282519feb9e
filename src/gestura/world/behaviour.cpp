#include "gestura/world/behaviour.hpp"

#include <algorithm>

#include "gestura/world/trajectory.hpp"

namespace gestura {
namespace {

vec3 head_of(const ActorView& a) { return eye_point(a); }

}  // namespace

AvoidIntent decide_avoidance(std::span<const ActorView> actors, int self, const Percept& percept, const vec3& direction, float offset);

LookIntent choose_look(std::span<const ActorView> actors, int self, const Percept& percept, std::span<const SoundEvent> events,
                       const LookInputs& in, LookState& state) {
  LookIntent out;
  if (in.scripted) {
    out.point = *in.scripted;
    out.actor = in.scripted_actor;
    out.weight = 1.0f;
    out.why = "script";
    return out;
  }
  if (in.self_signing && in.addressee >= 0) {
    out.actor = in.addressee;
    out.point = head_of(actors[static_cast<std::size_t>(in.addressee)]);
    out.weight = 0.8f;  // the signing keeps some of its own head movement
    out.why = "addressee";
    return out;
  }
  // Whoever is seen signing: stay with the one already watched while they sign and are seen.
  bool held_seen = false;
  int best = -1;
  float best_bearing = 1e30f;
  for (const SeenActor& s : percept.actors) {
    if (!s.signing || s.actor == self) continue;
    if (s.actor == state.held_signer) held_seen = true;
    if (std::abs(s.bearing) < best_bearing) best_bearing = std::abs(s.bearing), best = s.actor;
  }
  if (!held_seen) state.held_signer = best;
  if (state.held_signer >= 0 && !in.self_signing) {
    out.actor = state.held_signer;
    out.point = head_of(actors[static_cast<std::size_t>(state.held_signer)]);
    out.weight = 1.0f;
    out.why = "signer";
    return out;
  }
  // A sound just heard: a glance toward it.
  for (const Heard& h : percept.heard) {
    const SoundEvent& e = events[static_cast<std::size_t>(h.event)];
    if (in.now - e.time < 0.2f) state.glance_until = in.now + 1.5f, state.glance_point = e.position;
  }
  if (in.now < state.glance_until) {
    out.point = state.glance_point;
    out.weight = 0.9f;
    out.why = "sound";
  }
  return out;
}

AvoidIntent avoid_others(std::span<const ActorView> actors, int self, const Percept& percept, const vec3& direction, float offset,
                         AvoidState& state) {
  AvoidIntent out = decide_avoidance(actors, self, percept, direction, offset);
  const ActorView& me = actors[static_cast<std::size_t>(self)];
  // Keep out of the way of the walker avoided until it is behind or well aside.
  if (state.threat >= 0) {
    const ActorView& o = actors[static_cast<std::size_t>(state.threat)];
    const vec3 rel = o.position - me.position;
    const bool passed = glm::dot(rel, direction) < -0.2f || glm::length(vec2(rel.x, rel.z)) > 4.0f;
    if (passed) state = AvoidState{};
    else if (out.threat < 0 || out.threat == state.threat) {
      out.threat = state.threat;
      if (std::abs(state.offset) > std::abs(out.offset)) out.offset = state.offset;
      out.speed_scale = std::min(out.speed_scale, std::max(state.speed_scale, 0.5f));
    }
  }
  if (out.threat >= 0 && (state.threat < 0 || out.threat == state.threat)) {
    state.threat = out.threat;
    if (std::abs(out.offset) >= std::abs(state.offset)) state.offset = out.offset;
    state.speed_scale = out.speed_scale;
  }
  return out;
}

AvoidIntent decide_avoidance(std::span<const ActorView> actors, int self, const Percept& percept, const vec3& direction, float offset) {
  AvoidIntent out;
  out.offset = 0.0f;
  const ActorView& me = actors[static_cast<std::size_t>(self)];
  const vec3 left(direction.z, 0.0f, -direction.x);
  // The most imminent conflict among the walkers this actor perceives (seen or touching).
  float soonest = 1e30f;
  for (const SeenActor& s : percept.actors) {
    if (s.distance > 6.0f) continue;
    const ActorView& o = actors[static_cast<std::size_t>(s.actor)];
    const vec2 p(o.position.x - me.position.x, o.position.z - me.position.z);
    const vec2 v(o.velocity.x - me.velocity.x, o.velocity.z - me.velocity.z);
    const float vv = glm::dot(v, v);
    const float tca = vv > 1e-6f ? std::clamp(-glm::dot(p, v) / vv, 0.0f, 4.0f) : 0.0f;
    const float miss = glm::length(p + v * tca);
    const float needed = me.radius + o.radius + 0.15f;
    if (miss >= needed || tca >= 4.0f) continue;
    // Ahead only: what is behind avoids us.
    if (glm::dot(vec2(direction.x, direction.z), p) < -0.2f) continue;
    if (tca < soonest || (tca == soonest && s.actor < out.threat)) soonest = tca, out.threat = s.actor;
  }
  for (const Touch& t : percept.touches)
    if (t.actor >= 0 && out.threat < 0) out.threat = t.actor, soonest = 0.0f;
  if (out.threat < 0) return out;
  const ActorView& o = actors[static_cast<std::size_t>(out.threat)];
  const vec3 rel = o.position - me.position;
  const float side = glm::dot(rel, left);  // + : the other is on the left
  const float their_speed = glm::length(o.velocity), my_speed = std::max(glm::length(me.velocity), 0.1f);
  const vec3 their_dir = their_speed > 0.1f ? o.velocity / their_speed : vec3(0.0f);
  const float urgency = std::clamp(1.0f - soonest / 4.0f, 0.0f, 1.0f);
  const float step = me.radius + o.radius + 0.2f;
  const float facing = glm::dot(their_dir, direction);
  if (their_speed < 0.1f) {
    // Standing: pass it on the side away from it.
    out.offset = (side > 0.0f ? -1.0f : 1.0f) * step * urgency;
    out.speed_scale = 1.0f - 0.4f * urgency;
  } else if (facing < -0.5f) {
    // Head on: both keep to their right.
    out.offset = -step * urgency;
    out.speed_scale = 1.0f - 0.3f * urgency;
  } else if (facing > 0.5f) {
    // Same way: fall in behind one that is slower.
    out.offset = offset * 0.5f;
    out.speed_scale = std::clamp(their_speed / my_speed, 0.2f, 1.0f);
  } else {
    // Crossing: give way to one coming from the right; the one coming from the left goes on.
    const vec3 from = -their_dir;
    const bool from_right = glm::dot(from, left) < 0.0f;
    out.offset = offset * 0.5f;
    out.speed_scale = from_right ? std::max(0.0f, 1.0f - 1.2f * urgency) : 1.0f;
  }
  return out;
}

std::optional<vec3> follow_goal(const ActorView& me, const ActorView& followed, float distance, float slack) {
  vec3 d = followed.position - me.position;
  d.y = 0.0f;
  const float gap = glm::length(d);
  if (gap <= distance + slack) return std::nullopt;
  return followed.position - d / gap * distance;
}

}  // namespace gestura
