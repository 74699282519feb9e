#include "gestura/world/director.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "gestura/io/avatar_source.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/world/character_motion.hpp"
#include "gestura/world/simulation.hpp"
#include "gestura/world/walk_rig.hpp"

namespace gestura {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string format_time(float t) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", t);
  return text;
}

// A cast member: its avatar (shared by characters built alike), rigs and signer.
struct Cast {
  std::shared_ptr<const Avatar> avatar;
  std::unique_ptr<SigningRig> rig;
  std::unique_ptr<WalkRig> walk;
  Signer* signer = nullptr;
  std::string avatar_key;
};

struct Door {
  int object = -1;
  float angle = 0.0f;
};

// What one running action remembers between ticks.
struct Running {
  const ScriptAction* action = nullptr;
  int actor = -1;
  int phase = 0;
  float started = 0.0f;
  float until = 0.0f;
  bool done = false;
  std::optional<float> saved_speed;
  int door = -1;  // index into Director::doors_
  float door_from = 0.0f, door_to = 0.0f, swing_start = 0.0f;
};

struct Chain {
  const ScriptChain* chain = nullptr;
  std::size_t next = 0;
  std::optional<Running> current;
  bool done = false;
};

struct Statement {
  const ScriptStatement* source = nullptr;
  std::vector<Chain> chains;
  float started = -1.0f;
  bool done = false;
};

class Director {
 public:
  Director(const Scene& scene, const SceneGeometry& geometry, const Script& script, LayeredLexicon* lexicon, const PerformOptions& options)
      : scene_(scene), geometry_(geometry), script_(script), options_(options) {
    if (!lexicon) own_lexicon_ = std::make_unique<DefaultLexicon>(), lexicon = &own_lexicon_->layers();
    lexicon_ = lexicon;
    SimulationOptions so;
    so.tick = options.tick;
    so.seed = scene.seed;
    sim_ = std::make_unique<Simulation>(geometry, so);
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
      if (scene.objects[o].door) doors_.push_back({static_cast<int>(o), scene.objects[o].door->angle});
    cast_characters();
  }

  ScenePerformance run() {
    for (const ScriptStatement& st : script_.statements) {
      Statement s;
      s.source = &st;
      for (const ScriptChain& c : st.chains) s.chains.push_back(Chain{&c, 0, std::nullopt, false});
      statements_.push_back(std::move(s));
    }
    const int max_ticks = static_cast<int>(options_.max_seconds / options_.tick);
    float quiet_since = -1.0f;
    for (int tick = 0; tick < max_ticks; ++tick) {
      const float now = sim_->time();
      schedule(now);
      for (Statement& st : statements_) {
        if (st.started < 0.0f || st.done) continue;
        bool all = true;
        for (Chain& c : st.chains) {
          advance(c, now);
          all = all && c.done;
        }
        st.done = all;
      }
      update_signing(now);
      sim_->step();
      const bool scripted = std::any_of(statements_.begin(), statements_.end(), [](const Statement& s) { return !s.done; });
      const bool busy = !sim_->idle() || now < busy_until_;
      if (!scripted && !busy) {
        if (quiet_since < 0.0f) quiet_since = now;
        if (now - quiet_since >= options_.tail) break;
      } else {
        quiet_since = -1.0f;
      }
      if (tick + 1 == max_ticks) warn(nullptr, "the script was still running after " + format_time(options_.max_seconds) + " s: cut there");
    }
    return synthesize();
  }

