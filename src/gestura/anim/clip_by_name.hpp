#pragma once
// Moving a clip onto another skeleton whose joints carry the same names: the same rig at another
// size (a BVH written from the avatar, then played on a taller one) or a part of it (an arm-only
// IK demo). No retargeting: rotations are full local rotations and are copied as they are, which
// is right when both rigs have identity rest rotations with parallel joint frames (H-Anim's rule,
// BVH's convention). Translations keep the target's proportions: a key becomes the target's rest
// offset plus the key's offset from the source's rest, so root motion carries over and bones keep
// their target length.
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct JointNameMatch {
  std::vector<int> target_of;          // per source joint: the target joint of that name, or -1
  std::vector<std::string> unmatched;  // animated source joints (non-empty tracks) with no namesake
};

// Contract: clip.joint_count() == source.size().
JointNameMatch match_joints_by_name(const Skeleton& source, const Clip& clip, const Skeleton& target);

// The clip re-indexed for `target`: tracks of matched joints moved over (translations re-based as
// above), unmatched joints' tracks dropped, target joints without a source keep their rest; scalar
// channels copied. Contract: `match` comes from match_joints_by_name for the same arguments.
Clip clip_for_skeleton(const Skeleton& source, const Clip& clip, const Skeleton& target, const JointNameMatch& match);

}  // namespace gestura
