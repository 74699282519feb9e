#pragma once
// The walking skill: a body trajectory in, a full-body walk out (alias-movement-through-environments.txt
// §6.1; realtime-virtual-humans.txt §3, the walking motion generator of the TRACK system).
//
// Per frame: the gait phase from the footstep plan (gait.hpp); each foot on its plant — rolling over
// the heel at heel strike, flat, rolling over the ball with the toes bent flat at heel off and toe
// off — or swinging from one plant to the next, lifted clear of the ground below it (stairs' edges
// included); the pelvis on the trajectory, bobbing, swaying over the stance foot, turning and
// dropping on the swing side, its height kept low enough for both legs to reach their feet; legs by
// analytic two-bone IK with the knee toward the foot's direction and the foot turned by ankle,
// subtalar and midtarsal joints; the thorax turning against the pelvis; arms swinging against the
// legs; hands relaxed.
//
// The result is a clip on the avatar's skeleton in world space (its root moves), to be layered on
// the track system (tracks.hpp) with signing on the arms.
#include "gestura/anim/clip.hpp"
#include "gestura/world/gait.hpp"

namespace gestura {

struct WalkMotion {
  Clip clip;
  FootstepPlan steps;
  std::vector<float> pelvis_heights;  // root height per frame (what kept the legs within reach)
  float fps = 60.0f;
};

// Contract: `rig` was made for the skeleton the clip is for; `env` may be null (flat floor at the
// trajectory's height). Deterministic.
WalkMotion synthesize_walk(const WalkRig& rig, const RootTrajectory& body, const Environment* env,
                           const GaitParams& params = {}, float fps = 60.0f);

// The foot's frame at time t as the walk places it (world transform of the plant frame: origin on
// the sole under the ankle), and the toe joint's bend. For tests and for drawing footprints.
mat4 foot_frame(const WalkRig& rig, const FootstepPlan& plan, const GaitParams& params, int foot, float t,
                const Environment* env, float* toe_bend = nullptr);

}  // namespace gestura
