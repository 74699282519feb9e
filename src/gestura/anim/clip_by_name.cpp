#include "gestura/anim/clip_by_name.hpp"

namespace gestura {

JointNameMatch match_joints_by_name(const Skeleton& source, const Clip& clip, const Skeleton& target) {
  JointNameMatch match;
  match.target_of.assign(source.size(), -1);
  for (std::size_t j = 0; j < source.size(); ++j) {
    match.target_of[j] = target.find(source.names[j]);
    const bool animated = j < clip.joint_count() && (!clip.rotations[j].empty() || !clip.translations[j].empty() ||
                                                     !clip.scales[j].empty());
    if (match.target_of[j] < 0 && animated) match.unmatched.push_back(source.names[j]);
  }
  return match;
}

Clip clip_for_skeleton(const Skeleton& source, const Clip& clip, const Skeleton& target, const JointNameMatch& match) {
  Clip out;
  out.name = clip.name;
  out.duration = clip.duration;
  out.resize_joints(target.size());
  for (std::size_t s = 0; s < source.size() && s < clip.joint_count(); ++s) {
    const int t = match.target_of[s];
    if (t < 0) continue;
    const auto tu = static_cast<std::size_t>(t);
    out.rotations[tu] = clip.rotations[s];
    out.scales[tu] = clip.scales[s];
    Vec3Track translation = clip.translations[s];
    const vec3 rebase = target.rest_translations[tu] - source.rest_translations[s];
    for (vec3& v : translation.values) v += rebase;
    out.translations[tu] = std::move(translation);
  }
  out.channel_names = clip.channel_names;
  out.channels = clip.channels;
  return out;
}

}  // namespace gestura
