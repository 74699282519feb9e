#include "gestura/world/gait.hpp"

#include <algorithm>
#include <limits>

namespace gestura {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The plant frame origin of a foot when the body stands at `root` facing `yaw`.
vec3 standing_plant(const WalkRig& rig, int foot, const vec3& root, float yaw) {
  const LegRig& leg = rig.legs[static_cast<std::size_t>(foot)];
  const vec3 local(leg.plant_origin.x, 0.0f, leg.plant_origin.z);
  return root + glm::angleAxis(yaw, vec3(0, 1, 0)) * local;
}

// Puts a plant on the ground: its height from the surface below and, where heel and toes would
// stand on different levels (a tread's edge), slid along the foot onto one level.
void settle(Footstep& s, const WalkRig& rig, const Environment* env, float floor_hint, float other_foot = NAN,
            float max_rise = 1e30f) {
  if (!env) {
    s.position.y = floor_hint;
    return;
  }
  const LegRig& leg = rig.legs[static_cast<std::size_t>(s.foot)];
  const quat r = glm::angleAxis(s.yaw, vec3(0, 1, 0));
  auto ground = [&](const vec3& p) {
    const auto g = ground_below(*env, vec3(p.x, floor_hint + 0.6f, p.z), 1.6f);
    return g ? std::optional<GroundHit>(*g) : std::nullopt;
  };
  // Heel, ball and toes on one level, and nothing rising just beyond the toes or behind the heel
  // (a riser the foot would stand against).
  float heel = 0, ball = 0, toe = 0, ahead = 0, behind = 0;
  auto heights = [&](const vec3& origin, float& h_heel, float& h_ball, float& h_toe) {
    const auto h = ground(origin + r * leg.heel), b = ground(origin + r * leg.ball), t = ground(origin + r * leg.toe);
    const auto a = ground(origin + r * (leg.toe + vec3(0, 0, 0.04f))), c = ground(origin + r * (leg.heel - vec3(0, 0, 0.03f)));
    h_heel = h ? h->height : floor_hint, h_ball = b ? b->height : floor_hint, h_toe = t ? t->height : floor_hint;
    ahead = a ? a->height : floor_hint, behind = c ? c->height : floor_hint;
  };
  heights(s.position, heel, ball, toe);
  // …and no higher or lower than a step from where the other foot stands (one tread at a time).
  auto level = [&]() {
    const float top = std::max({heel, ball, toe});
    const bool rise_ok = std::isnan(other_foot) || std::abs(top - other_foot) <= max_rise;
    return top - std::min({heel, ball, toe}) < 0.01f && ahead < top + 0.01f && behind < top + 0.01f && rise_ok;
  };
  if (!level()) {
    const vec3 forward = r * vec3(0, 0, 1);
    for (int k = 1; k <= 24; ++k) {
      bool found = false;
      for (float sign : {1.0f, -1.0f}) {
        const vec3 moved = s.position + forward * (sign * 0.01f * static_cast<float>(k));
        heights(moved, heel, ball, toe);
        if (level()) {
          s.position = moved;
          found = true;
          break;
        }
      }
      if (found) break;
    }
    if (!level()) heights(s.position, heel, ball, toe);
  }
  s.position.y = std::max({heel, ball, toe});
  if (const auto g = ground(s.position)) {
    vec3 n = g->normal;
    // Stand on slopes up to 20° with the foot along them; steeper ground keeps the foot level.
    s.normal = n.y >= std::cos(deg(20.0f)) ? n : vec3(0, 1, 0);
  }
}

}  // namespace

const char* gait_phase_name(GaitPhase phase) {
  switch (phase) {
    case GaitPhase::HeelStrike: return "heel strike";
    case GaitPhase::FootFlat: return "foot flat";
    case GaitPhase::MidStance: return "mid-stance";
    case GaitPhase::HeelOff: return "heel off";
    case GaitPhase::ToeOff: return "toe off";
    case GaitPhase::EarlySwing: return "early swing";
    case GaitPhase::MidSwing: return "mid-swing";
    case GaitPhase::LateSwing: return "late swing";
  }
  return "?";
}

float step_length_for(const GaitParams& p, float body_height, float speed) {
  const float reference = p.step_length * body_height;
  return reference * std::clamp(std::sqrt(std::max(speed, 0.0f) / p.reference_speed), 0.35f, 1.25f);
}

