// The walking skill: planted feet stay put through heel strike, foot flat and heel off (< 1 cm), the
// phases follow §6.1's order, steps start short and end side by side, turning on the spot steps
// round, stairs are climbed tread by tread, arms swing against the legs, and no part of the skin
// goes more than 1 cm into walls or furniture along a walk planned through a furnished room.
#include <gtest/gtest.h>

#include "support/signing_avatar.hpp"

#include "gestura/anim/sampler.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/world/body_collision.hpp"
#include "gestura/world/locomotion.hpp"
#include "gestura/world/path_planner.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/walk.hpp"

namespace {

using namespace gestura;

const Avatar& avatar() { return test::signing_avatar().avatar; }

struct Posed {
  std::vector<mat4> model;
};

Posed pose_at(const Clip& clip, float t) {
  const Skeleton& s = avatar().skeleton;
  Pose pose;
  sample_clip(clip, t, WrapMode::Clamp, rest_pose(s), pose);
  Posed out;
  out.model.resize(s.size());
  local_to_model(s, pose, out.model);
  return out;
}

// Largest slide of the pivots over every stance: the foot rolls over its heel through heel strike,
// then over its ball (foot flat, mid-stance, heel off, toe off) until it lifts — each pivot must stay
// where it touched down while it is down (within 1 cm of its height then: a heel lifting off is not
// sliding). The heel is carried by the subtalar joint, the ball by the midtarsal.
float worst_slide(const WalkRig& rig, const WalkMotion& walk, const GaitParams& p, int* stances = nullptr) {
  float worst = 0.0f;
  int counted = 0;
  std::vector<mat4> rest(avatar().skeleton.size());
  local_to_model(avatar().skeleton, rest_pose(avatar().skeleton), rest);
  for (int foot = 0; foot < 2; ++foot) {
    const LegRig& leg = rig.legs[static_cast<std::size_t>(foot)];
    const vec3 heel_local = vec3(glm::inverse(rest[static_cast<std::size_t>(leg.subtalar)]) * vec4(leg.plant_origin + leg.heel, 1.0f));
    const vec3 ball_local = vec3(glm::inverse(rest[static_cast<std::size_t>(leg.midtarsal)]) * vec4(leg.plant_origin + leg.ball, 1.0f));
    const std::vector<std::size_t>& mine = walk.steps.of_foot[foot];
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const Footstep& s = walk.steps.steps[mine[k]];
      const float end = k + 1 < mine.size() ? walk.steps.steps[mine[k + 1]].lift : walk.clip.duration;
      vec3 heel0(0.0f), ball0(0.0f);
      bool ball_set = false;
      for (int i = 0; i < 120; ++i) {
        const float t = s.land + (end - s.land) * static_cast<float>(i) / 120.0f;
        const FootState st = foot_state(walk.steps, foot, t, p);
        if (st.swinging) break;
        const Posed posed = pose_at(walk.clip, t);
        const vec3 heel = vec3(posed.model[static_cast<std::size_t>(leg.subtalar)] * vec4(heel_local, 1.0f));
        const vec3 ball = vec3(posed.model[static_cast<std::size_t>(leg.midtarsal)] * vec4(ball_local, 1.0f));
        if (i == 0) heel0 = heel;
        if (st.phase == GaitPhase::HeelStrike) {
          if (heel.y - heel0.y < 0.01f) worst = std::max(worst, glm::length(heel - heel0));
        } else {
          if (!ball_set) ball0 = ball, ball_set = true;
          if (ball.y - ball0.y < 0.01f) worst = std::max(worst, glm::length(ball - ball0));
        }
      }
      ++counted;
    }
  }
  if (stances) *stances = counted;
  return worst;
}

struct SkinDepth {
  float depth = 0.0f;        // deepest skin vertex inside a primitive (other than `floor_object`)
  float below_floor = 0.0f;  // deepest skin vertex below y = 0
  std::string where;
};

