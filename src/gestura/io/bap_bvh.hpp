#pragma once
// BVH ↔ MPEG-4 BAP through the default avatar's skeleton, the body every BAP angle refers to.
//
// A BAP value is an Euler angle about one local axis of an H-Anim joint in that joint's rotation
// order (bap.hpp), so angles only mean something on a known skeleton. Both directions use
// build_avatar_skeleton() (H-Anim names, identity rest rotations, the avatar's own orders):
// - bvh_to_bap: each avatar joint takes the local rotation of the BVH joint of the same name
//   (a BVH written by gestura for the avatar — make_bvh — matches joint for joint; MakeHuman files
//   need renaming first); the root's translation is kept relative to its rest offset. BVH joints
//   without an avatar namesake and avatar joints without a BAP are dropped. Frames at the BVH rate.
// - bap_to_bvh: bap_to_clip on the avatar, written with make_bvh (ZXY channels) at the BAP rate.
// Round trip BVH → BAP → BVH on the avatar keeps every mapped joint's rotation to the BAP
// resolution (1e-5 rad per angle) and the root translation to 1e-5 m.
#include <string>

#include "gestura/io/bap.hpp"
#include "gestura/io/bvh.hpp"

namespace gestura {

BapFile bvh_to_bap(const BvhFile& bvh, const std::string& name);
BvhFile bap_to_bvh(const BapFile& bap);

}  // namespace gestura
