#include "gestura/world/grasp.hpp"

#include <algorithm>

#include "gestura/body/skinning.hpp"
#include "gestura/ik/chain.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/reference_arm.hpp"
#include "gestura/ik/swivel_arm.hpp"
#include "gestura/world/shapes.hpp"

namespace gestura {
namespace {

constexpr vec3 kUp(0.0f, 1.0f, 0.0f);
constexpr float kTouch = 0.0015f;  // a finger touches within 1.5 mm of the surface

vec3 axis_scale(const mat4& m) { return {glm::length(vec3(m[0])), glm::length(vec3(m[1])), glm::length(vec3(m[2]))}; }

vec3 perpendicular(const vec3& v, const vec3& to) {
  const vec3 p = v - glm::dot(v, to) * to;
  return glm::length(p) > 1e-5f ? glm::normalize(p) : vec3(0.0f);
}

float object_distance(const WorldPrimitive& w, const vec3& p) {
  return shape_signed_distance(w.shape, vec3(w.to_local * vec4(p, 1.0f))) * w.scale_min;
}

// Fingers wrapped round a bar of radius r along `axis` through `point` on it, approached from `from`.
void power_frame(GraspPlan& g, const vec3& axis, const vec3& point, float r, const vec3& from, const SigningRig& rig) {
  const vec3 approach = glm::normalize(point - from);
  vec3 n;
  if (std::abs(glm::dot(axis, kUp)) > 0.7f) {
    n = perpendicular(approach, axis);                                   // an upright bar: palm facing it
  } else {
    n = perpendicular(glm::normalize(approach + vec3(0, -0.6f, 0)), axis);  // a lying bar: palm over it
  }
  if (glm::length(n) < 0.5f) n = perpendicular(vec3(0, -1, 0), axis);
  vec3 f = glm::normalize(glm::cross(axis, n));
  const HandFrame frame = hand_frame_from_vectors(f, n, g.hand);
  if (std::abs(glm::dot(axis, kUp)) > 0.7f) {
    if (glm::dot(frame.thumb_side, kUp) < 0.0f) f = -f;                 // thumb up round an upright bar
  } else if (glm::dot(f, perpendicular(approach, kUp)) < 0.0f) {
    f = -f;                                                              // fingers over the bar, away from the body
  }
  g.palm_normal = n;
  g.finger = f;
  g.palm_centre = point - n * (r + rig.hand(Hand::Right).palm_half_thickness + 0.004f) - f * std::min(0.02f, 0.3f * r);
  g.size = 2.0f * r;
  g.pivot_point = point;
  g.pivot_axis = axis;
}

}  // namespace

const char* grasp_name(GraspType type) {
  switch (type) {
    case GraspType::Power: return "power";
    case GraspType::Spherical: return "spherical";
    case GraspType::Precision: return "precision";
    case GraspType::Flat: return "flat";
  }
  return "?";
}

GraspPlan choose_grasp(const WorldPrimitive& part, const vec3& from, Hand hand, const SigningRig& rig) {
  GraspPlan g;
  g.hand = hand;
  g.object = part;
  const mat4& m = part.to_world;
  const vec3 scale = axis_scale(m);
  const vec3 centre = vec3(m[3]);
  const float palm = rig.hand(Hand::Right).palm_half_thickness;
  auto flat_on = [&](const vec3& point, const vec3& outward) {
    g.type = GraspType::Flat;
    g.palm_normal = -outward;
    vec3 f = perpendicular(kUp, outward);
    if (glm::length(f) < 0.5f) f = perpendicular(glm::normalize(centre - from), outward);
    g.finger = f;
    g.palm_centre = point + outward * (palm + 0.003f);
    g.pivot_point = point;
    g.pivot_axis = outward;
  };
  switch (part.shape.kind) {
    case ShapeKind::Cylinder: {
      const vec3 axis = glm::normalize(vec3(m[1]));
      const float r = part.shape.radius * 0.5f * (scale.x + scale.z);
      const float half = 0.5f * part.shape.height * scale.y;
      const float along = std::clamp(glm::dot(from - centre, axis), -half + std::min(half, 0.04f), half - std::min(half, 0.04f));
      const vec3 point = centre + axis * along;
      if (2.0f * r <= 0.09f) {
        g.type = GraspType::Power;
        power_frame(g, axis, point, r, from, rig);
      } else {
        const vec3 out = perpendicular(from - point, axis);
        flat_on(point + out * r, out);
      }
      break;
    }
    case ShapeKind::Sphere: {
      const float r = part.shape.radius * std::max({scale.x, scale.y, scale.z});
      const vec3 approach = glm::normalize(centre - from);
      if (2.0f * r < 0.05f) {
        // Too small to close the hand round: the hand over it, set back so the bending fingers
        // come down on it with their pads; thumb and index close on it, the others tuck in.
        g.type = GraspType::Precision;
        g.palm_normal = glm::normalize(vec3(0, -1, 0) * 0.85f + perpendicular(approach, kUp) * 0.15f);
        g.finger = perpendicular(approach, g.palm_normal);
        // …shifted a finger's width toward the little finger, so index and middle fingers meet it.
        const vec3 radial = hand_frame_from_vectors(g.finger, g.palm_normal, hand).thumb_side;
        g.palm_centre = centre - g.palm_normal * (r + palm + 0.012f) - g.finger * 0.055f - radial * 0.012f;
        g.pivot_point = centre, g.pivot_axis = kUp;
      } else if (2.0f * r <= 0.16f) {
        g.type = GraspType::Spherical;
        g.palm_normal = glm::normalize(vec3(0, -1, 0) * 0.8f + perpendicular(approach, kUp) * 0.2f);
        g.finger = perpendicular(approach, g.palm_normal);
        g.palm_centre = centre - g.palm_normal * (r + palm + 0.004f);
        g.pivot_point = centre, g.pivot_axis = kUp;
      } else {
        const vec3 out = glm::normalize(from - centre);
        flat_on(centre + out * r, out);
      }
      g.size = 2.0f * r;
      break;
    }
    case ShapeKind::Box: {
      const vec3 dims = part.shape.size * scale;
      const vec3 axes[3] = {glm::normalize(vec3(m[0])), glm::normalize(vec3(m[1])), glm::normalize(vec3(m[2]))};
      int thin = 0, longest = 0;
      for (int i = 1; i < 3; ++i) {
        if (dims[i] < dims[thin]) thin = i;
        if (dims[i] > dims[longest]) longest = i;
      }
      const int third = 3 - thin - longest;
      if (dims[thin] <= 0.07f && dims[third] <= 0.07f) {
        g.type = GraspType::Power;
        const float half = dims[longest] * 0.5f;
        const float along = std::clamp(glm::dot(from - centre, axes[longest]), -half + std::min(half, 0.05f), half - std::min(half, 0.05f));
        power_frame(g, axes[longest], centre + axes[longest] * along, 0.5f * std::max(dims[thin], dims[third]), from, rig);
      } else {
        // The face turned most toward `from`; the palm at the point of it nearest `from`.
        int best = 0;
        float best_dot = -2.0f, sign = 1.0f;
        const vec3 to = glm::normalize(from - centre);
        for (int i = 0; i < 3; ++i)
          for (float s : {1.0f, -1.0f})
            if (s * glm::dot(axes[i], to) > best_dot) best_dot = s * glm::dot(axes[i], to), best = i, sign = s;
        const vec3 out = axes[best] * sign;
        vec3 point = centre + out * dims[best] * 0.5f;
        for (int i = 0; i < 3; ++i)
          if (i != best) point += axes[i] * std::clamp(glm::dot(from - centre, axes[i]), -dims[i] * 0.4f, dims[i] * 0.4f);
        flat_on(point, out);
      }
      g.size = dims[thin];
      break;
    }
    default: {
      const vec3 out = glm::normalize(from - centre);
      flat_on(centre, out);
      break;
    }
  }
  return g;
}

std::optional<GraspPlan> choose_object_grasp(const Environment& env, int object, const vec3& from, Hand hand, const SigningRig& rig) {
  const WorldPrimitive* best = nullptr;
  float best_d = 1e30f;
  for (const WorldPrimitive& w : env.primitives) {
    if (w.object != object) continue;
    // Prefer what a hand can close round (a handle, a bottle: its two smaller sides small) over a
    // big part at the same distance (a door's panel, thin as it is).
    vec3 dims = axis_scale(w.to_world) * (w.shape.kind == ShapeKind::Box ? w.shape.size : vec3(2.0f * w.shape.radius));
    if (w.shape.kind == ShapeKind::Cylinder) dims.y = 0.0f;  // its length does not count
    std::sort(&dims.x, &dims.x + 3);
    const float size = w.shape.kind == ShapeKind::Cylinder ? dims.z : dims.y;
    const float d = object_distance(w, from) + (size <= 0.09f ? -0.3f : 0.0f);
    if (d < best_d) best_d = d, best = &w;
  }
  if (!best) return std::nullopt;
  return choose_grasp(*best, from, hand, rig);
}

quat grasp_wrist_rotation(const GraspPlan& g, const SigningRig& rig) {
  const HandRig& h = rig.hand(g.hand);
  const HandFrame frame = hand_frame_from_vectors(g.finger, g.palm_normal, g.hand);
  return wrist_rotation_for(frame, h.rest_frame.rotation, h.rest_wrist_rotation);
}

GraspPlan turned(const GraspPlan& grasp, float angle) {
  GraspPlan g = grasp;
  const quat q = glm::angleAxis(angle, glm::normalize(grasp.pivot_axis));
  g.palm_centre = grasp.pivot_point + q * (grasp.palm_centre - grasp.pivot_point);
  g.palm_normal = q * grasp.palm_normal;
  g.finger = q * grasp.finger;
  return g;
}

ReachResult reach_for_grasp(const SigningRig& rig, GraspPlan& grasp, Pose& pose) {
  const Pose start = pose;
  ReachResult best;
  best.position_error = 1e30f;
  GraspPlan chosen = grasp;
  Pose best_pose = pose;
  for (const float angle : {0.0f, 25.0f, -25.0f, 50.0f, -50.0f, 75.0f, -75.0f, 100.0f, -100.0f, 180.0f}) {
    GraspPlan g = turned(grasp, deg(angle));
    Pose p = start;
    const ReachResult r = reach_arm(rig, g.hand, g.palm_centre, grasp_wrist_rotation(g, rig), p);
    const bool better = (r.reached && !best.reached) || (r.reached == best.reached &&
                        (r.reached ? r.orientation_error < best.orientation_error : r.position_error < best.position_error));
    if (better) best = r, chosen = g, best_pose = p;
    if (best.reached && best.orientation_error < deg(3.0f)) break;
  }
  grasp = chosen;
  pose = best_pose;
  return best;
}

ReachResult reach_arm(const SigningRig& rig, Hand hand, const vec3& palm_centre, const std::optional<quat>& wrist_rotation,
                      Pose& pose, bool from_ready) {
  const Skeleton& s = rig.skeleton();
  const HandRig& h = rig.hand(hand);
  if (from_ready) {
    const Pose ready = arm_ready_pose(s, hand == Hand::Right ? "r" : "l");
    for (int j : h.arm.joints) pose.rotations[static_cast<std::size_t>(j)] = ready.rotations[static_cast<std::size_t>(j)];
  }
  if (wrist_rotation) {
    // A start from the analytic arm (shoulder, elbow swivel, forearm twist, wrist within their
    // limits) puts the Jacobian near the right elbow posture.
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    const vec3 shoulder = vec3(model[static_cast<std::size_t>(h.shoulder)][3]);
    const quat parent = glm::quat_cast(mat3(model[static_cast<std::size_t>(s.parents[static_cast<std::size_t>(h.shoulder)])]));
    const vec3 wrist = palm_centre - *wrist_rotation * h.palm_centre_local;
    const SwivelSolution start = solve_swivel_arm(s, h.swivel, shoulder, parent, SwivelGoal{wrist, *wrist_rotation}, SwivelPreference{});
    apply_swivel_solution(s, h.swivel, start, pose);
  }
  IkWorkspace ws(h.arm);
  const mat4 base = parent_model_matrix(s, pose, h.arm.joints.front());
  auto solve = [&](Pose& p, float orientation_scale, bool with_orientation) {
    IkTarget target;
    target.position = palm_centre;
    if (wrist_rotation && with_orientation) target.orientation = *wrist_rotation, target.has_orientation = true;
    IkSettings settings;
    settings.max_iterations = 300;
    settings.position_tolerance = 2e-4f;
    settings.orientation_tolerance = deg(0.5f);
    settings.orientation_scale = orientation_scale;
    IkResult r = solve_dls(s, h.arm, base, target, settings, ws, p);
    if (r.position_error > 0.005f) {
      Pose retry = p;
      const IkResult r2 = solve_combined(s, h.arm, base, target, settings, ws, retry);
      if (r2.position_error < r.position_error) p = retry, r = r2;
    }
    return r;
  };
  // The hand's place matters most: when the turn asked for cannot be had there (joint limits), the
  // turn gives way — less weight on it, then none.
  Pose best = pose;
  IkResult result = solve(best, 0.1f, true);
  for (const float scale : {0.03f, 0.0f}) {
    if (result.position_error <= 0.005f) break;
    Pose retry = best;
    const IkResult r = solve(retry, scale, scale > 0.0f);
    if (r.position_error < result.position_error) best = retry, result = r;
  }
  pose = best;
  ReachResult out;
  out.position_error = result.position_error;
  out.iterations = result.iterations;
  if (wrist_rotation) {
    std::vector<mat4> model(s.size());
    local_to_model(s, pose, model);
    const quat have = glm::quat_cast(mat3(model[static_cast<std::size_t>(h.wrist)]));
    out.orientation_error = glm::length(rotation_error(have, *wrist_rotation));
  }
  out.reached = out.position_error < 0.01f;
  return out;
}

namespace {

vec3 flexion_axis(const Skeleton& s, int joint) {
  const JointDofs& d = s.dofs[static_cast<std::size_t>(joint)];
  int axis = -1;
  float widest = 0.0f;
  for (int a = 0; a < 3; ++a)
    if (d.free(a) && d.max_angle[a] - d.min_angle[a] > widest) widest = d.max_angle[a] - d.min_angle[a], axis = a;
  vec3 out(0.0f);
  if (axis >= 0) out[axis] = std::abs(d.min_angle[axis]) > std::abs(d.max_angle[axis]) ? d.min_angle[axis] : d.max_angle[axis];
  return out;  // the full flexion, signed
}

void set_angles(const Skeleton& s, Pose& pose, int joint, const vec3& angles) {
  quat q = s.rest_rotations[static_cast<std::size_t>(joint)] * euler_to_quat(angles, s.dofs[static_cast<std::size_t>(joint)].order);
  clamp_joint_to_limits(s, joint, q);
  pose.rotations[static_cast<std::size_t>(joint)] = q;
}

bool carried_by(const Skeleton& s, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = s.parents[static_cast<std::size_t>(j)])
    if (j == ancestor) return true;
  return false;
}

// The skin vertices of each finger of a hand (by their strongest joint).
std::array<std::vector<std::uint32_t>, 5> finger_vertices(const SigningRig& rig, Hand hand) {
  const Skeleton& s = rig.skeleton();
  const Mesh& m = rig.avatar->mesh;
  const HandRig& h = rig.hand(hand);
  std::array<std::vector<std::uint32_t>, 5> out;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (m.weights[v][k] > m.weights[v][best]) best = k;
    const int j = m.joints[v][best];
    for (int f = 0; f < 5; ++f)
      if (carried_by(s, j, h.fingers[static_cast<std::size_t>(f)][f == 0 ? 1 : 0])) out[static_cast<std::size_t>(f)].push_back(v);
  }
  return out;
}