 private:
  // --- the cast ------------------------------------------------------------------------------
  void cast_characters() {
    std::map<std::string, std::shared_ptr<const Avatar>> avatars;
    std::map<std::string, std::unique_ptr<Signer>> signers;
    for (const SceneCharacter& c : scene_.characters) {
      AvatarParams params;
      params.height = c.height;
      params.build = c.build;
      params.sex = parse_sex(c.sex);
      params.validate();
      const std::string key = c.avatar + "|" + std::to_string(c.height) + "|" + std::to_string(c.build) + "|" + c.sex;
      auto it = avatars.find(key);
      if (it == avatars.end()) {
        progress("building the avatar of " + c.name);
        it = avatars.emplace(key, std::make_shared<Avatar>(load_avatar(c.avatar, params))).first;
      }
      Cast cast;
      cast.avatar = it->second;
      cast.avatar_key = key;
      cast.rig = std::make_unique<SigningRig>(make_signing_rig(*cast.avatar));
      cast.walk = std::make_unique<WalkRig>(make_walk_rig(*cast.avatar));
      auto sit = signers_.find(key);
      if (sit == signers_.end()) sit = signers_.emplace(key, std::make_unique<Signer>(*cast.avatar, *lexicon_)).first;
      cast.signer = sit->second.get();
      float facing = c.facing;
      const vec3 at = start_position(scene_, c, sim_->environment(), &facing);
      ActorSpec spec;
      spec.name = c.name;
      spec.position = at;
      spec.yaw = deg(facing);
      spec.radius = c.radius;
      spec.speed = c.speed;
      spec.height = c.height;
      index_[lower(c.name)] = static_cast<int>(cast_.size());
      sim_->add_actor(spec);
      cast_.push_back(std::move(cast));
      records_.emplace_back();
    }
  }

  // --- targets -------------------------------------------------------------------------------
  int actor_of(const std::string& name) const {
    const auto it = index_.find(lower(name));
    return it == index_.end() ? -1 : it->second;
  }
  int object_of(const std::string& name) const {
    for (std::size_t o = 0; o < scene_.objects.size(); ++o)
      if (lower(scene_.objects[o].name) == lower(name)) return static_cast<int>(o);
    return -1;
  }
  const Place* place_of(const std::string& name) const {
    for (const auto& [k, p] : scene_.places)
      if (lower(k) == lower(name)) return &p;
    return nullptr;
  }
  Aabb object_box(int object) const {
    const std::vector<mat4> transforms = current_transforms();
    Aabb box;
    const auto o = static_cast<std::size_t>(object);
    for (std::uint32_t k = geometry_.object_first[o]; k < geometry_.object_first[o] + geometry_.object_count[o]; ++k)
      box.grow(vec3(transforms[o] * vec4(geometry_.positions[geometry_.indices[k]], 1.0f)));
    return box;
  }
  std::vector<mat4> current_transforms() const {
    std::vector<mat4> t;
    for (std::size_t o = 0; o < scene_.objects.size(); ++o) t.push_back(object_matrix(scene_.objects[o], door_angle(static_cast<int>(o))));
    return t;
  }
  float door_angle(int object) const {
    for (const Door& d : doors_)
      if (d.object == object) return d.angle;
    const SceneObject& o = scene_.objects[static_cast<std::size_t>(object)];
    return o.door ? o.door->angle : 0.0f;
  }
  // A target's point: a character's position, a place, an object's centre on the floor.
  vec3 target_point(const std::string& name) const {
    if (const int a = actor_of(name); a >= 0) return sim_->actor(a).view.position;
    if (const Place* p = place_of(name)) {
      const auto g = ground_below(sim_->environment(), p->position + vec3(0, 1.0f, 0));
      return vec3(p->position.x, g ? g->height : p->position.y, p->position.z);
    }
    const Aabb box = object_box(object_of(name));
    return vec3(box.centre().x, box.min.y, box.centre().z);
  }

  // --- logging ---------------------------------------------------------------------------------
  void progress(const std::string& text) {
    if (options_.progress) options_.progress(text);
  }
  void log(const std::string& text) {
    log_.push_back({sim_->time(), text, false});
    progress(format_time(sim_->time()) + " s  " + text);
  }
  void warn(const ScriptAction* a, const std::string& text) {
    std::string where;
    if (a) where = a->where.to_string() + (a->pointer.empty() ? "" : " " + a->pointer) + ": " + a->describe() + ": ";
    log_.push_back({sim_->time(), where + text, true});
    progress("warning: " + where + text);
  }

  // --- statements ------------------------------------------------------------------------------
  void schedule(float now) {
    for (std::size_t i = 0; i < statements_.size(); ++i) {
      Statement& st = statements_[i];
      if (st.started >= 0.0f) continue;
      const Statement* previous = i > 0 ? &statements_[i - 1] : nullptr;
      bool go = false;
      if (st.source->at) go = now >= *st.source->at && (!previous || previous->started >= 0.0f);
      else if (!previous) go = true;
      else if (st.source->with_previous) go = previous->started >= 0.0f;
      else go = previous->done;
      if (!go) break;  // statements start in order
      st.started = now;
    }
  }

