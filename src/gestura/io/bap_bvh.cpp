#include "gestura/io/bap_bvh.hpp"

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"

namespace gestura {

BapFile bvh_to_bap(const BvhFile& bvh, const std::string& name) {
  const Skeleton avatar = build_avatar_skeleton();
  Clip clip;
  clip.name = name;
  clip.resize_joints(avatar.size());
  clip.duration = bvh.clip.duration;
  int matched = 0;
  for (std::size_t j = 0; j < avatar.size(); ++j) {
    const int source = bvh.skeleton.find(avatar.names[j]);
    if (source < 0) continue;
    ++matched;
    const auto s = static_cast<std::size_t>(source);
    clip.rotations[j] = bvh.clip.rotations[s];
    // Only the root moves through space in BAP; its rest offset is the avatar's.
    if (avatar.parents[j] < 0 && !bvh.clip.translations[s].empty()) {
      clip.translations[j] = bvh.clip.translations[s];
      for (vec3& t : clip.translations[j].values) t += avatar.rest_translations[j] - bvh.skeleton.rest_translations[s];
    }
  }
  if (matched == 0)
    throw Error("BVH → BAP: no joint has an H-Anim name of the default avatar (e.g. humanoid_root, l_shoulder)");
  return clip_to_bap(clip, avatar, 1.0f / bvh.frame_time, name);
}

BvhFile bap_to_bvh(const BapFile& bap) {
  const Skeleton avatar = build_avatar_skeleton();
  const Clip clip = bap_to_clip(bap, avatar);
  return make_bvh(avatar, clip, 1.0f / bap.fps);
}

}  // namespace gestura
