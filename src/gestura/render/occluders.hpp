#pragma once
// Capsules that stand in for the arms and hands when the renderer works out what they
// shade: soft shadows from the key light and ambient occlusion on the body and on the other arm.
// With them a hand in front of the chest darkens the chest beside it, and the hand in front darkens
// the one behind — the cues that tell depth in a front view. Far cheaper than a shadow map on a
// software rasteriser (a few capsules per fragment instead of a second pass over every triangle).
//
// Found once from the skeleton's H-Anim joints and the bind-pose mesh: each capsule runs along a
// bone (upper arm, forearm, palm, fingers, thumb) with the radius of the skin around it.
#include <cstdint>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Which part of the body a vertex or capsule belongs to; a capsule does not shade its own part
// (an arm's capsules are too coarse to shadow that arm's own surface).
enum class BodyPart : std::uint8_t { Trunk = 0, LeftArm = 1, RightArm = 2, Head = 3 };

struct Occluder {
  int joint = 0;    // the joint whose skinning matrix moves the capsule
  vec3 a{0.0f}, b{0.0f};  // axis end points, bind-pose model space
  float radius = 0.0f;
  BodyPart part = BodyPart::Trunk;
};

struct OccluderSet {
  std::vector<Occluder> capsules;        // at most kMaxOccluders
  std::vector<BodyPart> joint_part;      // per skeleton joint
};
inline constexpr std::size_t kMaxOccluders = 16;

// Empty when the skeleton lacks the H-Anim arm joints (then nothing is shaded this way). Contract:
// mesh skinned to skeleton, at bind pose.
OccluderSet find_occluders(const Skeleton& skeleton, const Mesh& mesh);

}  // namespace gestura
