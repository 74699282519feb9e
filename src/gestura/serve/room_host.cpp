#include "gestura/serve/room_host.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/world/character_motion.hpp"
#include "gestura/world/locomotion.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/sensors.hpp"

namespace gestura::serve {
namespace {

ActorView view_of(const SeatView& s) {
  ActorView a;
  a.position = s.position;
  a.yaw = s.yaw;
  a.height = s.height;
  a.signing = s.signing;
  a.radius = 0.18f;  // a body standing still, not a walker's clearance: seats on the arc do not hide one another
  return a;
}

}  // namespace

HostLook choose_host_look(const SeatView& host, std::span<const SeatView> seats, int arrived, float now, LookState& state) {
  // Actor 0 is the host, then the seats someone sits in.
  std::vector<ActorView> actors{view_of(host)};
  std::vector<int> seat_of{-1};
  for (std::size_t k = 0; k < seats.size(); ++k)
    if (seats[k].present) actors.push_back(view_of(seats[k])), seat_of.push_back(static_cast<int>(k));
  Percept percept;
  see(Environment{}, actors, 0, {}, {}, VisionParams{}, percept);
  std::vector<SoundEvent> events;
  const auto arrived_actor = std::find(seat_of.begin(), seat_of.end(), arrived);
  if (arrived >= 0 && arrived_actor != seat_of.end()) {
    SoundEvent e;
    e.position = eye_point(actors[static_cast<std::size_t>(arrived_actor - seat_of.begin())]);
    e.what = "arrival";
    e.source_actor = static_cast<int>(arrived_actor - seat_of.begin());
    e.time = now;
    events.push_back(e);
    percept.heard.push_back(Heard{0, glm::length(e.position - host.position), true});
  }
  LookInputs inputs;
  inputs.now = now;
  const LookIntent intent = choose_look(actors, 0, percept, events, inputs, state);
  HostLook out;
  out.why = intent.why;
  if (intent.weight <= 0.0f) return out;  // straight ahead
  out.point = intent.point;
  out.seat = intent.actor > 0 ? seat_of[static_cast<std::size_t>(intent.actor)] : -1;
  return out;
}

HostGaze::HostGaze(std::shared_ptr<const Skeleton> skeleton, std::vector<mat4> bind_model)
    : skeleton_(std::move(skeleton)), bind_(std::move(bind_model)) {}

JointRotations HostGaze::look_at(const SeatView& host, const vec3& point) const {
  const Skeleton& s = *skeleton_;
  Pose pose = rest_pose(s);
  // The point in the host's model space (the host turned by its yaw about +Y).
  const vec3 d = point - host.position;
  const float c = std::cos(-host.yaw), sn = std::sin(-host.yaw);
  const vec3 local(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z);
  std::vector<mat4> model(s.size());  // apply_look_at's scratch, one matrix a joint
  apply_look_at(s, pose, local, 1.0f, bind_, model);
  JointRotations out;
  for (const char* name : {"vc4", "skullbase", "l_eyeball_joint", "r_eyeball_joint"}) {
    const int j = s.find(name);
    if (j < 0) continue;
    const quat& q = pose.rotations[static_cast<std::size_t>(j)];
    out.push_back({name, {q.x, q.y, q.z, q.w}});
  }
  return out;
}

HostStop stop_facing(const SeatView& seat, float distance, float aside) {
  // Toward the room's middle, turned `aside` to the side further from the viewers (the page's camera
  // looks from +Z): the host then never stands between the viewers and the signer's hands.
  const float a = heading(seat.yaw + aside).z < heading(seat.yaw - aside).z ? seat.yaw + aside : seat.yaw - aside;
  HostStop stop;
  stop.position = seat.position + heading(a) * distance;
  stop.position.y = seat.position.y;
  stop.yaw = yaw_of(seat.position - stop.position);
  return stop;
}

namespace {

Environment room_environment(std::span<const vec3> seats) {
  Scene scene;
  scene.name = "room";
  SceneObject floor;
  floor.name = "floor";
  floor.shape.kind = ShapeKind::Box;
  floor.shape.size = vec3(8.0f, 0.1f, 8.0f);
  floor.transform.position = vec3(0.0f, -0.05f, -0.6f);  // under the page's floor disc (radius 3.4 about z = -0.6)
  scene.objects.push_back(floor);
  for (std::size_t k = 0; k < seats.size(); ++k) {
    SceneObject body;
    body.name = "seat" + std::to_string(k);
    body.shape.kind = ShapeKind::Cylinder;
    body.shape.radius = RoomWorld::kSeatRadius;
    body.shape.height = 1.8f;
    body.shape.segments = 16;
    body.transform.position = seats[k] + vec3(0.0f, 0.9f, 0.0f);
    scene.objects.push_back(body);
  }
  validate(scene);
  return build_environment(build_scene_geometry(scene));
}

}  // namespace

RoomWorld::RoomWorld(std::span<const vec3> seats)
    : seats_(seats.begin(), seats.end()), env_(room_environment(seats)), planner_(std::make_unique<PathPlanner>(env_)) {}

std::optional<HostWalkPlan> RoomWorld::plan(const HostStop& from, const HostStop& to) {
  PlannedPath path;
  {
    std::lock_guard lock(mutex_);
    path = planner_->plan(PathRequest{from.position, to.position, kHostRadius});
  }
  if (path.status != PathStatus::Found || path.points.size() < 2) return std::nullopt;
  HostWalkPlan plan;
  plan.length = path.length;
  LocomotionParams walking;
  walking.speed = 1.0f;  // an unhurried host indoors
  plan.body = follow_path(path.points, from.yaw, to.yaw, walking, 1.0f / 60.0f, 0.2f, &env_);
  plan.path = std::move(path.points);
  return plan;
}

}  // namespace gestura::serve
