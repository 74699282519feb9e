#include "gestura/sign/signing_rig.hpp"

#include <algorithm>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/ik/reference_arm.hpp"
#include "gestura/sign/phonology_joint_rotation.hpp"

namespace gestura {

namespace {

constexpr float kFaceRadius = 0.035f;  // metres: the lower face's capsule (about the chin's half width)

int need(const Skeleton& s, const std::string& name) {
  const int j = s.find(name);
  if (j < 0) throw Error("signing rig: the avatar has no joint '" + name + "'");
  return j;
}

float distance_to_site(const SigningRig& rig, const char* site, const vec3& from, float fallback) {
  const BodySite* s = find_site(rig.sites, site);
  return s ? glm::distance(site_position(*s, rig.bind_model), from) : fallback;
}

HandRig make_hand(const Skeleton& s, const std::vector<mat4>& bind, Hand hand) {
  const std::string p = hand == Hand::Right ? "r_" : "l_";
  HandRig h;
  h.hand = hand;
  h.clavicle = need(s, p + "sternoclavicular");
  h.shoulder = need(s, p + "shoulder");
  h.elbow = need(s, p + "elbow");
  h.wrist = need(s, p + "wrist");
  const char* names[5] = {"thumb", "index", "middle", "ring", "pinky"};
  for (int f = 0; f < 5; ++f) {
    for (int k = 0; k < 3; ++k) h.fingers[f][k] = need(s, p + names[f] + std::to_string(k + 1));
    h.tips[f] = need(s, p + names[f] + "_tip");
  }
  const vec3 wrist = joint_position(bind, h.wrist), index1 = joint_position(bind, h.fingers[1][0]);
  const vec3 middle1 = joint_position(bind, h.fingers[2][0]), pinky1 = joint_position(bind, h.fingers[4][0]);
  h.rest_frame = hand_frame_from_joints(wrist, index1, middle1, pinky1, hand);
  h.rest_wrist_rotation = glm::normalize(glm::quat_cast(mat3(bind[joint_slot(h.wrist)])));
  // The hand's reference point: the middle of the palm, between the wrist and the knuckles.
  const vec3 centre = 0.4f * wrist + 0.6f * (index1 + middle1 + pinky1) / 3.0f;
  h.palm_centre_local = vec3(glm::inverse(bind[joint_slot(h.wrist)]) * vec4(centre, 1.0f));
  // The solvers place the palm centre: a hand turned less than asked still sits where it should.
  h.arm = make_chain(s, h.clavicle, h.wrist, h.palm_centre_local);
  h.swivel = make_swivel_arm(s, h.shoulder, h.elbow, h.wrist);
  return h;
}

}  // namespace

SigningRig make_signing_rig(const Avatar& avatar) {
  SigningRig rig;
  rig.avatar = &avatar;
  const Skeleton& s = avatar.skeleton;
  rig.rest = rest_pose(s);
  rig.bind_model.resize(s.size());
  local_to_model(s, rig.rest, rig.bind_model);
  rig.sites = find_body_sites(s, avatar.mesh);
  for (Hand hand : kBothHands) rig.hands[hand] = make_hand(s, rig.bind_model, hand);

  // Relaxed signing posture: both arms in the ready posture (hands low, in front of the body).
  rig.neutral = rig.rest;
  for (HandRig& h : rig.hands) {
    const Pose ready = arm_ready_pose(s, h.hand == Hand::Right ? "r" : "l");
    for (int j : h.arm.joints) rig.neutral.rotations[joint_slot(j)] = ready.rotations[joint_slot(j)];
  }
  for (HandRig& h : rig.hands) {
    const std::string p = h.hand == Hand::Right ? "r_" : "l_";
    const vec3 centre = vec3(rig.bind_model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
    h.palm_half_thickness = std::clamp(distance_to_site(rig, (p + "palm").c_str(), centre, 0.015f), 0.008f, 0.03f);
  }

  // Collision body from the skeleton, sized by the surface sites.
  const int vl3 = need(s, "vl3"), vt6 = need(s, "vt6"), vt1 = need(s, "vt1"), vc7 = need(s, "vc7");
  const int skull = need(s, "skullbase");
  const vec3 belly = joint_position(rig.bind_model, vl3), upper = joint_position(rig.bind_model, vt1);
  // The torso's radius makes its surface pass through the chest site: measured from the capsule's
  // axis, not from the spine joint behind it (the axis leans forward with the upper back), so a
  // palm laid on the chest touches the capsule where it touches the skin.
  float torso_r = std::clamp(distance_to_site(rig, "chest", joint_position(rig.bind_model, vt6), 0.13f), 0.08f, 0.25f);
  if (const BodySite* chest = find_site(rig.sites, "chest")) {
    const vec3 c = site_position(*chest, rig.bind_model), top = upper - vec3(0, 0.7f * torso_r, 0);
    const vec3 axis = top - belly;
    const float k = std::clamp(glm::dot(c - belly, axis) / glm::dot(axis, axis), 0.0f, 1.0f);
    torso_r = std::clamp(glm::distance(c, belly + k * axis), 0.08f, 0.25f);
  }
  rig.body.push_back({"torso", vt6, belly, upper - vec3(0, 0.7f * torso_r, 0), torso_r});
  const vec3 neck_a = joint_position(rig.bind_model, vc7), neck_b = joint_position(rig.bind_model, skull);
  const float neck_r = std::clamp(distance_to_site(rig, "neck", 0.5f * (neck_a + neck_b), 0.05f), 0.03f, 0.1f);
  rig.body.push_back({"neck", need(s, "vc4"), neck_a, neck_b, neck_r});
  const int crown = s.find("skull_tip");
  const vec3 top = crown >= 0 ? joint_position(rig.bind_model, crown) : neck_b + vec3(0, 0.16f, 0);
  const vec3 head_c = 0.5f * (neck_b + top) + vec3(0, 0, 0.015f);
  const float head_r = std::clamp(distance_to_site(rig, "forehead", head_c, 0.09f), 0.06f, 0.14f) * 0.92f;
  rig.body.push_back({"head", skull, head_c - vec3(0, 0.02f, 0), head_c + vec3(0, 0.02f, 0), head_r});
  // The lower face (chin, lips, the nose's base) stands out of the head's sphere by 4-5 cm: a
  // capsule from the chin up to the nose, its surface through the chin and the lips.
  const BodySite* chin = find_site(rig.sites, "chin");
  const BodySite* lips = find_site(rig.sites, "lips");
  const BodySite* nose = find_site(rig.sites, "nose");
  if (chin && lips && nose) {
    const vec3 chin_at = site_position(*chin, rig.bind_model), lips_at = site_position(*lips, rig.bind_model);
    const float r = kFaceRadius;
    const vec3 low = chin_at - site_normal(*chin, rig.bind_model) * r;
    const vec3 high(lips_at.x, site_position(*nose, rig.bind_model).y, lips_at.z - r);
    rig.body.push_back({"face", skull, low, high, r});
  }
  for (CollisionCapsule& c : rig.body) {  // model space at bind pose → the carrying joint's frame
    const mat4 to_joint = glm::inverse(rig.bind_model[joint_slot(c.joint)]);
    c.a = vec3(to_joint * vec4(c.a, 1.0f));
    c.b = vec3(to_joint * vec4(c.b, 1.0f));
  }
  return rig;
}

float body_signed_distance(const SigningRig& rig, std::span<const mat4> model, const vec3& p, vec3* outward) {
  float best = 1e9f;
  for (const CollisionCapsule& c : rig.body) {
    const mat4& joint = model[joint_slot(c.joint)];
    const vec3 a = vec3(joint * vec4(c.a, 1.0f)), b = vec3(joint * vec4(c.b, 1.0f));
    const vec3 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    const vec3 closest = a + t * ab;
    const vec3 d = p - closest;
    const float dist = glm::length(d) - c.radius;
    if (dist < best) {
      best = dist;
      if (outward) *outward = glm::length(d) > 1e-6f ? d / glm::length(d) : vec3(0, 0, 1);
    }
  }
  return best;
}

void apply_hand_posture(const SigningRig& rig, Hand hand, const HandPosture& posture, Pose& pose) {
  const HandRig& h = rig.hand(hand);
  const Skeleton& s = rig.skeleton();
  // Hand-local → wrist frame: the fingers' joint frames are parallel to the wrist's at bind pose.
  const quat to_wrist = glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation;
  const quat from_wrist = glm::inverse(to_wrist);
  const Finger order[4] = {Finger::Index, Finger::Middle, Finger::Ring, Finger::Pinky};
  for (std::size_t f = 0; f < 4; ++f) {
    const FingerJointRotations r = finger_joint_rotations(posture, order[f], hand);
    const auto& j = h.fingers[f + 1];
    pose.rotations[joint_slot(j[0])] = s.rest_rotations[joint_slot(j[0])] * (to_wrist * r.mcp * from_wrist);
    pose.rotations[joint_slot(j[1])] = s.rest_rotations[joint_slot(j[1])] * (to_wrist * r.pip * from_wrist);
    pose.rotations[joint_slot(j[2])] = s.rest_rotations[joint_slot(j[2])] * (to_wrist * r.dip * from_wrist);
  }
  // Thumb: on the avatar's CMC (left hand; the right mirrors y and z) +x flexes the thumb across
  // the palm toward the little finger, −y turns it about its own axis (opposition, the thumb hangs
  // along the hand at rest) and −z lifts it out of the palm plane toward the palm (palmar
  // abduction) — measured on the rig, see the avatar skeleton's axis table.
  const float mirror = hand == Hand::Right ? -1.0f : 1.0f;
  const ThumbPose& t = posture.thumb;
  const auto& tj = h.fingers[0];
  pose.rotations[joint_slot(tj[0])] =
      joint_rotation(s, tj[0], vec3(t.cmc_flexion, mirror * -t.cmc_opposition, mirror * -t.cmc_abduction));
  pose.rotations[joint_slot(tj[1])] = joint_rotation(s, tj[1], vec3(t.mcp, 0, 0));
  pose.rotations[joint_slot(tj[2])] = joint_rotation(s, tj[2], vec3(t.ip, 0, 0));
  // A hand posture is what this hand can make: some notated shapes ask a thumb or finger joint for
  // more than its range. Clamped here, so every user of the posed hand (contact geometry, keeping
  // the hand out of the body) sees the fingers as they will be performed.
  for (const auto& finger : h.fingers)
    for (int j : finger) clamp_joint_to_limits(s, j, pose.rotations[joint_slot(j)]);
}

}  // namespace gestura
