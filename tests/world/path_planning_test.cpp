// Path planning: Recast/Detour paths pulled tight keep the radius from every obstacle and come within
// 1 % of the exact shortest path — the visibility graph of the obstacles grown by the radius
// (Lozano-Pérez, alias-movement-through-environments.txt §7.2) — on polygonal floor plans; steps and
// ramps are climbed; unreachable goals are a clear "no path".
#include <gtest/gtest.h>

#include <cstdio>

#include "gestura/world/clearance.hpp"
#include "gestura/world/path_planner.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/visibility_graph.hpp"

namespace {

using namespace gestura;

// A floor plan: a floor, walls round it, and prism obstacles given as boxes (any rotation) and
// cylinders of few sides (convex polygons). The test knows each obstacle's footprint exactly.
struct FloorPlan {
  Scene scene;
  std::vector<Polygon2> footprints;

  void box(vec2 centre, vec2 size, float yaw_degrees, float height = 1.0f) {
    SceneObject o;
    o.name = "o" + std::to_string(scene.objects.size());
    o.shape.kind = ShapeKind::Box;
    o.shape.size = vec3(size.x, height, size.y);
    o.transform.position = vec3(centre.x, height * 0.5f, centre.y);
    o.transform.rotation.y = yaw_degrees;
    scene.objects.push_back(o);
    const quat q = o.transform.orientation();
    Polygon2 p;
    for (const vec2 c : {vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1)}) {
      const vec3 w = q * vec3(c.x * size.x * 0.5f, 0.0f, c.y * size.y * 0.5f);
      p.push_back(centre + vec2(w.x, w.z));
    }
    footprints.push_back(convex_hull(p));
  }
  void prism(vec2 centre, float radius, int sides, float height = 1.2f) {
    SceneObject o;
    o.name = "o" + std::to_string(scene.objects.size());
    o.shape.kind = ShapeKind::Cylinder;
    o.shape.radius = radius;
    o.shape.height = height;
    o.shape.segments = sides;
    o.transform.position = vec3(centre.x, height * 0.5f, centre.y);
    scene.objects.push_back(o);
    Polygon2 p;
    for (int i = 0; i < sides; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(sides);
      p.push_back(centre + radius * vec2(std::sin(a), std::cos(a)));
    }
    footprints.push_back(convex_hull(p));
  }
  // A rectangular room [0, w] × [0, d] with walls 0.2 m thick outside it.
  static FloorPlan room(float w, float d) {
    FloorPlan f;
    SceneObject floor;
    floor.name = "floor";
    floor.shape.kind = ShapeKind::Box;
    floor.shape.size = vec3(w + 2.0f, 0.1f, d + 2.0f);
    floor.transform.position = vec3(w * 0.5f, -0.05f, d * 0.5f);
    f.scene.objects.push_back(floor);
    f.box({w * 0.5f, -0.1f}, {w + 0.4f, 0.2f}, 0, 2.5f);
    f.box({w * 0.5f, d + 0.1f}, {w + 0.4f, 0.2f}, 0, 2.5f);
    f.box({-0.1f, d * 0.5f}, {0.2f, d}, 0, 2.5f);
    f.box({w + 0.1f, d * 0.5f}, {0.2f, d}, 0, 2.5f);
    return f;
  }
};

// Nearest distance in the plan from the polyline to any footprint.
float plan_clearance(const std::vector<vec3>& path, const std::vector<Polygon2>& footprints) {
  float best = 1e30f;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const vec2 a(path[i - 1].x, path[i - 1].z), b(path[i].x, path[i].z);
    for (const Polygon2& p : footprints) {
      for (std::size_t k = 0; k < p.size(); ++k)
        best = std::min(best, segment_segment_distance2(a, b, p[k], p[(k + 1) % p.size()]));
    }
  }
  return best;
}

struct Trip {
  vec2 from, to;
};

