#include "gestura/sentence/signing_space.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "gestura/body/body_sites.hpp"

namespace gestura {

namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;
constexpr float kChestLower = 0.06f;     // places lie this far below the chest site, where the hands sign
constexpr float kSignerOut = 0.12f;      // the signer's own place: this far in front of the chest
constexpr float kPointedReach = 0.90f;   // a pointing finger aims at the referent this far out
constexpr float kPointShift = 0.10f;     // a pointing hand moves this far toward its place's side
constexpr float kSweepHalfDegrees = 25.0f;  // a plural arc over one place: this far either side of it
constexpr float kSweepReach = 0.30f;     // the sweeping hand's path lies at this reach
constexpr float kPathReach = 0.30f;      // an agreement verb's path runs between places this far out
// An agreement verb's hand turns by this share of its path's turn: the fingers lead toward the goal
// without the wrist and forearm twisting past what an arm does when it crosses the body.
constexpr float kPathTurnShare = 0.5f;

vec3 chest(const SigningRig& rig) {
  if (const BodySite* s = find_site(rig.sites, "chest")) return site_position(*s, rig.bind_model);
  return vec3(0.0f, 1.25f, 0.12f);  // an avatar without the site: the default body's chest
}

vec3 horizontal(vec3 v) { return vec3(v.x, 0.0f, v.z); }

// Yaw (about +Y, + toward +X) from horizontal direction a to horizontal direction b.
float yaw_between(vec3 a, vec3 b) {
  return std::atan2(a.z * b.x - a.x * b.z, a.x * b.x + a.z * b.z);
}

quat yaw(float angle) { return glm::angleAxis(angle, vec3(0.0f, 1.0f, 0.0f)); }

vec3 finger_of(const HandState& s) { return s.orientation * vec3(0.0f, 1.0f, 0.0f); }

// Every hand state of one hand's timeline, and every movement path on it.
void each_state(HandTimeline& t, const std::function<void(HandState&)>& f) {
  for (HandSegment& seg : t.segments) {
    f(seg.from);
    f(seg.to);
  }
}

// Maps a vector of a path: `linear` for chords and offsets, `turn` alone for unit directions.
void map_paths(HandTimeline& t, const std::function<vec3(vec3)>& linear, const quat& turn) {
  for (HandSegment& seg : t.segments) {
    seg.detour = turn * seg.detour;
    for (Movement& m : seg.paths) {
      MovementPath& p = m.path;
      switch (p.kind) {
        case PathKind::Straight:
        case PathKind::Arc: {
          const vec3 chord = linear(p.direction * p.length);
          const float length = glm::length(chord);
          if (length > 1e-5f) {
            p.direction = chord / length;
            p.length = length;
          }
          vec3 bulge = turn * p.bulge;
          bulge -= p.direction * glm::dot(bulge, p.direction);
          if (glm::length(bulge) > 1e-4f) p.bulge = glm::normalize(bulge);
          break;
        }
        case PathKind::Circle:
          p.axis = turn * p.axis;
          p.start_radial = turn * p.start_radial;
          break;
        case PathKind::Polyline:
          for (vec3& q : p.points) q = linear(q);
          break;
      }
      p.modifier_axis = turn * p.modifier_axis;
      p.modifier_binormal = turn * p.modifier_binormal;
    }
  }
}

const HandState* first_active(const HandTimeline& t) {
  for (const HandSegment& seg : t.segments)
    if (seg.from.active) return &seg.from;
  return nullptr;
}

const HandState* last_active(const HandTimeline& t) {
  for (auto it = t.segments.rbegin(); it != t.segments.rend(); ++it)
    if (it->to.active) return &it->to;
  return nullptr;
}

// The turn about the vertical that points the hand's fingers (their horizontal direction) at
// `target`.
// A hand whose fingers point up or down (POSS: a flat hand, fingers up) faces its place with the
// palm instead.
float aim_yaw(const HandState& hand, vec3 target) {
  vec3 pointer = horizontal(finger_of(hand));
  if (glm::length(pointer) < 0.5f) pointer = horizontal(hand.orientation * vec3(0.0f, 0.0f, 1.0f));
  const vec3 want = horizontal(target - hand.position);
  if (glm::length(pointer) < 0.2f || glm::length(want) < 1e-3f) return 0.0f;
  return yaw_between(glm::normalize(pointer), glm::normalize(want));
}

// The dominant hand's path from `s` to `e` moved to run from `f` to `t`: turned about the vertical,
// stretched along its horizontal chord, translated; the other hand turned and moved with it.
SignPlan carried(const SignPlan& citation, vec3 s, vec3 e, vec3 f, vec3 t, float turn_share = 1.0f) {
  SignPlan out = citation;
  const vec3 chord = horizontal(e - s);
  const vec3 goal = horizontal(t - f);
  float angle = 0.0f, stretch = 1.0f;
  vec3 axis(0.0f, 0.0f, 1.0f);
  if (glm::length(chord) > 0.02f && glm::length(goal) > 0.02f) {
    angle = yaw_between(glm::normalize(chord), glm::normalize(goal));
    stretch = std::clamp(glm::length(goal) / glm::length(chord), 0.5f, 3.0f);
    axis = glm::normalize(chord);
  }
  const quat turn = yaw(angle);
  const quat hand_turn = yaw(angle * turn_share);
  const vec3 path = e - s;
  if (glm::length(chord) <= 0.02f && glm::length(path) > 0.02f && glm::length(goal) > 0.02f) {
    // A path with no horizontal run (HELP rises, the base hand lifting the fist): the hands carry
    // the path as it is and travel from f to t as they go along it — a shear, so each part of the
    // movement is as far along the way to t as it is along its own path. Both hands go together.
    const vec3 along = path / glm::dot(path, path);
    const auto sheared = [&](vec3 v) { return v + glm::dot(v, along) * goal; };
    for (auto* hand : {&out.right, &out.left}) {
      each_state(*hand, [&](HandState& h) { h.position = f + sheared(h.position - s); });
      map_paths(*hand, sheared, quat(1.0f, 0.0f, 0.0f, 0.0f));
    }
    return out;
  }
  const auto stretched = [&](vec3 v) { return v + (stretch - 1.0f) * glm::dot(v, axis) * axis; };
  each_state(out.right, [&](HandState& h) { h.position = f + turn * stretched(h.position - s); h.orientation = hand_turn * h.orientation; });
  map_paths(out.right, [&](vec3 v) { return turn * stretched(v); }, turn);
  each_state(out.left, [&](HandState& h) { h.position = f + turn * (h.position - s); h.orientation = hand_turn * h.orientation; });
  map_paths(out.left, [&](vec3 v) { return turn * v; }, turn);
  return out;
}

}  // namespace