  void advance(Chain& c, float now) {
    while (!c.done) {
      if (!c.current) {
        if (c.next >= c.chain->actions.size()) {
          c.done = true;
          return;
        }
        c.current = Running{};
        c.current->action = &c.chain->actions[c.next++];
        c.current->actor = c.current->action->actor.empty() ? -1 : actor_of(c.current->action->actor);
        c.current->started = now;
        begin(*c.current, now);
      } else {
        update(*c.current, now);
      }
      if (!c.current->done) return;
      c.current.reset();
    }
  }

  void begin(Running& r, float now) {
    const ScriptAction& a = *r.action;
    switch (a.kind) {
      case ActionKind::Wait: r.until = now + a.number; break;
      case ActionKind::Walk: begin_walk(r, now); break;
      case ActionKind::Turn: {
        SimActor& me = sim_->actor(r.actor);
        float yaw = me.walker.yaw;
        if (a.angle) yaw += deg(*a.angle);
        else {
          const vec3 d = target_point(a.target) - me.view.position;
          if (glm::length(vec2(d.x, d.z)) > 1e-3f) yaw = yaw_of(d);
        }
        sim_->turn_to(r.actor, yaw);
        log(a.describe());
        break;
      }
      case ActionKind::Say: begin_say(r, now); break;
      case ActionKind::LookAt: {
        const int other = actor_of(a.target);
        if (other >= 0) sim_->look_at(r.actor, std::nullopt, other);
        else sim_->look_at(r.actor, target_point(a.target) + vec3(0, object_of(a.target) >= 0 ? 0.3f : 1.2f, 0));
        log(a.describe());
        r.done = true;
        break;
      }
      case ActionKind::StopLooking:
        sim_->look_at(r.actor, std::nullopt);
        r.done = true;
        break;
      case ActionKind::Follow:
        sim_->follow(r.actor, actor_of(a.target), a.number);
        log(a.describe() + " at " + format_time(a.number) + " m");
        r.done = true;
        break;
      case ActionKind::StopFollowing:
        sim_->actor(r.actor).follow = -1;
        sim_->actor(r.actor).walker.stop();
        r.done = true;
        break;
      case ActionKind::Stop:
        sim_->stop(r.actor);
        r.done = true;
        break;
      case ActionKind::Reach: begin_reach(r, now); break;
      case ActionKind::Open:
      case ActionKind::Close: begin_door(r, now); break;
    }
  }

  void update(Running& r, float now) {
    const ScriptAction& a = *r.action;
    switch (a.kind) {
      case ActionKind::Wait:
      case ActionKind::Say: r.done = now >= r.until; break;
      case ActionKind::Walk:
      case ActionKind::Turn:
        if (!sim_->actor(r.actor).walker.busy()) {
          if (r.saved_speed) sim_->actor(r.actor).params.speed = *r.saved_speed;
          r.done = true;
        }
        break;
      case ActionKind::Reach: update_reach(r, now); break;
      case ActionKind::Open:
      case ActionKind::Close: update_door(r, now); break;
      default: r.done = true; break;
    }
  }

