#pragma once
// What the walking skill needs to know about one avatar, found once: the leg joints, the lengths of
// thigh and shin, and the foot's shape — where its heel, ball and toes touch the ground relative to
// the ankle (from the skin: the foot's lowest, rearmost and foremost vertices) — plus the standing
// height of the pelvis. Works on any skeleton with H-Anim leg names whose rest frames are parallel to
// the model frame (the default avatar, MakeHuman as loaded by load_avatar).
#include <array>

#include "gestura/body/avatar.hpp"

namespace gestura {

struct LegRig {
  int hip = -1, knee = -1, ankle = -1, subtalar = -1, midtarsal = -1, metatarsal = -1, toe_tip = -1;
  float thigh = 0.0f, shin = 0.0f;  // metres
  // The foot in its plant frame: origin on the sole under the ankle, +Y up, +Z toes; at rest.
  vec3 ankle_point{0.0f};  // the ankle joint (x, z = 0)
  vec3 heel{0.0f};    // where the heel first touches the ground
  vec3 ball{0.0f};    // under the ball of the foot (the toe joint), the pivot of heel-off
  vec3 toe{0.0f};     // the toe tip on the sole
  vec3 plant_origin{0.0f};  // the plant frame origin in the model's rest frame
  float side = 1.0f;  // +1 left (+X), −1 right
};

struct WalkRig {
  const Avatar* avatar = nullptr;
  int root = -1, pelvis = -1;               // humanoid_root, sacroiliac
  std::array<int, 3> spine{-1, -1, -1};     // lumbar, lower and upper thoracic joints turned against the pelvis
  std::array<LegRig, 2> legs;               // [0] left, [1] right
  int shoulders[2] = {-1, -1}, elbows[2] = {-1, -1}, wrists[2] = {-1, -1};
  std::vector<int> fingers[2];              // every finger joint per hand (relaxed while walking)
  float root_height = 0.95f;                // the root joint above the soles when standing
  float stance_width = 0.17f;               // between the plant origins at rest
  float height = 1.70f;                     // the body's height
  Pose rest;
};

// Contract: `avatar` outlives the rig. Throws gestura::Error naming a missing joint.
WalkRig make_walk_rig(const Avatar& avatar);

}  // namespace gestura
