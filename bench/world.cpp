// The world (issue "A sense of where they are"): path queries in a 24 × 24 m room with 100 obstacles
// (the navigation meshes built once, outside the timing), walk synthesis per second of motion, and
// 100 characters walking to random goals and avoiding each other, per simulation frame. The
// obstacles, start/goal pairs and goals come from fixed seeds, so every run measures the same work.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>

#include "gestura/body/avatar.hpp"
#include "gestura/world/locomotion.hpp"
#include "gestura/world/path_planner.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/simulation.hpp"
#include "gestura/world/walk.hpp"

namespace {

using namespace gestura;

constexpr float kRoom = 24.0f;

// A walled room with `count` boxes and prisms at seeded places, none on the spots `keep` lists.
Scene obstacle_room(int count, std::uint64_t seed) {
  Scene s;
  auto box = [&](const std::string& name, vec3 size, vec3 at, float yaw) {
    SceneObject o;
    o.name = name;
    o.shape.kind = ShapeKind::Box;
    o.shape.size = size;
    o.transform.position = at;
    o.transform.rotation.y = yaw;
    s.objects.push_back(o);
  };
  box("floor", vec3(kRoom + 1, 0.1f, kRoom + 1), vec3(kRoom * 0.5f, -0.05f, kRoom * 0.5f), 0);
  box("wall_n", vec3(kRoom, 2.5f, 0.2f), vec3(kRoom * 0.5f, 1.25f, -0.1f), 0);
  box("wall_s", vec3(kRoom, 2.5f, 0.2f), vec3(kRoom * 0.5f, 1.25f, kRoom + 0.1f), 0);
  box("wall_w", vec3(0.2f, 2.5f, kRoom), vec3(-0.1f, 1.25f, kRoom * 0.5f), 0);
  box("wall_e", vec3(0.2f, 2.5f, kRoom), vec3(kRoom + 0.1f, 1.25f, kRoom * 0.5f), 0);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<float> where(1.5f, kRoom - 1.5f), size(0.3f, 1.4f), turn(0.0f, 180.0f);
  for (int i = 0; i < count; ++i) {
    const vec3 at(where(random), 0.0f, where(random));
    if (i % 3 == 2) {
      SceneObject o;
      o.name = "pillar" + std::to_string(i);
      o.shape.kind = ShapeKind::Cylinder;
      o.shape.radius = size(random) * 0.4f;
      o.shape.height = 1.2f;
      o.shape.segments = 8;
      o.transform.position = at + vec3(0, 0.6f, 0);
      s.objects.push_back(o);
    } else {
      box("box" + std::to_string(i), vec3(size(random), 1.0f, size(random)), at + vec3(0, 0.5f, 0), turn(random));
    }
  }
  return s;
}

struct Room {
  Scene scene = obstacle_room(100, 2024);
  SceneGeometry geometry = build_scene_geometry(scene);
  Environment env = build_environment(geometry);
  std::unique_ptr<PathPlanner> planner = std::make_unique<PathPlanner>(env);
  std::vector<std::pair<vec3, vec3>> trips;
  Room() {
    // Trips between free floor points (snapped onto the mesh), fixed by a seed.
    const NavMesh& mesh = planner->navmesh(0.3f, false);
    planner->navmesh(0.3f, true);
    std::mt19937_64 random(99);
    std::uniform_real_distribution<float> where(0.8f, kRoom - 0.8f);
    while (trips.size() < 32) {
      const auto a = mesh.nearest_point(vec3(where(random), 0, where(random)), vec3(0.3f, 0.5f, 0.3f));
      const auto b = mesh.nearest_point(vec3(where(random), 0, where(random)), vec3(0.3f, 0.5f, 0.3f));
      if (a && b && glm::length(*a - *b) > 8.0f) trips.push_back({*a, *b});
    }
  }
};

Room& room() {
  static Room r;
  return r;
}

void BM_World_NavMeshBuild100Obstacles(benchmark::State& state) {
  Room& r = room();
  int polygons = 0;
  for (auto _ : state) {
    NavMeshSettings s;
    s.agent_radius = 0.3f;
    NavMesh mesh = NavMesh::build(r.env, s);
    polygons = mesh.polygon_count();
    benchmark::DoNotOptimize(polygons);
  }
  state.counters["polygons"] = polygons;
  state.counters["triangles"] = static_cast<double>(r.env.triangle_count());
}
BENCHMARK(BM_World_NavMeshBuild100Obstacles)->Unit(benchmark::kMillisecond);

// The whole query: Detour's corridor, the visibility search over the floor's corners, the path
// pulled tight to the radius and checked against the geometry.
void BM_World_PathQuery100Obstacles(benchmark::State& state) {
  Room& r = room();
  std::size_t k = 0;
  double length = 0.0, found = 0.0, queries = 0.0;
  for (auto _ : state) {
    const auto& [a, b] = r.trips[k++ % r.trips.size()];
    const PlannedPath p = r.planner->plan({a, b, 0.3f});
    benchmark::DoNotOptimize(p.length);
    length += p.length, found += p.status == PathStatus::Found, queries += 1.0;
  }
  state.counters["found"] = found / queries;
  state.counters["mean_length_m"] = length / queries;
}
BENCHMARK(BM_World_PathQuery100Obstacles)->Unit(benchmark::kMicrosecond);

// Detour alone (corridor and string-pulled corners), for comparison.
void BM_World_DetourFindPath100Obstacles(benchmark::State& state) {
  Room& r = room();
  const NavMesh& mesh = r.planner->navmesh(0.3f, true);
  std::size_t k = 0;
  for (auto _ : state) {
    const auto& [a, b] = r.trips[k++ % r.trips.size()];
    const NavPath p = mesh.find_path(a, b);
    benchmark::DoNotOptimize(p.points.data());
  }
}
BENCHMARK(BM_World_DetourFindPath100Obstacles)->Unit(benchmark::kMicrosecond);

// The walking skill: footsteps, pelvis, legs by IK, arms, over a 20 s walk with bends and stops,
// per second of motion (60 frames).
void BM_World_WalkSynthesisPerSecond(benchmark::State& state) {
  static const Avatar avatar = build_avatar();
  static const WalkRig rig = make_walk_rig(avatar);
  Room& r = room();
  // A tour through the room along planned paths, standing a moment at each stop.
  RootTrajectory body;
  body.dt = 1.0f / 60.0f;
  float yaw = 0.0f;
  for (std::size_t i = 0; i < 3; ++i) {
    const PlannedPath p = r.planner->plan({i == 0 ? r.trips[0].first : body.positions.back(), r.trips[i].second, 0.3f});
    const RootTrajectory leg = follow_path(p.points, yaw, std::nullopt, {}, body.dt, 0.3f, &r.env);
    for (std::size_t k = 0; k < leg.size(); ++k) body.push(leg.positions[k], leg.yaws[k]);
    yaw = body.yaws.back();
  }
  for (auto _ : state) {
    WalkMotion w = synthesize_walk(rig, body, &r.env);
    benchmark::DoNotOptimize(w.clip.rotations.data());
  }
  // items = seconds of motion: items_per_second is how many seconds of walking one second synthesizes.
  state.counters["motion_s"] = body.duration();
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * body.duration()));
}
BENCHMARK(BM_World_WalkSynthesisPerSecond)->Unit(benchmark::kMillisecond);

