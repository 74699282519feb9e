#pragma once
// One character's whole motion from what the simulation recorded: the walking skill on its
// trajectory (whole body), its sentences signed on top (arms, hands, head and face, fading in and
// out on the track system, so it may walk while signing), reaches and grasps (the arm brought to the
// object by IK on a minimum-jerk profile, the fingers closed on it, a held handle followed as the
// door swings), and its gaze (head and eyes turned to what its look behaviour chose) — baked into one
// clip in world space.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/simulation.hpp"
#include "gestura/world/walk.hpp"

namespace gestura {

struct SpeechRecord {
  float start = 0.0f;
  std::shared_ptr<const Clip> clip;  // a Signer's performance on this character's avatar
};

struct ReachRecord {
  int object = -1;
  Hand hand = Hand::Right;
  float start = 0.0f, contact = 0.0f, release = 0.0f, end = 0.0f;
};

struct CharacterRecord {
  RootTrajectory trajectory;
  std::vector<LookSample> looks;  // one per trajectory sample
  std::vector<SpeechRecord> speech;
  std::vector<ReachRecord> reaches;
};

// Each top-level object's transform at a time (doors swinging).
using ObjectsAt = std::function<std::vector<mat4>(float time)>;

struct CharacterMotionOptions {
  float fps = 30.0f;
  GaitParams gait;
  float sign_fade = 0.35f;    // seconds the signing layer takes to come in and go out
  float look_lag = 0.25f;     // seconds the gaze takes to settle on a new target
};

struct CharacterMotion {
  Clip clip;
  FootstepPlan steps;
  std::vector<std::string> notes;  // e.g. "reach for cup: the hand stops 3 cm short"
};

// Contract: `rig` and `walk` were made for `avatar`; `env` is the ground the feet stand on.
CharacterMotion perform_character(const Avatar& avatar, const SigningRig& rig, const WalkRig& walk, const CharacterRecord& record,
                                  const SceneGeometry& geometry, const ObjectsAt& objects_at, const Environment& env,
                                  float duration, const CharacterMotionOptions& options = {});

// Turns head and eyes of `pose` (world) toward `point` by `weight` (0..1): the neck and head take
// the part of the turn beyond what the eyes can do alone (face/eye_aim), added to the head
// movement the pose already has; the eyes turn the rest. `bind` are the avatar's bind-pose model
// matrices; `model` is scratch.
void apply_look_at(const Skeleton& skeleton, Pose& pose, const vec3& point, float weight, std::span<const mat4> bind,
                   std::vector<mat4>& model);

}  // namespace gestura
