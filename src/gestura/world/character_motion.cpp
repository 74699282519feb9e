#include "gestura/world/character_motion.hpp"

#include <algorithm>

#include "gestura/face/eye_aim.hpp"
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

// One reach worked out at its moment of contact: the grasp, the arm and fingers holding it, and the
// grasp's frame in the object's own frame (to follow the object when it moves).
struct PreparedReach {
  ReachRecord record;
  bool ok = false;
  GraspPlan grasp;
  Pose holding;               // the pose at contact with the arm and fingers grasping
  std::vector<int> joints;    // arm and finger joints the reach drives
  std::vector<int> arm;       // the IK chain
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
    const auto grasp = choose_object_grasp(parts, r.object, shoulder, r.hand, rig);
    if (!grasp) {
      out.notes.push_back("reach for " + geometry.object_names[static_cast<std::size_t>(r.object)] + ": it has no part a hand can hold");
      continue;
    }
    p.grasp = *grasp;
    p.holding = pose;
    const GraspResult result = perform_grasp(rig, p.grasp, p.holding);
    if (!result.reach.reached)
      out.notes.push_back("reach for " + geometry.object_names[static_cast<std::size_t>(r.object)] + ": the hand stops " +
                          std::to_string(static_cast<int>(std::lround(result.reach.position_error * 100.0f))) + " cm short");
    const mat4 inverse = glm::inverse(transforms[static_cast<std::size_t>(r.object)]);
    p.palm_local = vec3(inverse * vec4(p.grasp.palm_centre, 1.0f));
    p.normal_local = mat3(inverse) * p.grasp.palm_normal;
    p.finger_local = mat3(inverse) * p.grasp.finger;
    p.last = p.holding;
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
  for (const PreparedReach& r : reaches)
    for (int j : r.joints) keyed[static_cast<std::size_t>(j)] = true;
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
        // Bring the arm from where it is to the grasp; the fingers open on the way and close at the end.
        const float s_arm = minimum_jerk((t - rec.start) / std::max(1e-3f, rec.contact - rec.start));
        for (int j : r.arm) pose.rotations[static_cast<std::size_t>(j)] = slerp_short(pose.rotations[static_cast<std::size_t>(j)], r.holding.rotations[static_cast<std::size_t>(j)], s_arm);
        const float close = smooth((s_arm - 0.75f) / 0.25f);
        for (std::size_t k = r.arm.size(); k < r.joints.size(); ++k) {
          const auto j = static_cast<std::size_t>(r.joints[k]);
          const quat open = slerp_short(pose.rotations[j], s.rest_rotations[j], smooth(s_arm / 0.5f));
          pose.rotations[j] = slerp_short(open, r.holding.rotations[j], close);
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
        Pose held = pose;
        for (int j : r.joints) held.rotations[static_cast<std::size_t>(j)] = r.last.rotations[static_cast<std::size_t>(j)];
        reach_arm(rig, rec.hand, palm, grasp_wrist_rotation(now, rig), held, false);
        for (int j : r.joints) pose.rotations[static_cast<std::size_t>(j)] = held.rotations[static_cast<std::size_t>(j)];
        r.last = held;
        (void)h;
      } else {
        // Letting go: fingers open and the arm returns to what the body does.
        const float back = minimum_jerk((t - rec.release) / std::max(1e-3f, rec.end - rec.release));
        for (int j : r.joints) pose.rotations[static_cast<std::size_t>(j)] = slerp_short(r.last.rotations[static_cast<std::size_t>(j)], pose.rotations[static_cast<std::size_t>(j)], back);
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