// Skins the listed vertices for `pose` and returns their least signed distance to the object.
struct SkinScratch {
  std::vector<mat4> model, inverse_bind, skinning;
  explicit SkinScratch(const SigningRig& rig) : model(rig.skeleton().size()), inverse_bind(rig.skeleton().size()), skinning(rig.skeleton().size()) {
    for (std::size_t j = 0; j < inverse_bind.size(); ++j) inverse_bind[j] = glm::inverse(rig.bind_model[j]);
  }
};

float skin_distance(const SigningRig& rig, const Pose& pose, std::span<const std::uint32_t> vertices, const WorldPrimitive& object,
                    SkinScratch& k) {
  const Mesh& m = rig.avatar->mesh;
  local_to_model(rig.skeleton(), pose, k.model);
  skinning_matrices(k.model, k.inverse_bind, k.skinning);
  float best = 1e30f;
  for (std::uint32_t v : vertices) {
    vec3 p(0.0f);
    for (int c = 0; c < 4; ++c) {
      const float w = m.weights[v][c];
      if (w != 0.0f) p += w * vec3(k.skinning[m.joints[v][c]] * vec4(m.positions[v], 1.0f));
    }
    best = std::min(best, object_distance(object, p));
  }
  return best;
}

}  // namespace


void set_finger_curls(const SigningRig& rig, Hand hand, GraspType type, const std::array<float, 5>& curl, Pose& pose) {
  const Skeleton& s = rig.skeleton();
  const HandRig& h = rig.hand(hand);
  const float mirror = hand == Hand::Right ? -1.0f : 1.0f;
  // Thumb: its curl first turns it into opposition (out of the palm plane, facing the fingers),
  // then bends it; a flat palm keeps it along the hand.
  const float c0 = type == GraspType::Flat ? std::min(curl[0], 0.0f) : curl[0];
  const float oppose = std::clamp(2.0f * c0, 0.0f, 1.0f), bend = std::max(0.0f, (c0 - 0.3f) / 0.7f);
  const float open = std::max(0.0f, -c0);  // a negative curl opens the thumb further, out of the way
  // Open (curl 0): extended and lifted back out of the palm's way.
  set_angles(s, pose, h.fingers[0][0],
             vec3(glm::mix(deg(-12.0f), deg(8.0f), oppose) + bend * deg(25.0f) - open * deg(10.0f), mirror * deg(-35.0f) * oppose,
                  mirror * (glm::mix(deg(8.0f), deg(-40.0f), oppose) + open * deg(8.0f))));
  set_angles(s, pose, h.fingers[0][1], vec3(bend * deg(50.0f), 0.0f, 0.0f));
  set_angles(s, pose, h.fingers[0][2], vec3(bend * deg(65.0f), 0.0f, 0.0f));
  const float share[3] = {0.9f, 0.95f, 0.75f};  // MCP, PIP, DIP: how far of their range a full curl goes
  for (int f = 1; f < 5; ++f)
    for (int k = 0; k < 3; ++k) {
      const int j = h.fingers[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)];
      set_angles(s, pose, j, flexion_axis(s, j) * (share[k] * curl[static_cast<std::size_t>(f)]));
    }
}