  // --- walking ---------------------------------------------------------------------------------
  void begin_walk(Running& r, float) {
    const ScriptAction& a = *r.action;
    SimActor& me = sim_->actor(r.actor);
    vec3 goal = target_point(a.target);
    std::optional<float> facing;
    bool approach = false;
    vec3 extent(1.0f, 0.6f, 1.0f);
    if (const int other = actor_of(a.target); other >= 0) {
      // Up to the other character, stopping short at a comfortable distance, facing them.
      const SimActor& them = sim_->actor(other);
      vec3 d = me.view.position - them.view.position;
      d.y = 0.0f;
      const float gap = me.spec.radius + them.spec.radius + 0.5f;
      goal = them.view.position + (glm::length(d) > 1e-3f ? glm::normalize(d) : heading(them.view.yaw)) * gap;
      facing = yaw_of(them.view.position - goal);
      approach = true;
      extent = vec3(0.5f, 0.6f, 0.5f);
    } else if (const Place* p = place_of(a.target)) {
      if (p->facing) facing = deg(*p->facing);
    } else {
      // An object: the nearest floor next to it, facing it.
      const Aabb box = object_box(object_of(a.target));
      goal = vec3(box.centre().x, box.min.y, box.centre().z);
      const vec3 half = (box.max - box.min) * 0.5f;
      extent = vec3(half.x + me.spec.radius + 0.6f, 0.6f, half.z + me.spec.radius + 0.6f);
      approach = true;
    }
    if (a.speed) r.saved_speed = me.params.speed, me.params.speed = *a.speed;
    const PlannedPath path = sim_->walk_to(r.actor, goal, approach, facing, extent);
    if (path.status != PathStatus::Found) {
      warn(&a, path.reason);
      r.done = true;
      return;
    }
    if (!facing && approach) {
      // Face the object on arrival.
      const vec3 end = path.points.back();
      sim_->actor(r.actor).walker.final_yaw = yaw_of(goal - end);
    }
    log(a.describe() + " (" + format_time(path.length) + " m)");
  }

  // --- signing ---------------------------------------------------------------------------------
  void begin_say(Running& r, float now) {
    const ScriptAction& a = *r.action;
    Cast& c = cast_[static_cast<std::size_t>(r.actor)];
    const std::string key = c.avatar_key + "\n" + a.text;
    auto it = sentences_.find(key);
    if (it == sentences_.end()) {
      SentencePerformance p = c.signer->say(a.text, options_.say);
      for (const std::string& note : p.notes) progress("note: " + note);
      auto clip = std::make_shared<Clip>(std::move(p.clip));
      clip->duration = p.duration;
      float first = p.duration, last = 0.0f;
      for (const PerformedGloss& g : p.glosses) first = std::min(first, g.start), last = std::max(last, g.end);
      it = sentences_.emplace(key, Sentence{clip, first, last}).first;
    }
    const Sentence& s = it->second;
    records_[static_cast<std::size_t>(r.actor)].speech.push_back({now, s.clip});
    r.until = now + s.clip->duration;
    // Whom it is said to: the one named, else the nearest character it sees.
    int addressee = a.target.empty() ? -1 : actor_of(a.target);
    if (addressee < 0 && !sim_->actor(r.actor).percept.actors.empty()) addressee = sim_->actor(r.actor).percept.actors.front().actor;
    signing_.push_back({r.actor, now + std::max(0.0f, s.first - 0.2f), now + s.last + 0.2f, addressee});
    busy_until_ = std::max(busy_until_, r.until);
    log(a.describe() + (addressee >= 0 ? " to " + sim_->actor(addressee).spec.name : std::string()) + " (" + format_time(s.clip->duration) + " s)");
  }

  void update_signing(float now) {
    std::vector<int> addressee(cast_.size(), -1);
    std::vector<bool> on(cast_.size(), false);
    for (const Signing& s : signing_)
      if (now >= s.from && now <= s.until) on[static_cast<std::size_t>(s.actor)] = true, addressee[static_cast<std::size_t>(s.actor)] = s.addressee;
    for (std::size_t i = 0; i < cast_.size(); ++i) sim_->set_signing(static_cast<int>(i), on[i], addressee[i]);
  }

  // --- reaching --------------------------------------------------------------------------------
  Hand hand_toward(int actor, const vec3& point) const {
    const SimActor& me = sim_->actor(actor);
    const vec3 left = heading(me.view.yaw + kPi * 0.5f);
    return glm::dot(point - me.view.position, left) > 0.05f ? Hand::Left : Hand::Right;
  }

  vec3 shoulder_of(int actor, Hand hand) const {
    const SimActor& me = sim_->actor(actor);
    const vec3 side = heading(me.view.yaw + kPi * 0.5f) * (hand == Hand::Left ? 0.18f : -0.18f);
    return me.view.position + vec3(0.0f, me.spec.height * 0.81f, 0.0f) + side;
  }

