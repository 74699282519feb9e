// Autonomous actors: virtual vision sees what is in view and not what a wall or another body hides;
// hearing takes in sounds within range, less far through walls; touch feels overlapping bodies and
// near walls; the look behaviour turns to whoever signs; walkers avoid each other and followers
// follow; everything is deterministic under a seed.
#include <gtest/gtest.h>

#include "gestura/world/behaviour.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/simulation.hpp"

namespace {

using namespace gestura;

struct Room {
  Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [14, 0.1, 10], "position": [5, -0.05, 3]},
      {"name": "wall", "shape": "box", "size": [0.2, 2.5, 3.0], "position": [5, 1.25, 1.5]}
    ]})", "room.json");
  SceneGeometry geometry = build_scene_geometry(scene);
  Environment env = build_environment(geometry);
};

ActorView at(float x, float z, float yaw_degrees) {
  ActorView a;
  a.position = vec3(x, 0, z);
  a.yaw = deg(yaw_degrees);
  return a;
}

bool sees(const Room& r, const std::vector<ActorView>& actors, int self, int other) {
  Percept p;
  see(r.env, actors, self, {}, {}, VisionParams{}, p);
  for (const SeenActor& s : p.actors)
    if (s.actor == other) return true;
  return false;
}

TEST(Actors, VisionSeesWhatIsInViewAndNotWhatIsHidden) {
  const Room r;
  // Facing each other across open floor (+X is yaw 90°).
  EXPECT_TRUE(sees(r, {at(2, 5, 90), at(8, 5, -90)}, 0, 1));
  // The wall (x = 5, z 0..3) between them.
  EXPECT_FALSE(sees(r, {at(2, 1.5f, 90), at(8, 1.5f, -90)}, 0, 1));
  // Behind the watcher: out of its field of view (200°), while the other, facing it, sees it.
  EXPECT_FALSE(sees(r, {at(2, 5, -90), at(5, 5, -90)}, 0, 1));
  EXPECT_TRUE(sees(r, {at(2, 5, -90), at(5, 5, -90)}, 1, 0));
  // Hidden behind a third body standing right in front of the watcher.
  EXPECT_FALSE(sees(r, {at(2, 5, 90), at(8, 5, -90), at(2.5f, 5, -90)}, 0, 1));
  // Too far.
  EXPECT_FALSE(sees(r, {at(-1.5f, 7.5f, 90), at(11.5f, 7.5f, -90)}, 0, 1));
  // Objects: the wall is seen from the open side.
  Percept p;
  const std::vector<std::pair<int, vec3>> objects = {{1, vec3(5, 1.2f, 1.5f)}};
  const std::vector<ActorView> one = {at(2, 1.5f, 90)};
  see(r.env, one, 0, {}, objects, VisionParams{}, p);
  ASSERT_EQ(p.objects.size(), 1u);
  EXPECT_NEAR(p.objects[0].distance, 3.05f, 0.1f);
}

TEST(Actors, HearingAndTouch) {
  const Room r;
  const std::vector<ActorView> actors = {at(2, 1.5f, 0), at(6.0f, 1.5f, 0), at(2.2f, 1.7f, 0)};
  const std::vector<SoundEvent> events = {{vec3(12, 1, 1.5f), 1.0f, "door", -1, 0.0f},  // 10 m away, behind the wall
                                          {vec3(8, 1, 1.5f), 1.0f, "knock", -1, 0.0f}};  // 6 m, behind the wall
  Percept p;
  hear(r.env, actors, 0, events, 15.0f, p);
  ASSERT_EQ(p.heard.size(), 1u);  // 10 m through a wall is beyond half the range; 6 m is within
  EXPECT_EQ(p.heard[0].event, 1);
  EXPECT_FALSE(p.heard[0].direct);
  hear(r.env, actors, 1, events, 15.0f, p);
  EXPECT_EQ(p.heard.size(), 2u);  // the other side of the wall: both direct
  touch(r.env, actors, 0, p);
  ASSERT_FALSE(p.touches.empty());
  EXPECT_EQ(p.touches[0].actor, 2);
  touch(r.env, actors, 1, p);  // 1 m from the wall: no touch
  EXPECT_TRUE(p.touches.empty());
  const std::vector<ActorView> at_wall = {at(4.8f, 1.5f, 90)};
  touch(r.env, at_wall, 0, p);
  ASSERT_EQ(p.touches.size(), 1u);
  EXPECT_EQ(p.touches[0].object, 1);
}

