#pragma once
// A small behaviour system for autonomous actors: each tick a few behaviours, in priority order,
// read the actor's percept (sensors.hpp) and propose what it does — where it looks, whether it
// follows someone, how it gets out of others' way. Behaviours decide from what the actor perceives,
// not from the world's state, so an actor that does not see a signer does not turn to them.
//
//   look     (a selector) an explicit "look at" of the script > the one it signs to while signing >
//            whoever it sees signing (the nearest to the middle of its view, kept until they stop, so
//            the gaze does not flicker between two signers) > a sound it just heard (a glance for
//            a second and a half) > nothing
//   follow   keep `distance` behind the followed actor: walk after it when it gets further than
//            that (a path re-planned as it moves), stop and face it when near
//   avoid    while walking, predict when the nearest perceived walker would come closest; if that
//            is nearer than both radii and soon, step aside to the right (both keep right when they
//            meet head on), fall in behind one going the same way more slowly, give way to one
//            coming from the right, and pass a standing one on the side with more room
#include <optional>
#include <span>
#include <string>

#include "gestura/world/sensors.hpp"

namespace gestura {

struct LookIntent {
  int actor = -1;           // the actor looked at, or -1
  vec3 point{0.0f};         // what is looked at (world)
  float weight = 0.0f;      // 0 none … 1 full (head and eyes)
  std::string why;          // "script", "addressee", "signer", "sound"
};

struct LookState {
  int held_signer = -1;     // the signer the gaze stays on
  float glance_until = -1.0f;
  vec3 glance_point{0.0f};
};

struct LookInputs {
  std::optional<vec3> scripted;         // the script's "looks at"
  int scripted_actor = -1;
  int addressee = -1;                   // while signing
  bool self_signing = false;
  float now = 0.0f;
};

// The look behaviour (a selector over the sources above). `events` are the sound events the
// percept's `heard` refers to.
LookIntent choose_look(std::span<const ActorView> actors, int self, const Percept& percept, std::span<const SoundEvent> events,
                       const LookInputs& inputs, LookState& state);

struct AvoidIntent {
  float offset = 0.0f;       // sideways shift wanted (+ = left of the walking direction)
  float speed_scale = 1.0f;  // 0 wait … 1 full speed
  int threat = -1;           // the actor avoided, or -1
};

// What avoidance keeps between ticks: the walker it is getting out of the way of, and how far aside
// it has decided to go — held until that walker has passed, so the two do not drift back into each
// other's way as soon as the prediction clears.
struct AvoidState {
  int threat = -1;
  float offset = 0.0f;
  float speed_scale = 1.0f;
};

// `direction` is the unit walking direction; `offset` the current sideways shift. The result's
// offset is where the walker should be beside its path (0 when nothing is in the way).
AvoidIntent avoid_others(std::span<const ActorView> actors, int self, const Percept& percept, const vec3& direction, float offset,
                         AvoidState& state);

// The decision of one tick, without memory (what avoid_others builds on).
AvoidIntent decide_avoidance(std::span<const ActorView> actors, int self, const Percept& percept, const vec3& direction, float offset);

// Where a follower should go: `distance` short of the followed actor on the line between them, or
// none when it is already close enough (within distance + slack).
std::optional<vec3> follow_goal(const ActorView& me, const ActorView& followed, float distance, float slack = 0.35f);

}  // namespace gestura