  // The object's part nearest to the actor (what the hand will take).
  vec3 grasp_point(int actor, int object) const {
    const vec3 from = sim_->actor(actor).view.position + vec3(0.0f, sim_->actor(actor).spec.height * 0.6f, 0.0f);
    float best = 1e30f;
    vec3 point = object_box(object).centre();
    for (const WorldPrimitive& w : sim_->environment().primitives) {
      if (w.object != object) continue;
      const vec3 c = vec3(w.to_world[3]);
      const float d = glm::length(c - from);
      if (d < best) best = d, point = c;
    }
    return point;
  }

  void begin_reach(Running& r, float now) {
    const ScriptAction& a = *r.action;
    const int object = object_of(a.target);
    const vec3 point = grasp_point(r.actor, object);
    const Hand hand = hand_toward(r.actor, point);
    if (glm::length(point - shoulder_of(r.actor, hand)) > 0.58f) {
      // Out of reach: walk up to it first, facing it.
      SimActor& me = sim_->actor(r.actor);
      const Aabb box = object_box(object);
      const vec3 half = (box.max - box.min) * 0.5f;
      // The floor to stand on: where the object rests (a ball on the floor), or failing that each
      // surface further down under it (a cup on a table: the floor under the table).
      const vec3 extent(half.x + me.spec.radius + 0.3f, 0.6f, half.z + me.spec.radius + 0.3f);
      vec3 goal(point.x, box.min.y, point.z);
      PlannedPath path = sim_->walk_to(r.actor, goal, true, std::nullopt, extent);
      for (int below = 0; below < 4 && path.status != PathStatus::Found; ++below) {
        const auto ground = ground_below(sim_->environment(), vec3(goal.x, goal.y - 0.02f, goal.z));
        if (!ground) break;
        goal.y = ground->height;
        PlannedPath lower = sim_->walk_to(r.actor, goal, true, std::nullopt, extent);
        if (lower.status == PathStatus::Found) path = std::move(lower);
      }
      if (path.status != PathStatus::Found) {
        warn(&a, path.reason);
        r.done = true;
        return;
      }
      sim_->actor(r.actor).walker.final_yaw = yaw_of(point - path.points.back());
      log(r.action->actor + " walks to " + a.target + " (" + format_time(path.length) + " m)");
      r.phase = 0;
      return;
    }
    start_reach(r, now);
  }

  void start_reach(Running& r, float now) {
    const ScriptAction& a = *r.action;
    const int object = object_of(a.target);
    const Hand hand = hand_toward(r.actor, grasp_point(r.actor, object));
    ReachRecord rec{object, hand, now, now + options_.reach_seconds, now + options_.reach_seconds + 0.8f,
                    now + options_.reach_seconds + 1.5f};
    records_[static_cast<std::size_t>(r.actor)].reaches.push_back(rec);
    r.until = rec.end;
    r.phase = 1;
    busy_until_ = std::max(busy_until_, rec.end);
    log(a.describe() + " with the " + (hand == Hand::Left ? "left" : "right") + " hand");
  }

  void update_reach(Running& r, float now) {
    if (r.phase == 0) {
      if (!sim_->actor(r.actor).walker.busy()) start_reach(r, now);
      return;
    }
    r.done = now >= r.until;
  }