// 100 characters in the room, each walking to a random goal and, when there, to the next; every
// frame they sense (staggered: each actor's vision, hearing and touch every 6th frame), avoid each
// other and move. Per simulation frame (1/60 s).
void BM_World_Crowd100Walkers(benchmark::State& state) {
  Room& r = room();
  SimulationOptions options;
  options.record = false;
  options.seed = 5;
  Simulation sim(r.geometry, options);
  const NavMesh& mesh = sim.planner().navmesh(0.3f, false);
  std::uniform_real_distribution<float> where(0.8f, kRoom - 0.8f);
  auto free_point = [&] {
    for (;;)
      if (const auto p = mesh.nearest_point(vec3(where(sim.random()), 0, where(sim.random())), vec3(0.3f, 0.5f, 0.3f))) return *p;
  };
  for (int i = 0; i < 100; ++i) sim.add_actor({"w" + std::to_string(i), free_point(), 0.0f, 0.3f, 1.7f, 1.2f});
  auto new_goals = [&] {
    for (std::size_t i = 0; i < sim.actor_count(); ++i)
      if (!sim.actor(static_cast<int>(i)).walker.busy()) sim.walk_to(static_cast<int>(i), free_point());
  };
  new_goals();
  for (int i = 0; i < 120; ++i) sim.step();  // under way
  for (auto _ : state) {
    sim.step();
    if (sim.ticks() % 30 == 0) {
      state.PauseTiming();  // new goals (path planning) are not part of a frame's cost
      new_goals();
      state.ResumeTiming();
    }
  }
  int walking = 0;
  for (std::size_t i = 0; i < sim.actor_count(); ++i) walking += sim.actor(static_cast<int>(i)).walker.busy();
  state.counters["walking"] = walking;
  state.counters["actors"] = static_cast<double>(sim.actor_count());
}
BENCHMARK(BM_World_Crowd100Walkers)->Unit(benchmark::kMicrosecond);

}  // namespace