FingerClosure close_fingers(const SigningRig& rig, const GraspPlan& grasp, Pose& pose) {
  FingerClosure out;
  const auto vertices = finger_vertices(rig, grasp.hand);
  SkinScratch model(rig);
  std::array<float, 5> curl{};
  // A precision grasp closes index and middle on the object and tucks the others; a flat hand only lays its
  // fingers on the surface.
  std::array<bool, 5> closes{true, true, true, true, true};
  float most = 1.0f;
  if (grasp.type == GraspType::Precision) closes = {true, true, true, false, false}, curl = {0, 0, 0, 0.6f, 0.65f};
  if (grasp.type == GraspType::Flat) most = 0.35f;
  set_finger_curls(rig, grasp.hand, grasp.type, curl, pose);
  for (int f = 0; f < 5; ++f) {
    const auto i = static_cast<std::size_t>(f);
    auto distance_at = [&](float c) {
      curl[i] = c;
      set_finger_curls(rig, grasp.hand, grasp.type, curl, pose);
      return skin_distance(rig, pose, vertices[i], grasp.object, model);
    };
    const float start = curl[i];
    const float d0 = distance_at(start);
    if (d0 < 0.0f) {
      // Already in the object where it starts: open it until it only touches.
      float lo = -1.0f, hi = start;
      if (distance_at(lo) < 0.0f) {
        curl[i] = lo;
        continue;
      }
      for (int it = 0; it < 18; ++it) {
        const float mid = 0.5f * (lo + hi);
        (distance_at(mid) < 0.0005f ? hi : lo) = mid;
      }
      distance_at(lo);
      out.touching[i] = true;
      continue;
    }
    if (!closes[i]) continue;
    if (d0 <= kTouch) {
      out.touching[i] = true;
      continue;
    }
    if (distance_at(most) > kTouch) continue;  // closes round nothing: bent as far as it goes
    float lo = start, hi = most;
    for (int it = 0; it < 18; ++it) {
      const float mid = 0.5f * (lo + hi);
      (distance_at(mid) > kTouch ? lo : hi) = mid;
    }
    distance_at(hi);
    out.touching[i] = true;
  }
  out.curl = curl;
  set_finger_curls(rig, grasp.hand, grasp.type, curl, pose);
  return out;
}