  // --- doors -------------------------------------------------------------------------------------
  void begin_door(Running& r, float now) {
    const ScriptAction& a = *r.action;
    const int object = object_of(a.target);
    int door = -1;
    for (std::size_t d = 0; d < doors_.size(); ++d)
      if (doors_[d].object == object) door = static_cast<int>(d);
    r.door = door;
    const SceneObject& o = scene_.objects[static_cast<std::size_t>(object)];
    r.door_from = doors_[static_cast<std::size_t>(door)].angle;
    r.door_to = a.kind == ActionKind::Open ? o.door->open_angle : 0.0f;
    if (std::abs(r.door_to - r.door_from) < 1.0f) {
      log(a.target + " is already " + (a.kind == ActionKind::Open ? "open" : "closed"));
      r.done = true;
      return;
    }
    // Where to stand: in front of the handle on the side the actor is, facing the door; beside the
    // swing when the door opens toward that side.
    const mat4 m = object_matrix(o, r.door_from);
    const vec3 handle = vec3(m * vec4(o.door->handle, 1.0f));
    vec3 normal = glm::normalize(vec3(m[2]));
    normal.y = 0.0f;
    normal = glm::normalize(normal);
    SimActor& me = sim_->actor(r.actor);
    const float side = glm::dot(me.view.position - handle, normal) >= 0.0f ? 1.0f : -1.0f;
    const mat4 m2 = object_matrix(o, r.door_from + (r.door_to - r.door_from) * 0.1f);
    const vec3 moved = vec3(m2 * vec4(o.door->handle, 1.0f)) - handle;
    const bool toward = glm::dot(moved, normal * side) > 0.0f;
    vec3 across = glm::normalize(vec3(m[0]));  // along the panel, from the hinge to its free edge
    across.y = 0.0f;
    across = glm::normalize(across);
    // Pushing: in front of the handle. Pulling: beside the door's free edge, just outside the arc
    // its panel sweeps (a metre from the hinge, 30° out from the wall), the handle in reach.
    const vec3 hinge = vec3(m[3]);
    vec3 stand = toward ? hinge + across * (std::cos(deg(30.0f)) * 1.0f) + normal * side * (std::sin(deg(30.0f)) * 1.0f)
                        : handle + normal * side * 0.45f;
    const auto g = ground_below(sim_->environment(), vec3(stand.x, handle.y, stand.z));
    stand.y = g ? g->height : me.view.position.y;
    r.phase = 0;
    if (glm::length(vec2(stand.x - me.view.position.x, stand.z - me.view.position.z)) > 0.2f) {
      const PlannedPath path = sim_->walk_to(r.actor, stand, false, yaw_of(handle - stand), vec3(0.4f, 0.6f, 0.4f));
      if (path.status != PathStatus::Found) {
        warn(&a, path.reason);
        r.done = true;
        return;
      }
      log(a.actor + " walks to " + a.target + " (" + format_time(path.length) + " m)");
    } else {
      sim_->turn_to(r.actor, yaw_of(handle - me.view.position));
    }
    (void)now;
  }

  void update_door(Running& r, float now) {
    const ScriptAction& a = *r.action;
    if (r.phase == 0) {
      if (sim_->actor(r.actor).walker.busy()) return;
      // Reach for the handle; the door starts to swing when the hand holds it.
      const int object = doors_[static_cast<std::size_t>(r.door)].object;
      const SceneObject& o = scene_.objects[static_cast<std::size_t>(object)];
      const vec3 handle = vec3(object_matrix(o, r.door_from) * vec4(o.door->handle, 1.0f));
      const Hand hand = hand_toward(r.actor, handle);
      r.swing_start = now + options_.reach_seconds;
      const float release = r.swing_start + options_.door_seconds * 0.4f;
      records_[static_cast<std::size_t>(r.actor)].reaches.push_back({object, hand, now, r.swing_start, release, release + 0.7f});
      // The door's angle over the swing, eased in and out.
      DoorMotion& motion = door_motion(object);
      for (int k = 0; k <= 16; ++k) {
        const float f = static_cast<float>(k) / 16.0f;
        const float e = f * f * (3.0f - 2.0f * f);
        const float t = r.swing_start + f * options_.door_seconds;
        if (!motion.angle.empty() && t <= motion.angle.times.back()) continue;
        motion.angle.add(t, r.door_from + (r.door_to - r.door_from) * e);
      }
      r.until = std::max(release + 0.7f, r.swing_start + options_.door_seconds);
      busy_until_ = std::max(busy_until_, r.until);
      r.phase = 1;
      log(a.describe() + " with the " + (hand == Hand::Left ? "left" : "right") + " hand");
      return;
    }
    if (r.phase == 1 && now >= r.swing_start) {
      sim_->emit({vec3(object_matrix(scene_.objects[static_cast<std::size_t>(doors_[static_cast<std::size_t>(r.door)].object)], r.door_from)[3]) +
                      vec3(0, 1.0f, 0),
                  1.0f, "door", r.actor, now});
      r.phase = 2;
    }
    if (r.phase == 2 && now >= r.swing_start + options_.door_seconds) {
      Door& d = doors_[static_cast<std::size_t>(r.door)];
      d.angle = r.door_to;
      sim_->set_object_transform(d.object, object_matrix(scene_.objects[static_cast<std::size_t>(d.object)], d.angle));
      r.phase = 3;
    }
    if (r.phase == 3 && now >= r.until) r.done = true;
  }

