#include "gestura/face/jaw_motion.hpp"

#include <string>

#include "gestura/face/face_channels.hpp"

namespace gestura::face {

void write_jaw_from_channel(const Skeleton& skeleton, Clip& clip) {
  const int channel = clip.find_channel(std::string(kJawOpen));
  const int jaw = skeleton.find("temporomandibular");
  if (channel < 0 || jaw < 0) return;
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  const FloatTrack& open = clip.channels[static_cast<std::size_t>(channel)];
  QuatTrack track;
  track.interpolation = Interpolation::Slerp;
  const quat rest = skeleton.rest_rotations[static_cast<std::size_t>(jaw)];
  for (std::size_t k = 0; k < open.size(); ++k)
    track.add(open.times[k], rest * glm::angleAxis(glm::radians(open.values[k] * kJawOpenMaxDegrees), vec3(1, 0, 0)));
  clip.rotations[static_cast<std::size_t>(jaw)] = std::move(track);
}

}  // namespace gestura::face
