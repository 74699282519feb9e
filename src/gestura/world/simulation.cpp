#include "gestura/world/simulation.hpp"

#include <algorithm>

namespace gestura {

Simulation::Simulation(const SceneGeometry& geometry, const SimulationOptions& options)
    : geometry_(&geometry), options_(options), object_transforms_(geometry.object_transforms), random_(options.seed) {
  rebuild();
}

void Simulation::rebuild() {
  EnvironmentOptions eo;
  eo.max_slope_degrees = options_.navigation.max_slope_degrees;
  eo.max_climb = options_.navigation.max_climb;
  env_ = std::make_unique<Environment>(build_environment(*geometry_, object_transforms_, eo));
  planner_ = std::make_unique<PathPlanner>(*env_, options_.navigation);
  objects_.clear();
  for (std::size_t o = 0; o < geometry_->object_names.size(); ++o) {
    if (geometry_->object_names[o].empty() || geometry_->object_count[o] == 0) continue;
    Aabb box;
    for (std::uint32_t k = geometry_->object_first[o]; k < geometry_->object_first[o] + geometry_->object_count[o]; ++k)
      box.grow(vec3(object_transforms_[o] * vec4(geometry_->positions[geometry_->indices[k]], 1.0f)));
    objects_.push_back({static_cast<int>(o), box.centre()});
  }
  dirty_ = false;
}

int Simulation::add_actor(const ActorSpec& spec) {
  SimActor a;
  a.spec = spec;
  a.params.speed = spec.speed;
  a.walker.position = spec.position;
  a.walker.yaw = spec.yaw;
  a.view.position = spec.position;
  a.view.yaw = spec.yaw;
  a.view.radius = spec.radius;
  a.view.height = spec.height;
  a.trajectory.dt = options_.tick;
  // Sample k of the records is the state at time k·tick.
  for (int k = 0; k <= ticks_ && options_.record; ++k) {
    a.trajectory.push(spec.position, spec.yaw);
    a.looks.push_back({});
  }
  actors_.push_back(std::move(a));
  views_.push_back(actors_.back().view);
  return static_cast<int>(actors_.size()) - 1;
}

PlannedPath Simulation::walk_to(int i, const vec3& goal, bool approach, std::optional<float> facing, vec3 approach_extent) {
  if (dirty_) rebuild();
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  PathRequest request{a.walker.position, goal, a.spec.radius};
  request.approach = approach;
  request.approach_extent = approach_extent;
  PlannedPath path = planner_->plan(request);
  if (path.status != PathStatus::Found) return path;
  // The path starts where the actor stands (it may stand a little off the floor's mesh).
  if (!path.points.empty()) path.points.front() = a.walker.position;
  a.walker.follow(make_track(path.points, env_.get(), a.spec.radius, a.spec.height), facing);
  return path;
}

void Simulation::turn_to(int i, float yaw) { actors_[static_cast<std::size_t>(i)].walker.turn_to(yaw); }

void Simulation::stop(int i) {
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  a.walker.stop();
  a.follow = -1;
}

void Simulation::follow(int i, int target, float distance) {
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  a.follow = target;
  a.follow_distance = distance;
  a.follow_replan_at = time_;
  a.follow_planned_to = vec3(1e30f);
}

void Simulation::look_at(int i, std::optional<vec3> point, int target_actor) {
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  a.look_at_point = point;
  a.look_at_actor = target_actor;
}

void Simulation::set_signing(int i, bool signing, int addressee) {
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  a.signing = signing;
  a.addressee = signing ? addressee : -1;
}

void Simulation::emit(const SoundEvent& event) {
  sounds_.push_back(event);
  sounds_.back().time = time_;
}

void Simulation::set_object_transform(int object, const mat4& transform) {
  object_transforms_[static_cast<std::size_t>(object)] = transform;
  dirty_ = true;
}

bool Simulation::idle() const {
  for (const SimActor& a : actors_)
    if (a.walker.busy()) return false;
  return true;
}

void Simulation::sense(int i) {
  SimActor& a = actors_[static_cast<std::size_t>(i)];
  const std::size_t n = actors_.size();
  std::vector<int> candidates;
  if (static_cast<int>(n) > options_.vision_candidates + 1) {
    // The nearest few (a crowd's far members hide behind its near ones anyway).
    std::vector<std::pair<float, int>> near;
    for (std::size_t k = 0; k < n; ++k) {
      if (static_cast<int>(k) == i) continue;
      const vec3 d = views_[k].position - a.view.position;
      near.push_back({d.x * d.x + d.z * d.z, static_cast<int>(k)});
    }
    const auto keep = static_cast<std::ptrdiff_t>(std::min<std::size_t>(near.size(), static_cast<std::size_t>(options_.vision_candidates)));
    std::partial_sort(near.begin(), near.begin() + keep, near.end());
    for (std::ptrdiff_t k = 0; k < keep; ++k) candidates.push_back(near[static_cast<std::size_t>(k)].second);
  }
  see(*env_, views_, i, candidates, n <= 12 ? std::span<const std::pair<int, vec3>>(objects_) : std::span<const std::pair<int, vec3>>(),
      options_.vision, a.percept);
  // Sounds of the last half second.
  hear(*env_, views_, i, sounds_, options_.hearing_range, a.percept);
  a.percept.heard.erase(std::remove_if(a.percept.heard.begin(), a.percept.heard.end(),
                                       [&](const Heard& h) { return time_ - sounds_[static_cast<std::size_t>(h.event)].time >= 0.5f; }),
                        a.percept.heard.end());
  touch(*env_, views_, i, a.percept);
  for (const Touch& t : a.percept.touches)
    if (t.actor >= 0 && std::find(a.touching.begin(), a.touching.end(), t.actor) == a.touching.end()) a.touching.push_back(t.actor);
}

void Simulation::step() {
  if (dirty_) rebuild();
  const float dt = options_.tick;
  const std::size_t n = actors_.size();
  for (std::size_t i = 0; i < n; ++i) {
    actors_[i].view.signing = actors_[i].signing;
    views_[i] = actors_[i].view;
  }
  const int every = options_.sense_every > 0 ? options_.sense_every : (n > 12 ? 6 : 1);
  for (std::size_t i = 0; i < n; ++i)
    if ((static_cast<int>(i) + ticks_) % every == 0) sense(static_cast<int>(i));

  for (std::size_t i = 0; i < n; ++i) {
    SimActor& a = actors_[i];
    // Follow: re-plan toward the followed actor twice a second when it has moved on.
    if (a.follow >= 0 && time_ >= a.follow_replan_at) {
      a.follow_replan_at = time_ + 0.5f;
      const ActorView& target = views_[static_cast<std::size_t>(a.follow)];
      if (const auto goal = follow_goal(a.view, target, a.follow_distance)) {
        if (glm::length(*goal - a.follow_planned_to) > 0.3f || !a.walker.busy()) {
          const float facing = yaw_of(target.position - *goal);
          if (walk_to(static_cast<int>(i), *goal, false, facing).status == PathStatus::Found) a.follow_planned_to = *goal;
        }
      } else if (!a.walker.busy()) {
        const float facing = yaw_of(target.position - a.view.position);
        if (std::abs(angle_difference(facing, a.walker.yaw)) > deg(35.0f)) a.walker.turn_to(facing);
      }
    }
    // Look: scripted, addressee, signer seen, sound heard.
    LookInputs in;
    if (a.look_at_actor >= 0) in.scripted = eye_point(views_[static_cast<std::size_t>(a.look_at_actor)]), in.scripted_actor = a.look_at_actor;
    else in.scripted = a.look_at_point;
    in.addressee = a.addressee;
    in.self_signing = a.signing;
    in.now = time_;
    a.look = choose_look(views_, static_cast<int>(i), a.percept, sounds_, in, a.look_state);
    // Move: along the path, out of others' way.
    if (a.walker.mode == Locomotor::Mode::Walk) {
      const vec3 dir = a.walker.track.tangent_at(a.walker.progress);
      const AvoidIntent avoid = avoid_others(views_, static_cast<int>(i), a.percept, dir, a.walker.offset, a.avoid_state);
      step_locomotor(a.walker, a.params, dt, avoid.speed_scale, avoid.offset);
    } else {
      step_locomotor(a.walker, a.params, dt);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    SimActor& a = actors_[i];
    vec3 v = (a.walker.position - a.view.position) / dt;
    v.y = 0.0f;
    a.view.velocity = v;
    a.view.position = a.walker.position;
    a.view.yaw = a.walker.yaw;
    if (options_.record) {
      a.trajectory.push(a.walker.position, a.walker.yaw);
      a.looks.push_back({a.look.point, a.look.weight, a.look.actor});
    }
  }
  time_ += dt;
  ++ticks_;
}

}  // namespace gestura