  DoorMotion& door_motion(int object) {
    for (DoorMotion& d : door_motions_)
      if (d.object == object) return d;
    DoorMotion d;
    d.object = object;
    d.angle.interpolation = Interpolation::Linear;
    d.angle.add(0.0f, door_angle(object));
    door_motions_.push_back(d);
    return door_motions_.back();
  }

  // --- the animation -----------------------------------------------------------------------------
  ScenePerformance synthesize() {
    ScenePerformance out;
    out.duration = sim_->time();
    out.doors = door_motions_;
    out.log = log_;
    const ObjectsAt objects_at = [&](float t) { return object_transforms_at(scene_, out, t); };
    // The ground: the environment as the scene starts (doors do not change where feet stand).
    const Environment ground = build_environment(geometry_);
    for (std::size_t i = 0; i < cast_.size(); ++i) {
      progress("animating " + scene_.characters[i].name);
      const SimActor& a = sim_->actor(static_cast<int>(i));
      CharacterRecord& rec = records_[i];
      rec.trajectory = a.trajectory;
      rec.looks = a.looks;
      CharacterMotionOptions mo;
      mo.fps = options_.fps;
      CharacterMotion motion = perform_character(*cast_[i].avatar, *cast_[i].rig, *cast_[i].walk, rec, geometry_, objects_at, ground,
                                                 out.duration, mo);
      for (const std::string& note : motion.notes) out.log.push_back({out.duration, scene_.characters[i].name + ": " + note, true});
      out.characters.push_back({scene_.characters[i].name, cast_[i].avatar, scene_.characters[i].colors, std::move(motion.clip)});
    }
    return out;
  }

  struct Sentence {
    std::shared_ptr<const Clip> clip;
    float first = 0.0f, last = 0.0f;  // when its signs start and end, within the clip
  };
  struct Signing {
    int actor = -1;
    float from = 0.0f, until = 0.0f;
    int addressee = -1;
  };

  const Scene& scene_;
  const SceneGeometry& geometry_;
  const Script& script_;
  PerformOptions options_;
  std::unique_ptr<DefaultLexicon> own_lexicon_;
  LayeredLexicon* lexicon_ = nullptr;
  std::unique_ptr<Simulation> sim_;
  std::vector<Cast> cast_;
  std::map<std::string, std::unique_ptr<Signer>> signers_;
  std::map<std::string, int> index_;
  std::vector<CharacterRecord> records_;
  std::vector<Statement> statements_;
  std::vector<Door> doors_;
  std::vector<DoorMotion> door_motions_;
  std::map<std::string, Sentence> sentences_;
  std::vector<Signing> signing_;
  std::vector<LogEntry> log_;
  float busy_until_ = 0.0f;
};

}  // namespace

vec3 start_position(const Scene& scene, const SceneCharacter& c, const Environment& env, float* facing_degrees) {
  vec3 p = c.position;
  if (!c.place.empty()) {
    const auto it = scene.places.find(c.place);
    if (it != scene.places.end()) {
      p = it->second.position;
      if (it->second.facing && facing_degrees) *facing_degrees = *it->second.facing;
    }
  }
  const auto g = ground_below(env, p + vec3(0.0f, 1.0f, 0.0f), 50.0f);
  if (g) p.y = g->height;
  return p;
}

ScenePerformance perform_scene(const Scene& scene, const SceneGeometry& geometry, const Script& script, LayeredLexicon* lexicon,
                               const PerformOptions& options) {
  check_script(script, scene);
  if (!(options.tick > 0.0f && options.tick <= 0.1f)) throw Error("perform: the simulation step must be in (0, 0.1] s");
  if (!(options.fps >= 1.0f && options.fps <= 240.0f)) throw Error("perform: fps must be 1..240");
  Director director(scene, geometry, script, lexicon, options);
  return director.run();
}

}  // namespace gestura
