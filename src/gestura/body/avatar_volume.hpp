#pragma once
// The default avatar's body as implicit primitives on its skeleton (realtime-virtual-humans.txt
// §2.2): ellipsoids for the trunk masses, head and feet, tapered capsules for limbs and phalanges,
// a rounded box for the palm, lid balls with the eye openings carved in, a smooth-subtracted oral
// cavity, and a floor plane that flattens the soles. Dressed by material: dark long-sleeve shirt and
// trousers (Cloth), skin on hands, neck and face, a hair cap, lips and the mouth's lining. The
// eyeballs, teeth and tongue are separate rigid parts (face_parts.hpp).
#include <vector>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/implicit_body.hpp"
#include "gestura/body/polygonize.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// `skeleton` must come from build_avatar_skeleton(params). jaw_open_degrees turns the primitives
// riding the jaw joint open about it (positive opens the mouth; the avatar polygonises its surface
// with proportions::kBindJawOpenDegrees).
ImplicitBody build_avatar_volume(const Skeleton& skeleton, const AvatarParams& params, float jaw_open_degrees = 0.0f);

// The nails of the ten digits of an avatar skeleton (build_avatar_skeleton(params)): field() is
// negative on each nail plate (on the back of the last phalanx, from a little over a quarter of
// its length to the tip, two thirds of the digit wide), positive elsewhere; roughly metres.
class NailPlates {
 public:
  NailPlates(const Skeleton& skeleton, const AvatarParams& params);
  float field(const vec3& p) const;

 private:
  struct Plate {
    vec3 joint, tip, dir, across, back;
    float radius;
  };
  std::vector<Plate> plates_;
};

// Where the polygoniser should spend its detail: both hands (fingers need ~3 mm cells; the
// forearm enters each box from above) and the head (lids, lips, nostrils; the neck enters from
// below).
std::vector<DetailBox> avatar_detail_boxes(const Skeleton& skeleton, const AvatarParams& params);

}  // namespace gestura