// Skins the avatar along the walk every `step` seconds and measures the skin against the scene's
// exact primitive shapes.
SkinDepth deepest_skin_point(const WalkMotion& walk, const Environment& env, const SceneGeometry& g, int floor_object, float step) {
  const Avatar& a = avatar();
  std::vector<mat4> inverse_bind(a.skeleton.size()), skinning(a.skeleton.size());
  {
    std::vector<mat4> bind(a.skeleton.size());
    local_to_model(a.skeleton, rest_pose(a.skeleton), bind);
    for (std::size_t j = 0; j < bind.size(); ++j) inverse_bind[j] = glm::inverse(bind[j]);
  }
  Environment solids = env;
  solids.primitives.erase(std::remove_if(solids.primitives.begin(), solids.primitives.end(),
                                         [&](const WorldPrimitive& w) { return w.object == floor_object; }),
                          solids.primitives.end());
  std::vector<vec3> skin(a.mesh.vertex_count());
  SkinDepth out;
  for (float t = 0.0f; t <= walk.clip.duration; t += step) {
    const Posed posed = pose_at(walk.clip, t);
    skinning_matrices(posed.model, inverse_bind, skinning);
    skin_positions(skinning, a.mesh.joints, a.mesh.weights, a.mesh.positions, skin);
    for (const vec3& v : skin) {
      int object = -1;
      const float d = primitive_signed_distance(solids, v, &object);
      if (-d > out.depth) out.depth = -d, out.where = g.object_names[static_cast<std::size_t>(object)] + " at t=" + std::to_string(t);
      out.below_floor = std::max(out.below_floor, -v.y);
    }
  }
  return out;
}

TEST(Walk, PlantedFeetDoNotSlideOnFlatGround) {
  const WalkRig rig = make_walk_rig(avatar());
  const std::vector<vec3> path = {vec3(0, 0, 0), vec3(3, 0, 0), vec3(4.5f, 0, 2.0f)};
  const RootTrajectory body = follow_path(path, deg(90), deg(0));
  const GaitParams params;
  const WalkMotion walk = synthesize_walk(rig, body, nullptr, params);
  int stances = 0;
  const float slide = worst_slide(rig, walk, params, &stances);
  std::printf("flat walk: %zu steps, worst pivot slide %.2f mm over %d stances\n", walk.steps.steps.size(), slide * 1000.0f, stances);
  EXPECT_GE(walk.steps.steps.size(), 8u);
  EXPECT_LT(slide, 0.01f);
}

TEST(Walk, PhasesFollowTheWalkCycle) {
  const WalkRig rig = make_walk_rig(avatar());
  const std::vector<vec3> path = {vec3(0, 0, 0), vec3(0, 0, 6)};
  const RootTrajectory body = follow_path(path, 0.0f, std::nullopt);
  const GaitParams p;
  const WalkMotion walk = synthesize_walk(rig, body, nullptr, p);
  // Over one steady stride of the left foot the phases come in §6.1's order, each once.
  const Footstep& s = walk.steps.steps[walk.steps.of_foot[0][1]];
  const Footstep& next = walk.steps.steps[walk.steps.of_foot[0][2]];
  std::vector<GaitPhase> seen;
  for (float t = s.land + 1e-3f; t < next.land; t += 1.0f / 240.0f) {
    const GaitPhase ph = foot_state(walk.steps, 0, t, p).phase;
    if (seen.empty() || seen.back() != ph) seen.push_back(ph);
  }
  const std::vector<GaitPhase> expected = {GaitPhase::HeelStrike, GaitPhase::FootFlat, GaitPhase::MidStance, GaitPhase::HeelOff,
                                           GaitPhase::ToeOff,     GaitPhase::EarlySwing, GaitPhase::MidSwing, GaitPhase::LateSwing};
  ASSERT_EQ(seen.size(), expected.size());
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], expected[i]) << gait_phase_name(seen[i]);
  // Stance about 60 % of the cycle.
  const float stance = (next.lift - s.land) / (next.land - s.land);
  EXPECT_GT(stance, 0.55f);
  EXPECT_LT(stance, 0.68f);
}

