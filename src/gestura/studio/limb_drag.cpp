#include "gestura/studio/limb_drag.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gestura/ik/ccd.hpp"
#include "gestura/ik/chain.hpp"
#include "gestura/ik/limb.hpp"

namespace gestura::studio {
namespace {

// Distance along the ray to where it passes nearest the segment a–b, and how near; nullopt when
// it passes further than `radius` or behind the origin.
std::optional<float> ray_capsule(const vec3& o, const vec3& d, const vec3& a, const vec3& b, float radius) {
  const vec3 u = b - a, w = o - a;
  const float aa = glm::dot(d, d), bb = glm::dot(d, u), cc = glm::dot(u, u), dd = glm::dot(d, w), ee = glm::dot(u, w);
  const float den = aa * cc - bb * bb;
  float s = 0.0f, t = 0.0f;  // ray parameter, segment parameter
  if (den > 1e-12f) s = (bb * ee - cc * dd) / den;
  else s = -dd / aa;
  t = cc > 0.0f ? std::clamp((ee + s * bb) / cc, 0.0f, 1.0f) : 0.0f;
  s = std::max(0.0f, glm::dot(a + t * u - o, d) / aa);  // the ray point nearest the clamped segment point
  const float gap = glm::length(o + s * d - (a + t * u));
  if (gap > radius) return std::nullopt;
  return s * std::sqrt(aa);
}

float end_error(const Skeleton& skeleton, const Pose& pose, int end, const vec3& target) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, pose, model);
  return glm::length(vec3(model[static_cast<std::size_t>(end)][3]) - target);
}

}  // namespace

int pick_bone(const Skeleton& skeleton, std::span<const mat4> model, const vec3& origin, const vec3& direction, float radius) {
  if (glm::length(direction) < 1e-9f) return -1;
  int best = -1;
  float nearest = std::numeric_limits<float>::max();
  for (std::size_t c = 0; c < skeleton.size(); ++c) {
    const int p = skeleton.parents[c];
    if (p < 0) continue;
    const vec3 a(model[static_cast<std::size_t>(p)][3]), b(model[c][3]);
    // Finger bones are thin: their capsules are narrower so a click between fingers finds the right one.
    const float r = glm::length(b - a) < 0.06f ? radius * 0.45f : radius;
    if (const auto at = ray_capsule(origin, direction, a, b, r); at && *at < nearest) nearest = *at, best = p;
  }
  return best;
}

std::optional<DragLimb> limb_of(const Skeleton& skeleton, int joint) {
  if (joint < 0 || joint >= static_cast<int>(skeleton.size())) return std::nullopt;
  // Walk up to the first joint that names a limb part.
  for (int j = joint; j >= 0; j = skeleton.parents[static_cast<std::size_t>(j)]) {
    const std::string& name = skeleton.names[static_cast<std::size_t>(j)];
    if (name.size() < 3 || name[1] != '_' || (name[0] != 'l' && name[0] != 'r')) continue;
    const std::string side(1, name[0]);
    const bool arm = name.find("shoulder") != std::string::npos || name.find("elbow") != std::string::npos ||
                     name.find("wrist") != std::string::npos || name.find("thumb") != std::string::npos ||
                     name.find("index") != std::string::npos || name.find("middle") != std::string::npos ||
                     name.find("ring") != std::string::npos || name.find("pinky") != std::string::npos;
    const bool leg = name.find("hip") != std::string::npos || name.find("knee") != std::string::npos ||
                     name.find("ankle") != std::string::npos || name.find("tarsal") != std::string::npos ||
                     name.find("subtalar") != std::string::npos;
    if (!arm && !leg) continue;
    DragLimb limb;
    limb.arm = arm;
    limb.side = name[0];
    limb.start = skeleton.find(side + (arm ? "_shoulder" : "_hip"));
    limb.mid = skeleton.find(side + (arm ? "_elbow" : "_knee"));
    limb.end = skeleton.find(side + (arm ? "_wrist" : "_ankle"));
    if (limb.start < 0 || limb.mid < 0 || limb.end < 0) return std::nullopt;
    if (skeleton.parents[static_cast<std::size_t>(limb.mid)] != limb.start || skeleton.parents[static_cast<std::size_t>(limb.end)] != limb.mid)
      return std::nullopt;
    return limb;
  }
  return std::nullopt;
}

float drag_limb(const Skeleton& skeleton, Pose& pose, const DragLimb& limb, const vec3& wanted) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, pose, model);
  const vec3 start(model[static_cast<std::size_t>(limb.start)][3]), mid(model[static_cast<std::size_t>(limb.mid)][3]);
  const vec3 end(model[static_cast<std::size_t>(limb.end)][3]);
  // A target far beyond reach (a typed 1e30, a ray nearly parallel to the drag plane) is brought
  // within twice the limb's length: the limb points at it all the same, and the solvers see sane numbers.
  vec3 target = wanted;
  const float reach = 2.0f * (glm::length(mid - start) + glm::length(end - mid));
  const bool finite = std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z);
  if (!finite) target = end;
  else if (glm::length(target - start) > reach) target = start + glm::normalize(target - start) * reach;
  // The elbow bends out, down and back; the knee forward (the avatar faces +Z, its left is +X).
  const float out = limb.side == 'l' ? 1.0f : -1.0f;
  const vec3 pole = limb.arm ? start + vec3(0.4f * out, -0.5f, -0.6f) : mid + vec3(0.0f, 0.0f, 0.8f);
  const vec3 axis = limb.arm ? vec3(-1, 0, 0) : vec3(1, 0, 0);
  const LimbIkResult r = solve_limb(skeleton, pose, limb.start, limb.mid, limb.end, axis, target, pole);
  if (r.position_error < 2e-3f && target == wanted) return r.position_error;
  if (r.position_error < 2e-3f) return finite ? end_error(skeleton, pose, limb.end, wanted) : std::numeric_limits<float>::infinity();
  // A limit stopped the analytic solution (or the target is out of reach): let CCD use every free
  // axis of the chain, from where the two-bone solve left it, and keep the better of the two.
  const Pose analytic = pose;
  const IkChain chain = make_chain(skeleton, limb.start, limb.end);
  IkWorkspace ws(chain);
  const mat4 base = parent_model_matrix(skeleton, pose, limb.start);
  solve_ccd(skeleton, chain, base, IkTarget{target}, IkSettings{}, ws, pose);
  const float ccd = end_error(skeleton, pose, limb.end, target);
  if (ccd > r.position_error) pose = analytic;
  if (target == wanted) return std::min(ccd, r.position_error);
  // The distance left to what was asked for (infinite when that was not a point).
  return finite ? end_error(skeleton, pose, limb.end, wanted) : std::numeric_limits<float>::infinity();
}

}  // namespace gestura::studio