float locus_yaw(Locus locus) {
  if (locus.person != 3) return 0.0f;
  // a: right, b: left, c: far right, d: far left, then round again. The avatar's right is −X,
  // so rightward places have negative yaw.
  const int k = locus.index % 4;
  const float degrees = k < 2 ? kLocusSideDegrees : kLocusFarDegrees;
  return (k % 2 == 0 ? -degrees : degrees) * kDegree;
}

vec3 locus_point(const SigningRig& rig, Locus locus, float reach) {
  const vec3 c = chest(rig) - vec3(0.0f, kChestLower, 0.0f);
  if (locus.person == 1) return c + vec3(0.0f, 0.0f, kSignerOut);
  const float a = locus_yaw(locus);
  return c + reach * vec3(std::sin(a), 0.0f, std::cos(a));
}

SignPlan aimed_at(const SignPlan& citation, const SigningRig& rig, Locus locus) {
  SignPlan out = citation;
  const HandState* end = last_active(citation.right);
  if (!end || locus.person == 0) return out;
  const vec3 target = locus_point(rig, locus, kPointedReach);
  const vec3 shift(std::sin(locus_yaw(locus)) * kPointShift, 0.0f, 0.0f);
  HandState moved = *end;
  moved.position += shift;
  const quat turn = yaw(aim_yaw(moved, target));
  const vec3 pivot = end->position;
  each_state(out.right, [&](HandState& h) {
    h.position = pivot + shift + turn * (h.position - pivot);
    h.orientation = turn * h.orientation;
  });
  map_paths(out.right, [&](vec3 v) { return turn * v; }, turn);
  return out;
}

SignPlan moved_between(const SignPlan& citation, const SigningRig& rig, Locus from, Locus to) {
  const HandState* s = first_active(citation.right);
  const HandState* e = last_active(citation.right);
  if (!s || !e || !from || !to) return citation;
  const vec3 f = from.person == 1 ? s->position : locus_point(rig, from, kPathReach);
  const vec3 t = locus_point(rig, to, kPathReach);
  return carried(citation, s->position, e->position, f, t, kPathTurnShare);
}

SignPlan swept_over(const SignPlan& citation, const SigningRig& rig, std::span<const Locus> places) {
  const HandState* s = first_active(citation.right);
  const HandState* e = last_active(citation.right);
  if (!s || !e || places.empty()) return citation;
  float a = locus_yaw(places.front()), b = locus_yaw(places.back());
  if (places.size() == 1) {
    a -= kSweepHalfDegrees * kDegree;
    b += kSweepHalfDegrees * kDegree;
  }
  const vec3 c = chest(rig) - vec3(0.0f, kChestLower, 0.0f);
  const auto at = [&](float yaw_angle, float reach) { return c + reach * vec3(std::sin(yaw_angle), 0.0f, std::cos(yaw_angle)); };
  SignPlan out = carried(citation, s->position, e->position, at(a, kSweepReach), at(b, kSweepReach));
  // Each posture points at the part of the arc it has reached: its progress along the sweep.
  const vec3 f = at(a, kSweepReach), t = at(b, kSweepReach);
  const vec3 chord = horizontal(t - f);
  const float chord2 = std::max(glm::dot(chord, chord), 1e-6f);
  each_state(out.right, [&](HandState& h) {
    const float progress = std::clamp(glm::dot(horizontal(h.position - f), chord) / chord2, 0.0f, 1.0f);
    const vec3 target = at(a + (b - a) * progress, kPointedReach);
    h.orientation = yaw(aim_yaw(h, target)) * h.orientation;
  });
  return out;
}

bool uses_space(const GlossToken& g) { return !g.over.empty() || g.at.person == 3 || (g.from && g.to); }

std::string space_key(const GlossToken& g) {
  std::string key;
  for (const Locus& l : g.over) key += (key.empty() ? "" : "+") + l.name();
  if (g.at) key += "@" + g.at.name();
  if (g.from && g.to) key += g.from.name() + "→" + g.to.name();
  return key;
}

SignPlan in_space(const SignPlan& citation, const SigningRig& rig, const GlossToken& g) {
  if (!g.over.empty()) return swept_over(citation, rig, g.over);
  if (g.from && g.to) return moved_between(citation, rig, g.from, g.to);
  if (g.at.person == 3) {
    const std::string& sign = g.sign();
    const bool plural = sign.size() > 3 && sign.compare(sign.size() - 3, 3, "-PL") == 0;
    return plural ? swept_over(citation, rig, std::span<const Locus>(&g.at, 1)) : aimed_at(citation, rig, g.at);
  }
  return citation;
}

}  // namespace gestura
