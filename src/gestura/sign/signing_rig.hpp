#pragma once
// Everything sign synthesis needs to know about one avatar, computed once: where the body sites
// are, how to reach with each arm, how the hand is built, and a simple collision body.
//
// The rig works on any skeleton with H-Anim 1.1 names whose rest rotations are the identity at the
// wrists and fingers (the default avatar; importers bring other avatars to that form).
#include <array>
#include <span>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/body/body_sites.hpp"
#include "gestura/ik/chain.hpp"
#include "gestura/ik/swivel_arm.hpp"
#include "gestura/sign/hand.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

// A capsule of the collision body: the segment a–b swept by `radius`, carried by `joint`.
struct CollisionCapsule {
  const char* name;
  int joint;
  vec3 a, b;  // in the joint's frame (so a moved joint moves the capsule without re-deriving it)
  float radius;
};

struct HandRig {
  Hand hand = Hand::Right;
  int clavicle = -1, shoulder = -1, elbow = -1, wrist = -1;
  std::array<std::array<int, 3>, 5> fingers{};  // thumb1..3, index1..3, … pinky1..3
  std::array<int, 5> tips{};                     // *_tip sites
  IkChain arm;                                   // clavicle → wrist, effector at the palm centre
  SwivelArm swivel;                              // shoulder → elbow → wrist, solved analytically
  HandFrame rest_frame;                          // hand frame of the bind pose
  quat rest_wrist_rotation{1, 0, 0, 0};          // model rotation of the wrist at bind pose
  vec3 palm_centre_local{0.0f};                  // the hand's reference point, wrist frame
  float palm_half_thickness = 0.015f;
};

struct SigningRig {
  const Avatar* avatar = nullptr;
  std::vector<BodySite> sites;
  std::vector<mat4> bind_model;       // model matrices at bind pose
  Pose rest;                          // bind pose
  Pose neutral;                       // arms in the relaxed signing posture (hands low, in front)
  ByHand<HandRig> hands;
  std::vector<CollisionCapsule> body; // torso, neck, head, lower face

  const HandRig& hand(Hand h) const { return hands[h]; }
  const Skeleton& skeleton() const { return avatar->skeleton; }
};

// Contract: `avatar` outlives the rig. Throws gestura::Error naming a missing joint.
SigningRig make_signing_rig(const Avatar& avatar);

// Signed distance from `p` to the collision body (negative inside), and the outward direction at
// the closest capsule. `model` are the current joint model matrices.
float body_signed_distance(const SigningRig& rig, std::span<const mat4> model, const vec3& p, vec3* outward = nullptr);

// Finger joint local rotations for a hand posture (thumb included), written into `pose`, clamped
// into the joints' limits.
void apply_hand_posture(const SigningRig& rig, Hand hand, const HandPosture& posture, Pose& pose);


}  // namespace gestura