TEST(Actors, LookBehaviourTurnsToWhoeverSigns) {
  const Room r;
  std::vector<ActorView> actors = {at(2, 5, 90), at(6, 5, -90), at(6, 7, -120)};
  actors[2].signing = true;
  Percept p;
  see(r.env, actors, 0, {}, {}, VisionParams{}, p);
  LookState state;
  LookIntent look = choose_look(actors, 0, p, {}, LookInputs{}, state);
  EXPECT_EQ(look.actor, 2);
  EXPECT_EQ(look.why, "signer");
  // A second signer starts: the gaze stays with the first while it signs.
  actors[1].signing = true;
  see(r.env, actors, 0, {}, {}, VisionParams{}, p);
  look = choose_look(actors, 0, p, {}, LookInputs{}, state);
  EXPECT_EQ(look.actor, 2);
  actors[2].signing = false;
  see(r.env, actors, 0, {}, {}, VisionParams{}, p);
  look = choose_look(actors, 0, p, {}, LookInputs{}, state);
  EXPECT_EQ(look.actor, 1);
  // A signer behind the wall is not looked at: it is not seen.
  std::vector<ActorView> hidden = {at(2, 1.5f, 90), at(8, 1.5f, -90)};
  hidden[1].signing = true;
  see(r.env, hidden, 0, {}, {}, VisionParams{}, p);
  LookState fresh;
  EXPECT_EQ(choose_look(hidden, 0, p, {}, LookInputs{}, fresh).actor, -1);
  // A sound: a glance toward it.
  const std::vector<SoundEvent> sounds = {{vec3(2, 1, 9), 1.0f, "door", -1, 1.0f}};
  hear(r.env, hidden, 0, sounds, 15.0f, p);
  LookInputs in;
  in.now = 1.05f;
  const LookIntent glance = choose_look(hidden, 0, p, sounds, in, fresh);
  EXPECT_EQ(glance.why, "sound");
  EXPECT_NEAR(glance.point.z, 9.0f, 1e-4f);
}

TEST(Actors, WalkersMeetingHeadOnKeepRightAndDoNotCollide) {
  const Room r;
  SimulationOptions options;
  Simulation sim(r.geometry, options);
  const int a = sim.add_actor({"a", vec3(-1, 0, 6), deg(90), 0.3f, 1.7f, 1.3f});
  const int b = sim.add_actor({"b", vec3(11, 0, 6), deg(-90), 0.3f, 1.7f, 1.3f});
  ASSERT_EQ(sim.walk_to(a, vec3(11, 0, 6)).status, PathStatus::Found);
  ASSERT_EQ(sim.walk_to(b, vec3(-1, 0, 6)).status, PathStatus::Found);
  float nearest = 1e30f;
  for (int i = 0; i < 60 * 20 && !sim.idle(); ++i) {
    sim.step();
    nearest = std::min(nearest, glm::length(sim.actor(a).view.position - sim.actor(b).view.position));
  }
  EXPECT_TRUE(sim.idle());
  EXPECT_GT(nearest, 0.6f) << "the bodies met";
  EXPECT_NEAR(sim.actor(a).view.position.x, 11.0f, 0.05f);
  EXPECT_NEAR(sim.actor(b).view.position.x, -1.0f, 0.05f);
  // Each stepped aside from the line they met on.
  float a_side = 0.0f, b_side = 0.0f;
  for (std::size_t k = 0; k < sim.actor(a).trajectory.size(); ++k) {
    a_side = std::max(a_side, std::abs(sim.actor(a).trajectory.positions[k].z - 6.0f));
    b_side = std::max(b_side, std::abs(sim.actor(b).trajectory.positions[k].z - 6.0f));
  }
  EXPECT_GT(a_side, 0.2f);
  EXPECT_GT(b_side, 0.2f);
}

TEST(Actors, AFollowerKeepsItsDistanceAndFacesTheFollowed) {
  const Room r;
  Simulation sim(r.geometry);
  const int leader = sim.add_actor({"leader", vec3(0, 0, 7), deg(90), 0.3f, 1.7f, 1.2f});
  const int follower = sim.add_actor({"follower", vec3(-1, 0, 8), deg(90), 0.3f, 1.7f, 1.3f});
  sim.follow(follower, leader, 1.5f);
  ASSERT_EQ(sim.walk_to(leader, vec3(9, 0, 8)).status, PathStatus::Found);
  for (int i = 0; i < 60 * 15; ++i) sim.step();
  const vec3 l = sim.actor(leader).view.position, f = sim.actor(follower).view.position;
  const float gap = glm::length(vec2(l.x - f.x, l.z - f.z));
  EXPECT_GT(gap, 1.2f);
  EXPECT_LT(gap, 1.5f + 0.4f);
  EXPECT_LT(std::abs(angle_difference(sim.actor(follower).view.yaw, yaw_of(l - f))), deg(36.0f));
}

TEST(Actors, DeterministicUnderASeed) {
  const Room r;
  auto run = [&](std::uint64_t seed) {
    SimulationOptions options;
    options.seed = seed;
    Simulation sim(r.geometry, options);
    std::vector<int> ids;
    for (int i = 0; i < 12; ++i) ids.push_back(sim.add_actor({"a" + std::to_string(i), vec3(0.5f + static_cast<float>(i % 4) * 3.0f, 0, 4.5f + static_cast<float>(i / 4) * 1.6f), 0.0f, 0.3f, 1.7f, 1.3f}));
    std::uniform_real_distribution<float> x(-0.5f, 11.5f), z(4.0f, 7.5f);
    for (int id : ids) sim.walk_to(id, vec3(x(sim.random()), 0, z(sim.random())));
    for (int i = 0; i < 60 * 6; ++i) sim.step();
    std::vector<vec3> out;
    for (int id : ids) out.push_back(sim.actor(id).view.position);
    return out;
  };
  const auto a = run(7), b = run(7), c = run(8);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) differs = differs || a[i] != c[i];
  EXPECT_TRUE(differs);
}

}  // namespace