TEST(Walk, StartsWithAShortStepAndStopsWithFeetTogether) {
  const WalkRig rig = make_walk_rig(avatar());
  const RootTrajectory body = follow_path(std::vector<vec3>{vec3(0, 0, 0), vec3(0, 0, 5)}, 0.0f, std::nullopt);
  const WalkMotion walk = synthesize_walk(rig, body, nullptr);
  const auto& steps = walk.steps.steps;
  ASSERT_GE(steps.size(), 6u);
  auto advance = [&](std::size_t i) {
    const Footstep& before = i >= 2 ? steps[i - 2] : walk.steps.initial[steps[i].foot];
    return steps[i].position.z - before.position.z;
  };
  const float cruise = advance(steps.size() / 2);
  EXPECT_LT(advance(0), 0.8f * cruise);
  EXPECT_GT(cruise, 0.55f * 2.0f);  // a stride of two steps of ≥ 0.55 m at 1.3 m/s
  const Footstep& l = walk.steps.steps[walk.steps.of_foot[0].back()];
  const Footstep& r = walk.steps.steps[walk.steps.of_foot[1].back()];
  EXPECT_NEAR(std::abs(l.position.z - r.position.z), 0.0f, 0.03f);
  EXPECT_NEAR(l.position.x - r.position.x, rig.stance_width, 0.03f);
  // Standing at the end: both feet flat, the body over them.
  const Posed end = pose_at(walk.clip, walk.clip.duration);
  EXPECT_NEAR(end.model[static_cast<std::size_t>(rig.root)][3].z, 5.0f, 0.05f);
}

TEST(Walk, TurningOnTheSpotStepsRound) {
  const WalkRig rig = make_walk_rig(avatar());
  RootTrajectory body;
  body.dt = 1.0f / 60.0f;
  for (int i = 0; i <= 240; ++i) {
    const float t = static_cast<float>(i) * body.dt;
    const float turn = std::clamp((t - 0.5f) / 2.0f, 0.0f, 1.0f);
    body.push(vec3(1.0f, 0.0f, 2.0f), deg(150.0f) * (3 * turn * turn - 2 * turn * turn * turn));
  }
  const GaitParams p;
  const WalkMotion walk = synthesize_walk(rig, body, nullptr, p);
  EXPECT_GE(walk.steps.steps.size(), 4u);
  EXPECT_EQ(walk.steps.steps.front().foot, 0);  // turning left: the left foot leads
  for (const Footstep& s : walk.steps.steps) EXPECT_LT(glm::length(vec2(s.position.x - 1.0f, s.position.z - 2.0f)), 0.2f);
  const Footstep& l = walk.steps.steps[walk.steps.of_foot[0].back()];
  const Footstep& r = walk.steps.steps[walk.steps.of_foot[1].back()];
  EXPECT_NEAR(angle_difference(l.yaw, deg(150.0f) + p.toe_out), 0.0f, deg(7.0f));
  EXPECT_NEAR(angle_difference(r.yaw, deg(150.0f) - p.toe_out), 0.0f, deg(7.0f));
  EXPECT_LT(worst_slide(rig, walk, p), 0.01f);
}

