#include "gestura/anim/change_basis.hpp"

namespace gestura {

void change_basis(Skeleton& skeleton, Clip& clip, const quat& basis) {
  const quat inverse = glm::conjugate(basis);
  for (vec3& t : skeleton.rest_translations) t = basis * t;
  for (quat& r : skeleton.rest_rotations) r = basis * r * inverse;
  for (Vec3Track& track : clip.translations)
    for (vec3& v : track.values) v = basis * v;
  for (QuatTrack& track : clip.rotations) {
    for (quat& q : track.values) q = basis * q * inverse;
    make_continuous(track);
  }
}

}  // namespace gestura