FootstepPlan plan_footsteps(const RootTrajectory& body, const WalkRig& rig, const GaitParams& p, const Environment* env) {
  FootstepPlan plan;
  const float env_climb = env ? env->max_climb * 0.75f : 1e30f;  // a step climbs about one riser
  const float end = body.duration();
  const float dt = body.dt;
  auto cadence = [&](float t) {
    const float v = body.speed_at(t), w = std::abs(body.turn_rate_at(t));
    const float c = std::max(v / step_length_for(p, rig.height, v), w / p.turn_per_step);
    return std::clamp(c, p.min_cadence, p.max_cadence);
  };
  auto moving = [&](float t) { return body.speed_at(t) > 0.03f || std::abs(body.turn_rate_at(t)) > 0.12f; };
  Footstep current[2];
  for (int f = 0; f < 2; ++f) {
    Footstep& s = current[f];
    s.foot = f;
    s.land = -kInf;
    s.lift = -kInf;
    s.yaw = body.yaw_at(0.0f) + rig.legs[static_cast<std::size_t>(f)].side * p.toe_out;
    s.position = standing_plant(rig, f, body.position_at(0.0f), body.yaw_at(0.0f));
    settle(s, rig, env, body.position_at(0.0f).y);
    plan.initial[f] = s;
  }
  auto ideal = [&](int f, float t) {
    Footstep s;
    s.foot = f;
    s.yaw = body.yaw_at(t) + rig.legs[static_cast<std::size_t>(f)].side * p.toe_out;
    s.position = standing_plant(rig, f, body.position_at(t), body.yaw_at(t));
    return s;
  };
  auto push = [&](Footstep s, float hint) {
    settle(s, rig, env, hint, current[1 - s.foot].position.y, 1.15f * env_climb);
    plan.steps.push_back(s);
    current[s.foot] = s;
  };

  float busy_until = 0.0f;
  float t = 0.0f;
  while (t < end) {
    // The next stretch of movement, short pauses bridged.
    while (t < end && !moving(t)) t += dt;
    if (t >= end) break;
    float a = std::max(t, busy_until), b = a;
    for (float quiet = 0.0f; b < end && quiet < 0.4f; b += dt) quiet = moving(b) ? 0.0f : quiet + dt;
    while (b > a && !moving(b)) b -= dt;
    b = std::min(b + dt, end);

    // The first foot: into the turn when turning on the spot, else the one with further to go.
    const float look = std::min(a + 0.5f, end);
    const float turn = angle_difference(body.yaw_at(look), body.yaw_at(a));
    int foot = 1;
    if (body.speed_at(a + 0.2f) < 0.3f && std::abs(turn) > 0.2f) {
      foot = turn > 0.0f ? 0 : 1;
    } else {
      const float need0 = glm::length(ideal(0, look).position - current[0].position);
      const float need1 = glm::length(ideal(1, look).position - current[1].position);
      foot = need0 > need1 + 0.01f ? 0 : 1;
    }
    float last = a;
    bool first = true;
    while (true) {
      // Run the step clock for one step.
      float h = last, u = 0.0f;
      while (u < 1.0f && h < end + 5.0f) u += cadence(h) * dt, h += dt;
      if (h >= b) break;
      // Mid-stance: the middle of the foot's stance, which lasts a step and its double support.
      Footstep s = ideal(foot, std::min(h + 0.5f * (1.0f + p.double_support) / cadence(h), b));
      // Turning while walking: the foot points ahead into the turn, but not further than the
      // hips can twist from the way the body faces as it lands.
      const float facing = body.yaw_at(h) + rig.legs[static_cast<std::size_t>(foot)].side * p.toe_out;
      s.yaw = facing + std::clamp(angle_difference(s.yaw, facing), -p.max_foot_turn, p.max_foot_turn);
      s.lift = first ? a : last + p.double_support * (h - last);
      s.land = h;
      push(s, body.position_at(std::min(h, b)).y);
      last = h;
      first = false;
      foot = 1 - foot;
    }
    // Stopping: feet side by side under the pelvis where it stopped (at most two closing steps).
    for (int k = 0; k < 2; ++k) {
      Footstep target = ideal(foot, b);
      settle(target, rig, env, body.position_at(b).y);
      const bool there = glm::length(target.position - current[foot].position) < 0.03f &&
                         std::abs(angle_difference(target.yaw, current[foot].yaw)) < deg(6.0f);
      if (!there) {
        const float period = 1.0f / std::max(p.min_cadence, cadence(std::max(b - dt, 0.0f)));
        const float h = std::max(last + period, first ? a + period : b);
        target.lift = first ? a : last + p.double_support * (h - last);
        target.land = h;
        plan.steps.push_back(target);
        current[foot] = target;
        last = h;
        first = false;
      }
      foot = 1 - foot;
    }
    busy_until = last + 0.05f;
    t = std::max(b, busy_until);
  }
  for (std::size_t i = 0; i < plan.steps.size(); ++i) plan.of_foot[plan.steps[i].foot].push_back(i);
  return plan;
}

FootState foot_state(const FootstepPlan& plan, int foot, float t, const GaitParams& p) {
  FootState st;
  const std::vector<std::size_t>& mine = plan.of_foot[foot];
  const Footstep* on = &plan.initial[foot];
  const Footstep* next = nullptr;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const Footstep& s = plan.steps[mine[k]];
    if (s.land <= t) on = &s;
    else {
      next = &s;
      break;
    }
  }
  if (next && t >= next->lift) {
    st.swinging = true;
    st.from = on;
    st.to = next;
    st.swing_fraction = std::clamp((t - next->lift) / std::max(1e-3f, next->land - next->lift), 0.0f, 1.0f);
    st.phase = st.swing_fraction < 1.0f / 3.0f ? GaitPhase::EarlySwing : st.swing_fraction < 2.0f / 3.0f ? GaitPhase::MidSwing : GaitPhase::LateSwing;
    return st;
  }
  st.from = on;
  st.stance_start = on->land;
  st.stance_end = next ? next->lift : kInf;
  // A nominal stance for the ends that are open (standing before the first step, after the last).
  const float nominal = next && std::isfinite(on->land) ? next->lift - on->land : 0.7f;
  float f = 0.5f;
  if (std::isfinite(st.stance_start) && std::isfinite(st.stance_end)) f = (t - st.stance_start) / std::max(1e-3f, st.stance_end - st.stance_start);
  else if (std::isfinite(st.stance_start)) f = std::min(0.5f, (t - st.stance_start) / nominal);
  else if (std::isfinite(st.stance_end)) f = 1.0f - std::min(0.5f, (st.stance_end - t) / nominal);
  st.stance_fraction = std::clamp(f, 0.0f, 1.0f);
  st.phase = f < p.foot_flat_at ? GaitPhase::HeelStrike : f < p.mid_stance_at ? GaitPhase::FootFlat
           : f < p.heel_off_at  ? GaitPhase::MidStance : f < p.toe_off_at ? GaitPhase::HeelOff : GaitPhase::ToeOff;
  return st;
}

}  // namespace gestura
