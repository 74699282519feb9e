#include "gestura/world/walk.hpp"

#include <algorithm>

#include "gestura/ik/chain.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/skeleton/rotation_order.hpp"

namespace gestura {
namespace {

float smooth(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x * x * (3.0f - 2.0f * x);
}

// The plant frame of a footstep on the ground: origin, yaw, tilted to the ground's normal.
mat4 plant_matrix(const Footstep& s) {
  const quat yaw = glm::angleAxis(s.yaw, vec3(0, 1, 0));
  const quat tilt = glm::rotation(vec3(0, 1, 0), glm::normalize(s.normal));
  mat4 m = glm::mat4_cast(tilt * yaw);
  m[3] = vec4(s.position, 1.0f);
  return m;
}

// A rotation of the foot about a point of its plant frame: pitch > 0 lowers the toes.
mat4 pitch_about(const vec3& pivot, float pitch) {
  return glm::translate(mat4(1.0f), pivot) * glm::mat4_cast(glm::angleAxis(pitch, vec3(1, 0, 0))) *
         glm::translate(mat4(1.0f), -pivot);
}

struct FootPose {
  mat4 frame{1.0f};
  float toe = 0.0f;        // toe joint bend (negative: toes up relative to the foot)
  float heel_room = 0.0f;  // how far the toes are up (rolling down onto the heel may take that much)
};

float landing_angle(const Footstep& plant, const GaitParams& p) {
  const vec3 forward(std::sin(plant.yaw), 0.0f, std::cos(plant.yaw));
  const float uphill = std::max(0.0f, -std::asin(std::clamp(glm::dot(glm::normalize(plant.normal), forward), -1.0f, 1.0f)));
  return std::max(0.0f, p.heel_strike_angle - uphill);
}

// Stance on a plant: the heel rocker after heel strike, flat, the ball rocker from heel off.
FootPose stance_pose(const LegRig& leg, const Footstep& plant, float f, const GaitParams& p, bool came_from_swing) {
  FootPose out;
  const mat4 base = plant_matrix(plant);
  if (came_from_swing && f < p.foot_flat_at) {
    // Up a slope the foot lands flatter: its toes are already raised by the slope.
    const float alpha = landing_angle(plant, p) * (1.0f - smooth(f / p.foot_flat_at));
    out.frame = base * pitch_about(leg.heel, -alpha);
    out.heel_room = alpha;
  } else if (f > p.heel_off_at) {
    const float x = (f - p.heel_off_at) / (1.0f - p.heel_off_at);
    const float beta = p.toe_off_angle * x * x * (1.6f - 0.6f * x);  // slow heel rise, faster at push-off
    out.frame = base * pitch_about(leg.ball, beta);
    out.toe = -beta;
  } else {
    out.frame = base;
  }
  return out;
}

// Pitch of the swinging foot: from the toe-off angle through level to the heel-strike angle
// (`landing`, less up a slope).
float swing_pitch(float tau, const GaitParams& p, float landing) {
  if (tau < 0.45f) return p.toe_off_angle * (1.0f - smooth(tau / 0.45f));
  return -landing * smooth((tau - 0.45f) / 0.55f);
}


vec3 ankle_of(const LegRig& leg, const mat4& frame) { return vec3(frame * vec4(leg.ankle_point, 1.0f)); }

// Lowest points of the foot in a frame: heel and toe.
void foot_points(const LegRig& leg, const mat4& frame, vec3& heel, vec3& toe) {
  heel = vec3(frame * vec4(leg.heel, 1.0f));
  toe = vec3(frame * vec4(leg.toe, 1.0f));
}

// The swing's frame at fraction tau before lifting clear of the ground.
mat4 swing_base(const LegRig& leg, const FootPose& from, const FootPose& to, const Footstep& a, const Footstep& b, float tau,
                const GaitParams& p) {
  const vec3 pa = ankle_of(leg, from.frame), pb = ankle_of(leg, to.frame);
  const float e = smooth(tau);
  const vec3 ankle = glm::mix(pa, pb, e);
  const float yaw = a.yaw + e * angle_difference(b.yaw, a.yaw);
  const vec3 normal = glm::normalize(glm::mix(a.normal, b.normal, e));
  const quat r = glm::rotation(vec3(0, 1, 0), normal) * glm::angleAxis(yaw, vec3(0, 1, 0)) *
                 glm::angleAxis(swing_pitch(tau, p, landing_angle(b, p)), vec3(1, 0, 0));
  mat4 m = glm::mat4_cast(r);
  m[3] = vec4(ankle - r * leg.ankle_point, 1.0f);
  return m;
}

float ground_at(const Environment* env, const vec3& p, float fallback) {
  if (!env) return fallback;
  const auto g = ground_below(*env, vec3(p.x, p.y + 0.6f, p.z), 2.0f);
  return g ? g->height : fallback;
}

// How high the swinging foot is lifted at tau: at least a bump of the clearance, and enough to
// keep heel and toes above the ground below them (a tread's edge), as a smooth envelope.
float swing_lift(const LegRig& leg, const FootPose& from, const FootPose& to, const Footstep& a, const Footstep& b, float tau,
                 const GaitParams& p, const Environment* env) {
  // The clearance bump, and the knee's bend early in the swing: the ankle rises most just after
  // toe off (peaks near a third of the swing) while the toes, still pointing down, stay low.
  const float step = glm::length(vec2(b.position.x - a.position.x, b.position.z - a.position.z));
  const float knee = std::min(0.07f, 0.12f * step) * std::sin(kPi * tau) * (1.0f - tau) * 1.9f;
  const float bump = p.swing_clearance * std::pow(std::sin(kPi * tau), 0.7f) + knee;
  if (!env) return bump;
  constexpr int kSamples = 14;
  float lift = bump;
  for (int j = 1; j < kSamples; ++j) {
    const float tj = static_cast<float>(j) / static_cast<float>(kSamples);
    const mat4 m = swing_base(leg, from, to, a, b, tj, p);
    vec3 heel, toe;
    foot_points(leg, m, heel, toe);
    const vec3 ball = vec3(m * vec4(leg.ball, 1.0f)), toe_front = vec3(m * vec4(leg.toe + vec3(0, 0, 0.02f), 1.0f));
    const float ramp = std::min({1.0f, tj / 0.15f, (1.0f - tj) / 0.15f});
    float need = 0.0f;
    for (const vec3& q : {heel, (heel + ball) * 0.5f, ball, toe, toe_front})
      need = std::max(need, ground_at(env, q, std::min(a.position.y, b.position.y)) + p.swing_clearance * ramp - q.y);
    // Parabolic envelope: requirements spread smoothly to neighbouring times.
    const float d = (tau - tj) * 2.5f;
    lift = std::max(lift, need - d * d * 0.5f);
  }
  return std::max(0.0f, lift) * std::min(1.0f, std::min(tau, 1.0f - tau) / 0.04f);
}

FootPose foot_pose(const WalkRig& rig, const FootstepPlan& plan, const GaitParams& p, int foot, float t, const Environment* env) {
  const LegRig& leg = rig.legs[static_cast<std::size_t>(foot)];
  const FootState st = foot_state(plan, foot, t, p);
  if (!st.swinging) return stance_pose(leg, *st.from, st.stance_fraction, p, std::isfinite(st.from->land));
  const FootPose from = stance_pose(leg, *st.from, 1.0f, p, false);
  const FootPose to = stance_pose(leg, *st.to, 0.0f, p, true);
  FootPose out;
  out.frame = swing_base(leg, from, to, *st.from, *st.to, st.swing_fraction, p);
  out.frame[3] += vec4(0.0f, swing_lift(leg, from, to, *st.from, *st.to, st.swing_fraction, p, env), 0.0f, 0.0f);
  out.toe = from.toe * (1.0f - smooth(st.swing_fraction / 0.4f));
  out.heel_room = std::max(0.0f, -swing_pitch(st.swing_fraction, p, landing_angle(*st.to, p)));
  return out;
}

// The gait phase of the body: the last heel strike (either foot), the fraction of the step since,
// and its foot's side (+1 left).
struct BodyPhase {
  float fraction = 0.0f;
  float side = 0.0f;  // 0 while standing
};

BodyPhase body_phase(const FootstepPlan& plan, float t) {
  BodyPhase out;
  const std::vector<Footstep>& s = plan.steps;
  auto it = std::upper_bound(s.begin(), s.end(), t, [](float time, const Footstep& x) { return time < x.land; });
  if (it == s.begin() || it == s.end()) return out;
  const Footstep& last = *(it - 1);
  const Footstep& next = *it;
  if (next.foot == last.foot) return out;  // a pause between walks
  out.fraction = std::clamp((t - last.land) / std::max(1e-3f, next.land - last.land), 0.0f, 1.0f);
  out.side = last.foot == 0 ? 1.0f : -1.0f;
  return out;
}

void set_euler(const Skeleton& s, Pose& pose, int joint, const vec3& angles) {
  if (joint < 0) return;
  const auto j = static_cast<std::size_t>(joint);
  quat q = s.rest_rotations[j] * euler_to_quat(angles, s.dofs[j].order);
  clamp_joint_to_limits(s, joint, q);
  pose.rotations[j] = q;
}

// The flexion direction of a finger joint: toward the larger end of its widest free axis.
vec3 flexion_of(const Skeleton& s, int joint) {
  const JointDofs& d = s.dofs[static_cast<std::size_t>(joint)];
  int axis = -1;
  float widest = 0.0f;
  for (int a = 0; a < 3; ++a)
    if (d.free(a) && d.max_angle[a] - d.min_angle[a] > widest) widest = d.max_angle[a] - d.min_angle[a], axis = a;
  vec3 out(0.0f);
  if (axis >= 0) out[axis] = std::abs(d.min_angle[axis]) > std::abs(d.max_angle[axis]) ? -1.0f : 1.0f;
  return out;
}

struct Frame {
  float t = 0.0f;
  vec3 root{0.0f};      // horizontal position + floor height (y)
  float yaw = 0.0f;
  float amount = 0.0f;  // how much of the gait's body motion shows (0 standing … 1 at reference speed)
  BodyPhase phase;
  FootPose feet[2];
  float floor = 0.0f;   // the ground reference under the pelvis
};

}  // namespace

mat4 foot_frame(const WalkRig& rig, const FootstepPlan& plan, const GaitParams& params, int foot, float t, const Environment* env,
                float* toe_bend) {
  const FootPose pose = foot_pose(rig, plan, params, foot, t, env);
  if (toe_bend) *toe_bend = pose.toe;
  return pose.frame;
}

WalkMotion synthesize_walk(const WalkRig& rig, const RootTrajectory& body, const Environment* env, const GaitParams& p, float fps) {
  WalkMotion out;
  out.fps = fps;
  out.steps = plan_footsteps(body, rig, p, env);
  const Skeleton& s = rig.avatar->skeleton;
  const float duration = body.duration();
  const int frames = std::max(1, static_cast<int>(std::ceil(duration * fps))) + 1;

  // Pass 1: where the body and feet are, frame by frame.
  std::vector<Frame> f(static_cast<std::size_t>(frames));
  for (int i = 0; i < frames; ++i) {
    Frame& x = f[static_cast<std::size_t>(i)];
    x.t = std::min(duration, static_cast<float>(i) / fps);
    x.root = body.position_at(x.t);
    x.yaw = body.yaw_at(x.t);
    x.phase = body_phase(out.steps, x.t);
    for (int k = 0; k < 2; ++k) x.feet[k] = foot_pose(rig, out.steps, p, k, x.t, env);
  }
  // The gait's amount eases in and out with the steps (not with the trajectory's raw speed, which
  // starts before the first heel strike).
  for (int i = 0; i < frames; ++i) {
    Frame& x = f[static_cast<std::size_t>(i)];
    const float v = std::clamp(body.speed_at(x.t) / p.reference_speed, 0.0f, 1.2f);
    x.amount = x.phase.side != 0.0f ? std::max(v, 0.35f) : 0.0f;
  }
  {
    std::vector<float> a(static_cast<std::size_t>(frames));
    const int w = static_cast<int>(0.25f * fps);
    for (int i = 0; i < frames; ++i) {
      float sum = 0.0f;
      int n = 0;
      for (int k = std::max(0, i - w); k <= std::min(frames - 1, i + w); ++k) sum += f[static_cast<std::size_t>(k)].amount, ++n;
      a[static_cast<std::size_t>(i)] = sum / static_cast<float>(n);
    }
    for (int i = 0; i < frames; ++i) f[static_cast<std::size_t>(i)].amount = a[static_cast<std::size_t>(i)];
  }
  // The floor under the pelvis: the feet's plants, averaged and smoothed over about half a second.
  {
    std::vector<float> raw(static_cast<std::size_t>(frames));
    for (int i = 0; i < frames; ++i) {
      const Frame& x = f[static_cast<std::size_t>(i)];
      float h = 0.0f;
      for (int k = 0; k < 2; ++k) {
        const FootState st = foot_state(out.steps, k, x.t, p);
        h += st.swinging ? glm::mix(st.from->position.y, st.to->position.y, smooth(st.swing_fraction)) : st.from->position.y;
      }
      raw[static_cast<std::size_t>(i)] = h * 0.5f;
    }
    const int w = static_cast<int>(0.25f * fps);
    for (int i = 0; i < frames; ++i) {
      float sum = 0.0f;
      int n = 0;
      for (int k = std::max(0, i - w); k <= std::min(frames - 1, i + w); ++k) sum += raw[static_cast<std::size_t>(k)], ++n;
      f[static_cast<std::size_t>(i)].floor = sum / static_cast<float>(n);
    }
  }

  // Pass 2: the pelvis height each frame may have (legs within reach of both feet), and what the
  // gait asks for; the lower of the asked height and a smooth envelope under the limits.
  const vec3 rest_root = s.rest_translations[static_cast<std::size_t>(rig.root)];
  std::vector<float> desired(static_cast<std::size_t>(frames)), limit(static_cast<std::size_t>(frames));
  std::vector<mat4> model(s.size());
  Pose pose = rig.rest;
  auto upper_pose = [&](const Frame& x, float height) {
    // Root and pelvis for this frame (the spine and arms do not move the hips).
    const float a = x.amount, side = x.phase.side, fr = x.phase.fraction;
    const vec3 left = heading(x.yaw + kPi * 0.5f);
    const float sway = side * p.sway * a * std::sin(kPi * fr);
    pose.translations[static_cast<std::size_t>(rig.root)] =
        vec3(x.root.x, height, x.root.z) + left * sway + glm::angleAxis(x.yaw, vec3(0, 1, 0)) * vec3(rest_root.x, 0.0f, rest_root.z);
    pose.rotations[static_cast<std::size_t>(rig.root)] = glm::angleAxis(x.yaw, vec3(0, 1, 0)) * s.rest_rotations[static_cast<std::size_t>(rig.root)];
    const float turn = -side * p.pelvis_rotation * a * std::cos(kPi * fr);
    const float list = side * p.pelvis_list * a * std::sin(kPi * fr);
    set_euler(s, pose, rig.pelvis, vec3(deg(2.0f) * a, turn, list));
  };
  const float reach = 0.993f * (rig.legs[0].thigh + rig.legs[0].shin);
  for (int i = 0; i < frames; ++i) {
    const Frame& x = f[static_cast<std::size_t>(i)];
    const float a = x.amount;
    desired[static_cast<std::size_t>(i)] =
        x.floor + rig.root_height - p.lowering * a - p.bob * a * 0.5f * std::cos(2.0f * kPi * x.phase.fraction);
    upper_pose(x, 0.0f);
    local_to_model(s, pose, model);
    float lim = 1e30f;
    for (int k = 0; k < 2; ++k) {
      const vec3 hip = vec3(model[static_cast<std::size_t>(rig.legs[k].hip)][3]);
      const vec3 ankle = ankle_of(rig.legs[k], x.feet[k].frame);
      const float horizontal = glm::length(vec2(ankle.x - hip.x, ankle.z - hip.z));
      const float rise = horizontal < reach ? std::sqrt(reach * reach - horizontal * horizontal) : 0.0f;
      lim = std::min(lim, ankle.y + rise - hip.y);
    }
    limit[static_cast<std::size_t>(i)] = lim;
  }
  out.pelvis_heights.resize(static_cast<std::size_t>(frames));
  {
    const int w = static_cast<int>(0.6f * fps);
    const float k = 4.0f;  // m/s²: how fast the envelope may bend
    for (int i = 0; i < frames; ++i) {
      float env_min = 1e30f;
      for (int j = std::max(0, i - w); j <= std::min(frames - 1, i + w); ++j) {
        const float d = static_cast<float>(j - i) / fps;
        env_min = std::min(env_min, limit[static_cast<std::size_t>(j)] + k * d * d);
      }
      out.pelvis_heights[static_cast<std::size_t>(i)] = std::min(desired[static_cast<std::size_t>(i)], env_min);
    }
  }

  // Pass 3: the pose of every frame, written as keys.
  out.clip.name = "walk";
  out.clip.resize_joints(s.size());
  out.clip.duration = static_cast<float>(frames - 1) / fps;
  std::vector<int> animated{rig.root, rig.pelvis};
  for (int j : rig.spine)
    if (j >= 0) animated.push_back(j);
  for (const LegRig& leg : rig.legs)
    for (int j : {leg.hip, leg.knee, leg.ankle, leg.subtalar, leg.midtarsal, leg.metatarsal})
      if (j >= 0) animated.push_back(j);
  for (int k = 0; k < 2; ++k) {
    animated.push_back(rig.shoulders[k]);
    animated.push_back(rig.elbows[k]);
    for (int j : rig.fingers[k]) animated.push_back(j);
  }
  for (int j : animated) out.clip.rotations[static_cast<std::size_t>(j)].interpolation = Interpolation::Linear;
  out.clip.translations[static_cast<std::size_t>(rig.root)].interpolation = Interpolation::Linear;

  std::vector<vec3> finger_flexion[2];
  for (int k = 0; k < 2; ++k)
    for (int j : rig.fingers[k]) finger_flexion[k].push_back(flexion_of(s, j));

  for (int i = 0; i < frames; ++i) {
    const Frame& x = f[static_cast<std::size_t>(i)];
    pose = rig.rest;
    upper_pose(x, out.pelvis_heights[static_cast<std::size_t>(i)]);
    const float a = x.amount, side = x.phase.side, fr = x.phase.fraction;
    // The thorax turns against the pelvis; lumbar joints take little, thoracic ones most.
    const float pelvis_turn = -side * p.pelvis_rotation * a * std::cos(kPi * fr);
    const float shares[3] = {0.2f, 0.4f, 0.4f};
    for (int k = 0; k < 3; ++k) set_euler(s, pose, rig.spine[static_cast<std::size_t>(k)], vec3(0.0f, -p.thorax_counter * pelvis_turn * shares[k] * 2.0f, 0.0f));
    // Arms against the legs: the left arm forward when the right leg is.
    const float left_leg_forward = side * std::cos(kPi * fr);
    for (int k = 0; k < 2; ++k) {
      const float mirror = k == 0 ? 1.0f : -1.0f;
      const float forward = (k == 0 ? -left_leg_forward : left_leg_forward) * a;
      set_euler(s, pose, rig.shoulders[k], vec3(-p.arm_swing * forward - deg(3.0f), 0.0f, -mirror * deg(4.0f)));
      const float bend = p.elbow_bend * (0.55f + 0.45f * std::max(0.0f, forward)) * (0.6f + 0.4f * a);
      set_euler(s, pose, rig.elbows[k], vec3(-bend, 0.0f, 0.0f));
      for (std::size_t n = 0; n < rig.fingers[k].size(); ++n)
        set_euler(s, pose, rig.fingers[k][n], finger_flexion[k][n] * p.finger_curl);
    }
    // Legs: two-bone IK to the ankle, the knee toward the foot's direction; then the foot's turn.
    // A foot whose shin leans further than the ankle can bend rolls onto its ball instead (what
    // lifts the heel in walking): the pitch about the ball grows by what the ankle lacks. The same
    // rule holds in the swing, so the foot does not jump when it leaves the ground.
    local_to_model(s, pose, model);
    for (int k = 0; k < 2; ++k) {
      const LegRig& leg = rig.legs[static_cast<std::size_t>(k)];
      mat4 frame = x.feet[k].frame;
      float toe = x.feet[k].toe;
      // Rolling further goes over the heel while the foot comes down onto it (late swing, heel
      // strike) until it is flat, over the ball beyond that — the toes never go under the ground.
      const FootState state = foot_state(out.steps, k, x.t, p);
      const bool on_heel = state.swinging ? state.swing_fraction > 0.5f
                                          : state.phase == GaitPhase::HeelStrike && std::isfinite(state.stance_start);
      float heel_room = on_heel ? x.feet[k].heel_room : 0.0f;  // down onto the heel no further than flat
      const float lowest = s.dofs[static_cast<std::size_t>(leg.ankle)].min_angle.x + deg(1.0f);
      vec3 e(0.0f);
      for (int pass = 0; pass < 10; ++pass) {
        const vec3 ankle = ankle_of(leg, frame);
        const vec3 forward = glm::normalize(vec3(frame[2]));
        const vec3 hip = vec3(model[static_cast<std::size_t>(leg.hip)][3]);
        const vec3 pole = (hip + ankle) * 0.5f + forward * 0.8f;
        solve_limb(s, pose, leg.hip, leg.knee, leg.ankle, vec3(1, 0, 0), ankle, pole);
        // The foot's world rotation from the shin's: ankle (x), subtalar (z), midtarsal (y).
        const mat4 knee_model = parent_model_matrix(s, pose, leg.ankle);
        const quat knee_rot = glm::quat_cast(mat3(knee_model));
        const quat need = glm::inverse(knee_rot) * glm::quat_cast(mat3(frame));
        e = quat_to_euler(glm::normalize(need), RotationOrder::XZY);
        if (e.x >= lowest) break;
        const float more = lowest - e.x + deg(0.5f);
        const float about_heel = std::min(more, heel_room);
        heel_room -= about_heel;
        if (about_heel > 0.0f) frame = frame * pitch_about(leg.heel, about_heel);
        if (more > about_heel) frame = frame * pitch_about(leg.ball, more - about_heel), toe -= more - about_heel;
      }
      set_euler(s, pose, leg.ankle, vec3(e.x, 0.0f, 0.0f));
      set_euler(s, pose, leg.subtalar, vec3(0.0f, 0.0f, e.z));
      set_euler(s, pose, leg.midtarsal, vec3(0.0f, e.y, 0.0f));
      set_euler(s, pose, leg.metatarsal, vec3(toe, 0.0f, 0.0f));
    }
    const float t = static_cast<float>(i) / fps;
    for (int j : animated) out.clip.rotations[static_cast<std::size_t>(j)].add(t, pose.rotations[static_cast<std::size_t>(j)]);
    out.clip.translations[static_cast<std::size_t>(rig.root)].add(t, pose.translations[static_cast<std::size_t>(rig.root)]);
  }
  for (int j : animated) make_continuous(out.clip.rotations[static_cast<std::size_t>(j)]);
  return out;
}

}  // namespace gestura