TEST(Walk, ArmsSwingAgainstTheLegs) {
  const WalkRig rig = make_walk_rig(avatar());
  const RootTrajectory body = follow_path(std::vector<vec3>{vec3(0, 0, 0), vec3(0, 0, 6)}, 0.0f, std::nullopt);
  const WalkMotion walk = synthesize_walk(rig, body, nullptr);
  int checked = 0;
  for (const Footstep& s : walk.steps.steps) {
    if (s.land < 1.5f || s.land > walk.clip.duration - 1.5f) continue;  // steady walking
    const Posed posed = pose_at(walk.clip, s.land);
    const float left_hand = posed.model[static_cast<std::size_t>(rig.wrists[0])][3].z;
    const float right_hand = posed.model[static_cast<std::size_t>(rig.wrists[1])][3].z;
    // The landing foot's leg is forward; the opposite arm is forward.
    if (s.foot == 0) EXPECT_GT(right_hand - left_hand, 0.08f);
    else EXPECT_GT(left_hand - right_hand, 0.08f);
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

TEST(Walk, ClimbsStairsTreadByTreadWithoutSliding) {
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [8, 0.1, 8], "position": [0, -0.05, 2]},
      {"name": "s1", "shape": "box", "size": [1.4, 0.17, 0.34], "position": [0, 0.085, 2.17]},
      {"name": "s2", "shape": "box", "size": [1.4, 0.34, 0.34], "position": [0, 0.17, 2.51]},
      {"name": "s3", "shape": "box", "size": [1.4, 0.51, 0.34], "position": [0, 0.255, 2.85]},
      {"name": "landing", "shape": "box", "size": [1.4, 0.68, 2.0], "position": [0, 0.34, 4.02]}
    ]})", "stairs.json");
  const SceneGeometry g = build_scene_geometry(scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath path = planner.plan({vec3(0, 0, 0.0f), vec3(0, 0.68f, 4.4f), 0.3f});
  ASSERT_EQ(path.status, PathStatus::Found) << path.reason;
  const RootTrajectory body = follow_path(path.points, 0.0f, std::nullopt, {}, 1.0f / 60.0f, 0.5f, &env);
  const WalkRig rig = make_walk_rig(avatar());
  const GaitParams p;
  const WalkMotion walk = synthesize_walk(rig, body, &env, p);
  // Every plant lies flat on one level: heel, ball and toes on the same tread.
  for (const Footstep& s : walk.steps.steps) {
    const LegRig& leg = rig.legs[static_cast<std::size_t>(s.foot)];
    const quat r = glm::angleAxis(s.yaw, vec3(0, 1, 0));
    for (const vec3& local : {leg.heel, leg.ball, leg.toe}) {
      const vec3 q = s.position + r * local;
      const auto ground = ground_below(env, q + vec3(0, 0.3f, 0));
      ASSERT_TRUE(ground);
      EXPECT_NEAR(ground->height, s.position.y, 0.011f) << "a foot straddles a tread edge at z " << q.z;
    }
  }
  EXPECT_NEAR(walk.steps.steps.back().position.y, 0.68f, 0.01f);
  EXPECT_LT(worst_slide(rig, walk, p), 0.01f);
  // The swinging feet clear the treads' edges and the standing ones keep off the risers: the skin
  // goes no more than 1 cm into any step.
  const SkinDepth depth = deepest_skin_point(walk, env, g, -1, 2.0f / 60.0f);
  std::printf("stairs: %zu steps, deepest skin point %.1f mm into %s\n", walk.steps.steps.size(), depth.depth * 1000.0f, depth.where.c_str());
  EXPECT_LT(depth.depth, 0.01f) << depth.where;
}

TEST(Walk, WalksUpARampWithFeetAlongTheSlope) {
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [6, 0.1, 12], "position": [0, -0.05, 4]},
      {"name": "ramp", "shape": "box", "size": [1.6, 0.1, 3.2], "position": [0, 0.36, 3.0], "rotation": [-15, 0, 0]},
      {"name": "landing", "shape": "box", "size": [1.6, 0.78, 2.0], "position": [0, 0.39, 5.54]}
    ]})", "ramp.json");
  const SceneGeometry g = build_scene_geometry(scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath path = planner.plan({vec3(0, 0, -0.5f), vec3(0, 0.78f, 5.8f), 0.3f});
  ASSERT_EQ(path.status, PathStatus::Found) << path.reason;
  const RootTrajectory body = follow_path(path.points, 0.0f, std::nullopt, {}, 1.0f / 60.0f, 0.5f, &env);
  const WalkRig rig = make_walk_rig(avatar());
  const GaitParams p;
  const WalkMotion walk = synthesize_walk(rig, body, &env, p);
  int on_ramp = 0;
  for (const Footstep& s : walk.steps.steps)
    if (s.position.z > 1.8f && s.position.z < 4.0f) {
      ++on_ramp;
      EXPECT_NEAR(std::acos(s.normal.y), deg(15.0f), deg(1.0f)) << "a plant on the ramp is not along it";
    }
  EXPECT_GE(on_ramp, 3);
  EXPECT_LT(worst_slide(rig, walk, p), 0.01f);
  const SkinDepth depth = deepest_skin_point(walk, env, g, -1, 2.0f / 60.0f);
  std::printf("ramp: %d plants on the ramp, deepest skin point %.1f mm into %s\n", on_ramp, depth.depth * 1000.0f, depth.where.c_str());
  EXPECT_LT(depth.depth, 0.01f) << depth.where;
}