GraspResult perform_grasp(const SigningRig& rig, GraspPlan& grasp, Pose& pose) {
  GraspResult out;
  const Pose start = pose;
  for (int attempt = 0; attempt < 4; ++attempt) {
    pose = start;
    out.reach = reach_for_grasp(rig, grasp, pose);
    out.closure = close_fingers(rig, grasp, pose);
    out.distances = finger_distances(rig, grasp, pose);
    // A part of the hand the fingers cannot lift out (the thumb's root, the palm's heel) in the
    // object: the palm steps back by that much and grasps again.
    const float deepest = *std::min_element(out.distances.begin(), out.distances.end());
    if (deepest >= -0.0015f || !out.reach.reached) break;
    grasp.palm_centre -= grasp.palm_normal * (-deepest + 0.001f);
  }
  return out;
}

std::array<float, 5> finger_distances(const SigningRig& rig, const GraspPlan& grasp, const Pose& pose) {
  const auto vertices = finger_vertices(rig, grasp.hand);
  SkinScratch model(rig);
  std::array<float, 5> out{};
  for (int f = 0; f < 5; ++f) out[static_cast<std::size_t>(f)] = skin_distance(rig, pose, vertices[static_cast<std::size_t>(f)], grasp.object, model);
  return out;
}

}  // namespace gestura
