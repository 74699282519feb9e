#include "gestura/world/character_motion.hpp"

#include <algorithm>
#include <array>

#include "gestura/face/eye_aim.hpp"
#include "gestura/ik/chain.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/world/grasp.hpp"
#include "gestura/world/tracks.hpp"

namespace gestura {
namespace {

float minimum_jerk(float tau) {
  tau = std::clamp(tau, 0.0f, 1.0f);
  return tau * tau * tau * (10.0f + tau * (-15.0f + 6.0f * tau));
}

float smooth(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x * x * (3.0f - 2.0f * x);
}

quat slerp_short(const quat& a, const quat& b, float t) {
  return glm::dot(a, b) < 0.0f ? glm::slerp(a, -b, t) : glm::slerp(a, b, t);
}

// The world primitives of one object placed by the object transforms of a moment.
Environment object_primitives(const SceneGeometry& g, std::span<const mat4> transforms, int object) {
  Environment env;
  for (const PlacedPrimitive& p : g.primitives) {
    if (p.object != object) continue;
    WorldPrimitive w;
    w.object = p.object;
    w.shape = p.shape;
    w.to_world = transforms[static_cast<std::size_t>(object)] * p.to_object;
    w.to_local = glm::inverse(w.to_world);
    w.scale_min = std::min({glm::length(vec3(w.to_world[0])), glm::length(vec3(w.to_world[1])), glm::length(vec3(w.to_world[2]))});
    env.primitives.push_back(w);
  }
  return env;
}

// How near the shoulder comes to what the hand reaches for before the arm takes over: the arm's
// reach, a little under the limit the director walks closer for (a door handle within it needs no bow).
constexpr float kLeanReach = 0.56f;
// The pre-grasp: the open hand this far back along the palm's normal and up from the grasp, so it
// comes to the object across what the object stands on, not up through its edge.
constexpr float kReadyBack = 0.1f, kReadyUp = 0.1f;
// The share of the approach spent reaching the pre-grasp.
constexpr float kReadyShare = 0.6f;
const float kMaxLean = deg(50.0f);

// Bends the lower spine toward `target` (about a level axis, so the upper body tips over it, as one
// bends over a table) just far enough that the shoulder comes within kLeanReach of it, at most
// kMaxLean, spread evenly over the joints of `spine`. The legs stay where the walk planted them.
// Returns the bend (radians; 0 when the shoulder is near enough already).
float lean_toward(const Skeleton& s, std::span<const int> spine, int shoulder, const vec3& target, Pose& pose) {
  if (spine.empty()) return 0.0f;
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const auto shoulder_at = [&] { return vec3(model[static_cast<std::size_t>(shoulder)][3]); };
  vec3 toward = target - shoulder_at();
  toward.y = 0.0f;
  if (glm::length(shoulder_at() - target) <= kLeanReach || glm::length(toward) < 1e-3f) return 0.0f;
  const vec3 axis = glm::normalize(glm::cross(vec3(0, 1, 0), glm::normalize(toward)));
  std::vector<quat> upright;
  for (int j : spine) upright.push_back(pose.rotations[static_cast<std::size_t>(j)]);
  const auto bend = [&](float angle) {
    for (std::size_t k = 0; k < spine.size(); ++k) {
      const auto j = static_cast<std::size_t>(spine[k]);
      local_to_model(s, pose, model);
      const int parent = s.parents[j];
      const quat parent_rotation = parent < 0 ? quat(1, 0, 0, 0) : glm::normalize(glm::quat_cast(mat3(model[static_cast<std::size_t>(parent)])));
      const quat turn = glm::angleAxis(angle / static_cast<float>(spine.size()), axis);
      pose.rotations[j] = glm::normalize(glm::inverse(parent_rotation) * turn * parent_rotation * upright[k]);
    }
    local_to_model(s, pose, model);
  };
  // The least bend that brings the shoulder near enough, found by bisection (the distance falls as
  // the body tips toward the target, until the shoulder passes over it).
  float lo = 0.0f, hi = kMaxLean;
  bend(hi);
  if (glm::length(shoulder_at() - target) > kLeanReach) return hi;
  for (int i = 0; i < 12; ++i) {
    const float mid = 0.5f * (lo + hi);
    bend(mid);
    (glm::length(shoulder_at() - target) > kLeanReach ? lo : hi) = mid;
  }
  bend(hi);
  return hi;
}

// Crouching for what lies too low to reach by bending over (alias-movement-through-environments.txt
// §6.2 reaches the floor with the legs too): the hips go down and a little back, the knees and hips
// bend, and the feet stay planted where they stood.
struct Crouch {
  float drop = 0.0f;  // metres the root goes down
  vec3 back{0.0f};    // level direction the hips move while going down (away from the object)
};
// The hips go back this share of the drop (balance over the feet, as in a squat).
constexpr float kHipsBack = 0.1f;
// The deepest crouch, as a share of the leg's length (hip to ankle).
constexpr float kMaxCrouch = 0.62f;

// Lowers the root by weight · crouch.drop and solves each leg (two-bone IK, the knee toward the toes)
// so its ankle stays where it is in `pose` and its foot keeps its turn in the world.
void apply_crouch(const Skeleton& s, const WalkRig& w, const Crouch& crouch, float weight, Pose& pose) {
  if (crouch.drop <= 0.0f || weight <= 0.0f || w.root < 0) return;
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  vec3 ankle[2];
  quat foot[2];
  for (int k = 0; k < 2; ++k) {
    const auto a = static_cast<std::size_t>(w.legs[static_cast<std::size_t>(k)].ankle);
    ankle[k] = vec3(model[a][3]);
    foot[k] = glm::normalize(glm::quat_cast(mat3(model[a])));
  }
  pose.translations[static_cast<std::size_t>(w.root)] += weight * crouch.drop * (vec3(0.0f, -1.0f, 0.0f) + kHipsBack * crouch.back);
  local_to_model(s, pose, model);
  for (int k = 0; k < 2; ++k) {
    const LegRig& leg = w.legs[static_cast<std::size_t>(k)];
    vec3 toes = foot[k] * vec3(0.0f, 0.0f, 1.0f);
    toes.y = 0.0f;
    toes = glm::length(toes) > 1e-4f ? glm::normalize(toes) : vec3(0, 0, 1);
    const vec3 hip = vec3(model[static_cast<std::size_t>(leg.hip)][3]);
    solve_limb(s, pose, leg.hip, leg.knee, leg.ankle, vec3(1, 0, 0), ankle[k], (hip + ankle[k]) * 0.5f + toes * 0.8f);
    const quat parent = glm::normalize(glm::quat_cast(mat3(parent_model_matrix(s, pose, leg.ankle))));
    pose.rotations[static_cast<std::size_t>(leg.ankle)] = glm::normalize(glm::inverse(parent) * foot[k]);
  }
}

// The least crouch from which bending over (lean_toward) brings the shoulder within kLeanReach of
// `target`; none when bending over alone does.
Crouch plan_crouch(const Skeleton& s, const WalkRig& w, std::span<const int> spine, int shoulder, const vec3& target, const Pose& pose) {
  const auto reaches = [&](const Crouch& c) {
    Pose p = pose;
    apply_crouch(s, w, c, 1.0f, p);
    lean_toward(s, spine, shoulder, target, p);
    std::vector<mat4> model(s.size());
    local_to_model(s, p, model);
    return glm::length(vec3(model[static_cast<std::size_t>(shoulder)][3]) - target) <= kLeanReach + 1e-3f;
  };
  if (w.root < 0 || reaches(Crouch{})) return {};
  Crouch c;
  vec3 back = vec3(pose.translations[static_cast<std::size_t>(w.root)]) - target;
  back.y = 0.0f;
  c.back = glm::length(back) > 1e-4f ? glm::normalize(back) : vec3(0.0f);
  const float leg = w.legs[0].thigh + w.legs[0].shin;
  float lo = 0.0f, hi = kMaxCrouch * leg;
  c.drop = hi;
  if (reaches(c)) {
    for (int i = 0; i < 14; ++i) {
      c.drop = 0.5f * (lo + hi);
      (reaches(c) ? hi : lo) = c.drop;
    }
    c.drop = hi;
  }  // else as low as the legs go: the arm gets as near as it can
  return c;
}

// One reach worked out at its moment of contact: the grasp, the arm and fingers holding it, and the
// grasp's frame in the object's own frame (to follow the object when it moves).
struct PreparedReach {
  ReachRecord record;
  bool ok = false;
  GraspPlan grasp;
  Pose holding;               // the pose at contact with the arm and fingers grasping
  Pose ready;                 // the pre-grasp: the open hand backed off from the grasp and a little above it
  std::array<vec3, 3> lift{}; // the palm's way to the pre-grasp: from where it is, up to its height, across
  Pose approach;              // the previous frame's arm on that way (warm start)
  bool approaching = false;
  vec3 let_go_palm{0.0f}, let_go_normal{0.0f};  // the grasp as the hand last held it
  Pose leaving;               // the previous frame's arm on the way back
  bool leaving_started = false;
  std::vector<int> joints;    // arm and finger joints the reach drives
  std::vector<int> arm;       // the IK chain
  std::vector<int> spine;     // lumbar and lower thoracic joints bent toward a low or far object
  Crouch crouch;              // the legs bent for an object near the floor
  float crouch_from = 0.0f;   // when the legs start bending: once the walk's last step is down
  vec3 palm_local{0.0f}, normal_local{0.0f}, finger_local{0.0f};
  Pose last;                  // the previous frame's held arm (warm start while following)
};

}  // namespace

void apply_look_at(const Skeleton& s, Pose& pose, const vec3& point, float weight, std::span<const mat4> bind, std::vector<mat4>& model) {
  if (weight <= 1e-3f) return;
  const int vc4 = s.find("vc4"), skull = s.find("skullbase"), le = s.find("l_eyeball_joint"), re = s.find("r_eyeball_joint");
  if (skull < 0) return;
  local_to_model(s, pose, model);
  const mat4& head = model[static_cast<std::size_t>(skull)];
  const vec3 eyes = le >= 0 && re >= 0 ? 0.5f * (vec3(model[static_cast<std::size_t>(le)][3]) + vec3(model[static_cast<std::size_t>(re)][3]))
                                       : vec3(head * vec4(0.0f, 0.07f, 0.08f, 1.0f));
  const vec3 d = glm::inverse(mat3(head) * glm::transpose(mat3(bind[static_cast<std::size_t>(skull)]))) * (point - eyes);
  if (glm::length(d) < 1e-4f) return;
  const vec2 gaze = face::gaze_angles(d);
  // The head takes what the eyes cannot, and a third of the rest (people turn to face whom they
  // watch), added to whatever the head already does.
  const vec2 beyond = face::beyond_eyes(gaze);
  const vec2 turn = weight * (beyond + 0.35f * (gaze - beyond));
  const std::pair<int, float> shares[2] = {{vc4, 0.4f}, {skull, 0.6f}};
  for (const auto& [joint, share] : shares) {
    if (joint < 0) continue;
    const auto j = static_cast<std::size_t>(joint);
    quat q = pose.rotations[j] * euler_to_quat(vec3(turn.x * share, turn.y * share, 0.0f), s.dofs[j].order);
    clamp_joint_to_limits(s, joint, q);
    pose.rotations[j] = q;
  }
  local_to_model(s, pose, model);
  for (const int eye : {le, re}) {
    if (eye < 0) continue;
    const quat aim = face::eye_rotation(s, eye, model, bind, point, 1.0f);
    pose.rotations[static_cast<std::size_t>(eye)] = glm::normalize(slerp_short(pose.rotations[static_cast<std::size_t>(eye)], aim, weight));
  }
}

CharacterMotion perform_character(const Avatar& avatar, const SigningRig& rig, const WalkRig& walk_rig, const CharacterRecord& record,
                                  const SceneGeometry& geometry, const ObjectsAt& objects_at, const Environment& env, float duration,
                                  const CharacterMotionOptions& options) {
  CharacterMotion out;
  const Skeleton& s = avatar.skeleton;
  // The walk over the whole trajectory, then the sentences on top.
  WalkMotion walk = synthesize_walk(walk_rig, record.trajectory, &env, options.gait, 60.0f);
  out.steps = walk.steps;
  TrackStack stack(s);
  TrackLayer walking;
  walking.name = "walk";
  walking.clip = std::make_shared<Clip>(std::move(walk.clip));
  walking.fade_in = walking.fade_out = 0.0f;
  walking.hold = true;
  stack.add(walking);
  for (const SpeechRecord& sp : record.speech) {
    TrackLayer layer;
    layer.name = "signing";
    layer.clip = sp.clip;
    layer.start = sp.start;
    layer.fade_in = layer.fade_out = options.sign_fade;
    layer.mask = mask_of_clip(*sp.clip, s.size());
    layer.priority = 1;
    stack.add(layer);
  }

  // Reaches, worked out at their moments of contact.
  std::vector<PreparedReach> reaches;
  Pose pose;
  for (const ReachRecord& r : record.reaches) {
    PreparedReach p;
    p.record = r;
    const HandRig& h = rig.hand(r.hand);
    p.arm = h.arm.joints;
    p.joints = h.arm.joints;
    for (const auto& finger : h.fingers)
      for (int j : finger) p.joints.push_back(j);
    stack.evaluate(r.contact, pose);
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    const vec3 shoulder = vec3(model[static_cast<std::size_t>(h.shoulder)][3]);
    const std::vector<mat4> transforms = objects_at(r.contact);
    const Environment parts = object_primitives(geometry, transforms, r.object);
    auto grasp = choose_object_grasp(parts, r.object, shoulder, r.hand, rig);
    if (!grasp) {
      out.notes.push_back("reach for " + geometry.object_names[static_cast<std::size_t>(r.object)] + ": it has no part a hand can hold");
      continue;
    }
    // Something low or across a table: bend over toward it, then choose the grasp from there.
    p.holding = pose;
    for (const char* name : {"vl5", "vl3", "vl1", "vt12"})
      if (const int j = s.find(name); j >= 0) p.spine.push_back(j);
    p.crouch = plan_crouch(s, walk_rig, p.spine, h.shoulder, grasp->palm_centre, p.holding);
    // The walk's closing steps may still be landing as the arm sets off: the knees bend once both
    // feet are down (a step's heel strike and its roll onto the sole), so a planted foot never slides.
    p.crouch_from = r.start;
    for (const Footstep& step : out.steps.steps)
      if (step.lift < r.contact) p.crouch_from = std::max(p.crouch_from, step.land + 0.15f);
    p.crouch_from = std::min(p.crouch_from, r.contact - 0.25f);
    apply_crouch(s, walk_rig, p.crouch, 1.0f, p.holding);
    if (lean_toward(s, p.spine, h.shoulder, grasp->palm_centre, p.holding) > 0.0f || p.crouch.drop > 0.0f) {
      local_to_model(s, p.holding, model);
      if (auto from_there = choose_object_grasp(parts, r.object, vec3(model[static_cast<std::size_t>(h.shoulder)][3]), r.hand, rig))
        grasp = from_there;
    } else {
      p.spine.clear();
    }
    p.grasp = *grasp;
    const GraspResult result = perform_grasp(rig, p.grasp, p.holding);
    if (!result.reach.reached)
      out.notes.push_back("reach for " + geometry.object_names[static_cast<std::size_t>(r.object)] + ": the hand stops " +
                          std::to_string(static_cast<int>(std::lround(result.reach.position_error * 100.0f))) + " cm short");
    {
      Pose start;
      stack.evaluate(r.start, start);
      local_to_model(s, start, model);
      p.lift[0] = vec3(model[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
      p.approach = start;
    }
    p.ready = p.holding;
    for (std::size_t k = p.arm.size(); k < p.joints.size(); ++k) {
      const auto j = static_cast<std::size_t>(p.joints[k]);
      p.ready.rotations[j] = s.rest_rotations[j];
    }
    p.lift[2] = p.grasp.palm_centre - p.grasp.palm_normal * kReadyBack + vec3(0, kReadyUp, 0);
    p.lift[1] = vec3(p.lift[0].x, std::max(p.lift[0].y, p.lift[2].y), p.lift[0].z);
    reach_arm(rig, r.hand, p.lift[2], grasp_wrist_rotation(p.grasp, rig), p.ready, false);
    const mat4 inverse = glm::inverse(transforms[static_cast<std::size_t>(r.object)]);
    p.palm_local = vec3(inverse * vec4(p.grasp.palm_centre, 1.0f));
    p.normal_local = mat3(inverse) * p.grasp.palm_normal;
    p.finger_local = mat3(inverse) * p.grasp.finger;
    p.last = p.holding;
    p.let_go_palm = p.grasp.palm_centre;
    p.let_go_normal = p.grasp.palm_normal;
    p.ok = true;
    reaches.push_back(std::move(p));
  }

  // The gaze: what the look behaviour chose, eased (the point glides to a new target, the weight
  // comes and goes over options.look_lag).
  std::vector<vec3> look_point(record.looks.size());
  std::vector<float> look_weight(record.looks.size());
  {
    const float a = std::min(1.0f, record.trajectory.dt / std::max(1e-3f, options.look_lag));
    vec3 p = record.looks.empty() ? vec3(0.0f) : record.looks.front().point;
    float w = 0.0f;
    for (std::size_t k = 0; k < record.looks.size(); ++k) {
      const LookSample& l = record.looks[k];
      if (l.weight > 0.0f) p = w < 0.05f ? l.point : glm::mix(p, l.point, std::min(1.0f, 2.0f * a));
      w += (l.weight - w) * a;
      look_point[k] = p;
      look_weight[k] = w;
    }
  }

  // Every frame: the blended tracks, the reaches, the gaze.
  const std::vector<int> head_joints = {s.find("vc4"), s.find("skullbase"), s.find("l_eyeball_joint"), s.find("r_eyeball_joint")};
  std::vector<bool> keyed(s.size(), false);
  for (const TrackLayer& l : stack.layers())
    for (std::size_t j = 0; j < s.size(); ++j) keyed[j] = keyed[j] || !l.clip->rotations[j].empty();
  for (int j : head_joints)
    if (j >= 0) keyed[static_cast<std::size_t>(j)] = true;
  for (const PreparedReach& r : reaches) {
    for (int j : r.joints) keyed[static_cast<std::size_t>(j)] = true;
    for (int j : r.spine) keyed[static_cast<std::size_t>(j)] = true;
  }
  Clip& clip = out.clip;
  clip.name = "scene";
  clip.resize_joints(s.size());
  clip.duration = duration;
  for (const std::string& c : stack.channel_names()) clip.channel(c).interpolation = Interpolation::Linear;
  std::vector<mat4> model(s.size());
  std::vector<float> channels;
  const int frames = std::max(1, static_cast<int>(std::ceil(duration * options.fps - 1e-4f))) + 1;
  for (int i = 0; i < frames; ++i) {
    const float t = std::min(duration, static_cast<float>(i) / options.fps);
    stack.evaluate(t, pose, &channels);
    for (PreparedReach& r : reaches) {
      const ReachRecord& rec = r.record;
      if (t < rec.start || t > rec.end) continue;
      const HandRig& h = rig.hand(rec.hand);
      if (t < rec.contact) {
        // Bring the arm from where it is to the pre-grasp, opening the fingers, then on to the grasp,
        // closing them at the end; the body bends over meanwhile.
        const float u = (t - rec.start) / std::max(1e-3f, rec.contact - rec.start);
        const float s_body = minimum_jerk(u);
        apply_crouch(s, walk_rig, r.crouch, minimum_jerk((t - r.crouch_from) / std::max(1e-3f, rec.contact - r.crouch_from)), pose);
        for (int j : r.spine) pose.rotations[static_cast<std::size_t>(j)] = slerp_short(pose.rotations[static_cast<std::size_t>(j)], r.holding.rotations[static_cast<std::size_t>(j)], s_body);
        if (u < kReadyShare) {
          // The palm goes up first, to the pre-grasp's height, then across to it (not forward through
          // the edge of the table the object stands on): the arm solved along that way, each frame from
          // the last, turning into the pre-grasp's posture as it arrives.
          const float a = minimum_jerk(u / kReadyShare);
          const float d1 = glm::length(r.lift[1] - r.lift[0]), d2 = glm::length(r.lift[2] - r.lift[1]);
          const float along = a * (d1 + d2);
          const vec3 palm = along <= d1 ? glm::mix(r.lift[0], r.lift[1], d1 > 1e-4f ? along / d1 : 1.0f)
                                        : glm::mix(r.lift[1], r.lift[2], d2 > 1e-4f ? (along - d1) / d2 : 1.0f);
          Pose solved = pose;
          if (!r.approaching) r.approach = pose, r.approaching = true;
          for (int j : r.arm) solved.rotations[static_cast<std::size_t>(j)] = r.approach.rotations[static_cast<std::size_t>(j)];
          reach_arm(rig, rec.hand, palm, std::nullopt, solved, false);
          r.approach = solved;
          const float into_ready = smooth((a - 0.6f) / 0.4f);
          for (std::size_t k = 0; k < r.joints.size(); ++k) {
            const auto j = static_cast<std::size_t>(r.joints[k]);
            pose.rotations[j] = k < r.arm.size() ? slerp_short(solved.rotations[j], r.ready.rotations[j], into_ready)
                                                 : slerp_short(pose.rotations[j], r.ready.rotations[j], smooth(a / 0.5f));
          }
        } else {
          const float s_arm = minimum_jerk((u - kReadyShare) / (1.0f - kReadyShare));
          const float close = smooth((s_arm - 0.5f) / 0.5f);
          for (std::size_t k = 0; k < r.joints.size(); ++k) {
            const auto j = static_cast<std::size_t>(r.joints[k]);
            pose.rotations[j] = slerp_short(r.ready.rotations[j], r.holding.rotations[j], k < r.arm.size() ? s_arm : close);
          }
        }
      } else if (t <= rec.release) {
        // Holding: the hand stays on the object as it moves (a door's handle swinging round).
        const std::vector<mat4> transforms = objects_at(t);
        const mat4& m = transforms[static_cast<std::size_t>(rec.object)];
        const vec3 palm = vec3(m * vec4(r.palm_local, 1.0f));
        GraspPlan now = r.grasp;
        now.palm_centre = palm;
        now.palm_normal = glm::normalize(mat3(m) * r.normal_local);
        now.finger = glm::normalize(mat3(m) * r.finger_local);
        apply_crouch(s, walk_rig, r.crouch, 1.0f, pose);
        for (int j : r.spine) pose.rotations[static_cast<std::size_t>(j)] = r.holding.rotations[static_cast<std::size_t>(j)];
        Pose held = pose;
        for (int j : r.joints) held.rotations[static_cast<std::size_t>(j)] = r.last.rotations[static_cast<std::size_t>(j)];
        reach_arm(rig, rec.hand, palm, grasp_wrist_rotation(now, rig), held, false);
        for (int j : r.joints) pose.rotations[static_cast<std::size_t>(j)] = held.rotations[static_cast<std::size_t>(j)];
        r.last = held;
        r.let_go_palm = palm;
        r.let_go_normal = now.palm_normal;
        (void)h;
      } else {
        // Letting go: the open hand backs off the object and rises, comes back over the edge of what
        // the object stands on, and drops to where the body carries it; the body straightens.
        const float v = (t - rec.release) / std::max(1e-3f, rec.end - rec.release);
        const Pose body = pose;
        apply_crouch(s, walk_rig, r.crouch, 1.0f - minimum_jerk((v - 0.2f) / 0.8f), pose);
        for (int j : r.spine) pose.rotations[static_cast<std::size_t>(j)] = slerp_short(r.holding.rotations[static_cast<std::size_t>(j)], body.rotations[static_cast<std::size_t>(j)], minimum_jerk((v - 0.2f) / 0.8f));
        std::vector<mat4> now_model(s.size());
        local_to_model(s, body, now_model);
        const vec3 rest_palm = vec3(now_model[static_cast<std::size_t>(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
        const vec3 off = r.let_go_palm - r.let_go_normal * kReadyBack + vec3(0, kReadyUp, 0);
        const std::array<vec3, 4> way = {r.let_go_palm, off, vec3(rest_palm.x, std::max(off.y, rest_palm.y), rest_palm.z), rest_palm};
        float lengths[3], total = 0.0f;
        for (int k = 0; k < 3; ++k) total += lengths[k] = glm::length(way[static_cast<std::size_t>(k + 1)] - way[static_cast<std::size_t>(k)]);
        const float b = minimum_jerk(v);
        float along = b * total;
        vec3 palm = way[3];
        for (int k = 0; k < 3; ++k) {
          if (along <= lengths[k]) {
            palm = glm::mix(way[static_cast<std::size_t>(k)], way[static_cast<std::size_t>(k + 1)], lengths[k] > 1e-4f ? along / lengths[k] : 1.0f);
            break;
          }
          along -= lengths[k];
        }
        Pose solved = pose;
        if (!r.leaving_started) r.leaving = r.last, r.leaving_started = true;
        for (int j : r.arm) solved.rotations[static_cast<std::size_t>(j)] = r.leaving.rotations[static_cast<std::size_t>(j)];
        reach_arm(rig, rec.hand, palm, std::nullopt, solved, false);
        r.leaving = solved;
        const float into_body = smooth((b - 0.7f) / 0.3f);
        for (std::size_t k = 0; k < r.joints.size(); ++k) {
          const auto j = static_cast<std::size_t>(r.joints[k]);
          if (k < r.arm.size()) pose.rotations[j] = slerp_short(solved.rotations[j], body.rotations[j], into_body);
          else pose.rotations[j] = slerp_short(slerp_short(r.last.rotations[j], s.rest_rotations[j], smooth(b / 0.2f)), body.rotations[j], into_body);
        }
      }
    }
    if (!record.looks.empty()) {
      const auto k = std::min(record.looks.size() - 1, static_cast<std::size_t>(std::lround(t / record.trajectory.dt)));
      apply_look_at(s, pose, look_point[k], look_weight[k], rig.bind_model, model);
    }
    for (std::size_t j = 0; j < s.size(); ++j)
      if (keyed[j]) clip.rotations[j].add(t, pose.rotations[j]);
    clip.translations[static_cast<std::size_t>(walk_rig.root)].add(t, pose.translations[static_cast<std::size_t>(walk_rig.root)]);
    for (std::size_t c = 0; c < channels.size(); ++c) clip.channels[c].add(t, channels[c]);
    if (t >= duration) break;
  }
  for (std::size_t j = 0; j < s.size(); ++j) {
    clip.rotations[j].interpolation = Interpolation::Linear;
    make_continuous(clip.rotations[j]);
  }
  clip.translations[static_cast<std::size_t>(walk_rig.root)].interpolation = Interpolation::Linear;
  return out;
}

}  // namespace gestura