TEST(Walk, NoBodyPartEntersFurnitureAlongAPlannedWalk) {
  const Scene scene = parse_scene(R"({"objects": [
      {"name": "floor", "shape": "box", "size": [9, 0.1, 7], "position": [3.5, -0.05, 2.5]},
      {"name": "wall_n", "shape": "box", "size": [9, 2.5, 0.2], "position": [3.5, 1.25, -0.9]},
      {"name": "wall_s", "shape": "box", "size": [9, 2.5, 0.2], "position": [3.5, 1.25, 5.9]},
      {"name": "table", "parts": [
        {"shape": "box", "size": [1.6, 0.05, 0.9], "position": [0, 0.74, 0]},
        {"shape": "box", "size": [0.06, 0.72, 0.06], "position": [0.7, 0.36, 0.38]},
        {"shape": "box", "size": [0.06, 0.72, 0.06], "position": [-0.7, 0.36, 0.38]},
        {"shape": "box", "size": [0.06, 0.72, 0.06], "position": [0.7, 0.36, -0.38]},
        {"shape": "box", "size": [0.06, 0.72, 0.06], "position": [-0.7, 0.36, -0.38]}
      ], "position": [2.5, 0, 1.6], "rotation": 20},
      {"name": "cabinet", "shape": "box", "size": [0.8, 1.8, 0.5], "position": [4.6, 0.9, 3.6]},
      {"name": "plant", "shape": "cylinder", "radius": 0.25, "height": 1.1, "position": [1.2, 0.55, 4.0]},
      {"name": "sofa", "parts": [
        {"shape": "box", "size": [2, 0.45, 0.9], "position": [0, 0.225, 0]},
        {"shape": "box", "size": [2, 0.5, 0.2], "position": [0, 0.7, -0.35]}
      ], "position": [5.8, 0, 0.4], "rotation": -90}
    ]})", "furnished.json");
  const SceneGeometry g = build_scene_geometry(scene);
  const Environment env = build_environment(g);
  PathPlanner planner(env);
  const PlannedPath path = planner.plan({vec3(0.2f, 0, 0.2f), vec3(6.5f, 0, 4.6f), 0.3f});
  ASSERT_EQ(path.status, PathStatus::Found) << path.reason;
  const RootTrajectory body = follow_path(path.points, deg(180), deg(0), {}, 1.0f / 60.0f, 0.5f, &env);
  const WalkRig rig = make_walk_rig(avatar());
  const WalkMotion walk = synthesize_walk(rig, body, &env);
  // The skin itself, skinned every 4th frame, against the furniture's exact shapes (the floor
  // apart: the soles stand on it) and the floor separately.
  const SkinDepth depth = deepest_skin_point(walk, env, g, 0, 4.0f / 60.0f);
  const float deepest = depth.depth, below_floor = depth.below_floor;
  const std::string where = depth.where;
  std::printf("furnished room: path %.2f m, walk %.1f s, deepest skin point %.1f mm into furniture (%s), %.1f mm below the floor\n",
              path.length, walk.clip.duration, deepest * 1000.0f, where.c_str(), below_floor * 1000.0f);
  EXPECT_LT(deepest, 0.01f) << where;
  EXPECT_LT(below_floor, 0.01f);
}

}  // namespace