void expect_near_optimal(FloorPlan& plan, const std::vector<Trip>& trips, float radius, const char* name) {
  validate(plan.scene);
  const SceneGeometry g = build_scene_geometry(plan.scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  std::vector<Polygon2> grown;
  for (const Polygon2& p : plan.footprints) grown.push_back(grow_convex(p, radius));
  for (const Trip& trip : trips) {
    const PlannedPath path = planner.plan({vec3(trip.from.x, 0, trip.from.y), vec3(trip.to.x, 0, trip.to.y), radius});
    ASSERT_EQ(path.status, PathStatus::Found) << name << ": " << path.reason;
    const PlanPath best = visibility_graph_path(grown, trip.from, trip.to);
    ASSERT_TRUE(best.found) << name;
    const float clearance = plan_clearance(path.points, plan.footprints);
    std::printf("%s r=%.2f (%.1f,%.1f)->(%.1f,%.1f): planner %.4f m, visibility graph %.4f m (%+.3f %%), clearance %.4f m, %s\n",
                name, radius, trip.from.x, trip.from.y, trip.to.x, trip.to.y, path.length, best.length,
                100.0f * (path.length - best.length) / best.length, clearance, path.tightened ? "tightened" : "navmesh path");
    EXPECT_GE(clearance, radius - 0.001f) << name;
    EXPECT_LE(std::abs(path.length - best.length), 0.01f * best.length) << name;
    // The path starts and ends where asked.
    EXPECT_NEAR(path.points.front().x, trip.from.x, 0.02f);
    EXPECT_NEAR(path.points.back().z, trip.to.y, 0.02f);
  }
}

TEST(PathPlanning, OfficeFloorPlanWithinOnePercentOfTheVisibilityGraph) {
  FloorPlan plan = FloorPlan::room(10.0f, 8.0f);
  plan.box({3.0f, 4.0f}, {0.8f, 3.0f}, 0.0f);
  plan.box({5.5f, 2.5f}, {1.6f, 0.8f}, 30.0f);
  plan.box({6.5f, 5.6f}, {2.0f, 0.6f}, -20.0f);
  plan.prism({8.0f, 3.0f}, 0.6f, 6);
  plan.prism({1.6f, 6.5f}, 0.5f, 5);
  plan.box({4.8f, 6.8f}, {0.5f, 1.6f}, 45.0f);
  const std::vector<Trip> trips = {{{0.8f, 0.8f}, {9.2f, 7.2f}}, {{0.8f, 4.0f}, {9.3f, 4.5f}}, {{9.0f, 1.0f}, {1.0f, 7.3f}},
                                   {{4.2f, 4.0f}, {7.5f, 4.2f}}, {{2.0f, 1.0f}, {2.0f, 7.4f}}};
  expect_near_optimal(plan, trips, 0.3f, "office");
  expect_near_optimal(plan, trips, 0.45f, "office");
}

TEST(PathPlanning, CorridorOfPillarsWithinOnePercent) {
  FloorPlan plan = FloorPlan::room(12.0f, 4.0f);
  for (int i = 0; i < 5; ++i) plan.prism({2.0f + 2.0f * static_cast<float>(i), i % 2 ? 1.4f : 2.6f}, 0.4f, 8);
  plan.box({6.0f, 3.5f}, {0.3f, 1.0f}, 0.0f);
  expect_near_optimal(plan, {{{0.6f, 2.0f}, {11.4f, 2.0f}}, {{0.6f, 0.6f}, {11.4f, 3.4f}}}, 0.3f, "pillars");
}

TEST(PathPlanning, ConcaveWallsAsUnionsOfBoxes) {
  FloorPlan plan = FloorPlan::room(8.0f, 8.0f);
  // An L of two boxes and a U the path must go round.
  plan.box({3.0f, 2.5f}, {0.3f, 4.0f}, 0.0f);
  plan.box({4.35f, 4.35f}, {3.0f, 0.3f}, 0.0f);
  plan.box({5.5f, 6.0f}, {0.3f, 2.2f}, 10.0f);
  expect_near_optimal(plan, {{{1.0f, 1.0f}, {4.5f, 3.0f}}, {{1.0f, 7.0f}, {7.0f, 1.0f}}}, 0.3f, "concave");
}

TEST(PathPlanning, NarrowDoorPassesSmallWalkersAndStopsWideOnes) {
  FloorPlan plan = FloorPlan::room(8.0f, 6.0f);
  // A wall across the room with a 0.8 m door.
  plan.box({1.8f, 3.0f}, {3.6f, 0.2f}, 0.0f, 2.5f);
  plan.box({6.2f, 3.0f}, {3.6f, 0.2f}, 0.0f, 2.5f);
  const SceneGeometry g = build_scene_geometry(plan.scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath through = planner.plan({vec3(1, 0, 1), vec3(7, 0, 5), 0.25f});
  ASSERT_EQ(through.status, PathStatus::Found) << through.reason;
  EXPECT_GE(plan_clearance(through.points, plan.footprints), 0.249f);
  const PlannedPath wide = planner.plan({vec3(1, 0, 1), vec3(7, 0, 5), 0.45f});
  EXPECT_EQ(wide.status, PathStatus::NoPath);
  EXPECT_NE(wide.reason.find("cannot be reached"), std::string::npos) << wide.reason;
}

TEST(PathPlanning, UnreachableGoalsAreAClearNoPath) {
  FloorPlan plan = FloorPlan::room(8.0f, 6.0f);
  plan.box({4.0f, 3.0f}, {1.0f, 1.0f}, 0.0f);
  // A closed cell in a corner.
  plan.box({6.5f, 4.5f}, {0.2f, 3.0f}, 0.0f, 2.5f);
  plan.box({7.25f, 3.1f}, {1.5f, 0.2f}, 0.0f, 2.5f);
  const SceneGeometry g = build_scene_geometry(plan.scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath inside = planner.plan({vec3(1, 0, 1), vec3(4, 0, 3), 0.3f});
  EXPECT_EQ(inside.status, PathStatus::NoPath);
  EXPECT_NE(inside.reason.find("not on the floor"), std::string::npos) << inside.reason;
  const PlannedPath locked = planner.plan({vec3(1, 0, 1), vec3(7.3f, 0, 5.0f), 0.3f});
  EXPECT_EQ(locked.status, PathStatus::NoPath);
  EXPECT_NE(locked.reason.find("cannot be reached"), std::string::npos) << locked.reason;
  const PlannedPath outside = planner.plan({vec3(1, 0, 1), vec3(30, 0, 30), 0.3f});
  EXPECT_EQ(outside.status, PathStatus::NoPath);
  const PlannedPath nan = planner.plan({vec3(1, 0, 1), vec3(std::nanf(""), 0, 0), 0.3f});
  EXPECT_EQ(nan.status, PathStatus::NoPath);
  // Approaching an object: the nearest reachable floor point next to it.
  PathRequest approach{vec3(1, 0, 1), vec3(4, 0, 3), 0.3f};
  approach.approach = true;
  const PlannedPath near = planner.plan(approach);
  ASSERT_EQ(near.status, PathStatus::Found) << near.reason;
  const vec3 end = near.points.back();
  const float gap = std::max(std::abs(end.x - 4.0f), std::abs(end.z - 3.0f)) - 0.5f;
  EXPECT_GT(gap, 0.29f);
  EXPECT_LT(gap, 0.5f);
}

TEST(PathPlanning, ClimbsStepsAndRampsButNotWalls) {
  // A platform 0.6 m up with two 0.2 m steps on its west side.
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [14, 0.1, 10], "position": [5, -0.05, 3]},
      {"name": "platform", "shape": "box", "size": [3, 0.6, 3], "position": [5, 0.3, 5]},
      {"name": "step1", "shape": "box", "size": [0.3, 0.2, 1.6], "position": [3.05, 0.1, 5]},
      {"name": "step2", "shape": "box", "size": [0.3, 0.4, 1.6], "position": [3.35, 0.2, 5]}
    ]})", "steps.json");
  const SceneGeometry g = build_scene_geometry(scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath up = planner.plan({vec3(1.5f, 0, 5.0f), vec3(5.0f, 0.6f, 5.0f), 0.3f});
  ASSERT_EQ(up.status, PathStatus::Found) << up.reason;
  EXPECT_NEAR(up.points.back().y, 0.6f, 0.05f);
  float highest = 0.0f;
  for (const vec3& p : up.points) highest = std::max(highest, p.y);
  EXPECT_NEAR(highest, 0.6f, 0.05f);

  const Scene no_stairs = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [14, 0.1, 10], "position": [5, -0.05, 3]},
      {"name": "platform", "shape": "box", "size": [3, 0.6, 3], "position": [5, 0.3, 5]}
    ]})", "cliff.json");
  const SceneGeometry g2 = build_scene_geometry(no_stairs);
  const Environment env2 = build_environment(g2);
  PathPlanner planner2(env2);
  const PlannedPath cliff = planner2.plan({vec3(3.0f, 0, 2.0f), vec3(5.0f, 0.6f, 5.0f), 0.3f});
  EXPECT_EQ(cliff.status, PathStatus::NoPath) << "a 0.6 m wall was climbed";

  // A ramp of 20°: walked.
  const Scene ramp = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [14, 0.1, 10], "position": [5, -0.05, 3]},
      {"name": "platform", "shape": "box", "size": [3, 0.6, 3], "position": [5, 0.3, 5]},
      {"name": "ramp", "shape": "box", "size": [1.2, 0.05, 1.8], "position": [5, 0.29, 2.66], "rotation": [-20, 0, 0]}
    ]})", "ramp.json");
  const SceneGeometry g3 = build_scene_geometry(ramp);
  const Environment env3 = build_environment(g3);
  PathPlanner planner3(env3);
  const PlannedPath walk_up = planner3.plan({vec3(5.0f, 0, 0.5f), vec3(5.0f, 0.6f, 5.5f), 0.3f});
  ASSERT_EQ(walk_up.status, PathStatus::Found) << walk_up.reason;
  EXPECT_NEAR(walk_up.points.back().y, 0.6f, 0.05f);
}

}  // namespace
