#include "gestura/world/walk_rig.hpp"

#include <algorithm>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"

namespace gestura {
namespace {

int need(const Skeleton& s, const std::string& name) {
  const int j = s.find(name);
  if (j < 0) throw Error("walking: the avatar has no joint '" + name + "'");
  return j;
}

bool descends(const Skeleton& s, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = s.parents[static_cast<std::size_t>(j)])
    if (j == ancestor) return true;
  return false;
}

}  // namespace

WalkRig make_walk_rig(const Avatar& avatar) {
  const Skeleton& s = avatar.skeleton;
  WalkRig rig;
  rig.avatar = &avatar;
  rig.rest = rest_pose(s);
  rig.root = need(s, "humanoid_root");
  rig.pelvis = need(s, "sacroiliac");
  rig.spine = {need(s, "vl5"), s.find("vt12"), s.find("vt6")};
  const std::vector<vec3> at = rest_joint_positions(s);
  vec3 lo(1e30f), hi(-1e30f);
  for (const vec3& p : avatar.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  rig.height = hi.y - lo.y;
  const char* sides[2] = {"l_", "r_"};
  for (int k = 0; k < 2; ++k) {
    const std::string p = sides[k];
    LegRig& leg = rig.legs[k];
    leg.side = k == 0 ? 1.0f : -1.0f;
    leg.hip = need(s, p + "hip");
    leg.knee = need(s, p + "knee");
    leg.ankle = need(s, p + "ankle");
    leg.subtalar = s.find(p + "subtalar");
    leg.midtarsal = s.find(p + "midtarsal");
    leg.metatarsal = s.find(p + "metatarsal");
    leg.toe_tip = s.find(p + "toe_tip");
    const vec3 hip = at[static_cast<std::size_t>(leg.hip)], knee = at[static_cast<std::size_t>(leg.knee)],
               ankle = at[static_cast<std::size_t>(leg.ankle)];
    leg.thigh = glm::length(knee - hip);
    leg.shin = glm::length(ankle - knee);
    // The foot's skin: vertices mostly moved by the ankle or joints below it.
    vec3 flo(1e30f), fhi(-1e30f);
    for (std::size_t v = 0; v < avatar.mesh.positions.size(); ++v) {
      const JointIndices& j = avatar.mesh.joints[v];
      const vec4& w = avatar.mesh.weights[v];
      int best = 0;
      for (int c = 1; c < 4; ++c)
        if (w[c] > w[best]) best = c;
      if (!descends(s, j[best], leg.ankle)) continue;
      flo = glm::min(flo, avatar.mesh.positions[v]);
      fhi = glm::max(fhi, avatar.mesh.positions[v]);
    }
    if (flo.x > fhi.x) throw Error("walking: no skin is carried by " + p + "ankle");
    const float sole = flo.y;
    leg.plant_origin = vec3(ankle.x, sole, ankle.z);
    leg.ankle_point = vec3(0.0f, ankle.y - sole, 0.0f);
    // The heel touches a little in front of its rearmost point (it is round); the ball under the
    // toe joint; the toe at the foot's front.
    leg.heel = vec3(0.0f, 0.0f, flo.z + 0.015f - ankle.z);
    const vec3 ball = leg.metatarsal >= 0 ? at[static_cast<std::size_t>(leg.metatarsal)] : ankle + vec3(0, 0, 0.7f * (fhi.z - ankle.z));
    leg.ball = vec3(ball.x - ankle.x, 0.0f, ball.z - ankle.z);
    leg.toe = vec3(leg.ball.x, 0.0f, fhi.z - 0.005f - ankle.z);
    rig.root_height = at[static_cast<std::size_t>(rig.root)].y - sole;
  }
  rig.stance_width = rig.legs[0].plant_origin.x - rig.legs[1].plant_origin.x;
  for (int k = 0; k < 2; ++k) {
    const std::string p = sides[k];
    rig.shoulders[k] = need(s, p + "shoulder");
    rig.elbows[k] = need(s, p + "elbow");
    rig.wrists[k] = need(s, p + "wrist");
    for (const char* f : kFingerNames)
      for (int i = 0; i <= 3; ++i) {
        const int j = s.find(p + f + std::to_string(i));
        // The thumb's base joint places the thumb rather than bending it: left as it is.
        if (j >= 0 && s.dofs[static_cast<std::size_t>(j)].count() > 0 && !(std::string(f) == "thumb" && i == 1)) rig.fingers[k].push_back(j);
      }
  }
  return rig;
}

}  // namespace gestura
