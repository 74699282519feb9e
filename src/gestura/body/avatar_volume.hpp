#pragma once
// The default avatar's body as implicit primitives on its skeleton (realtime-virtual-humans.txt
// §2.2): ellipsoids for the trunk masses, head and feet, tapered capsules for limbs and phalanges,
// a rounded box for the palm, smooth-subtracted eye sockets and mouth, and a floor plane that flattens
// the soles. Dressed by material: dark long-sleeve shirt and trousers (Cloth), skin on hands, neck
// and face, a hair cap, eyes, lips, teeth and tongue.
#include <vector>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/implicit_body.hpp"
#include "gestura/body/polygonize.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// `skeleton` must come from build_avatar_skeleton(params).
ImplicitBody build_avatar_volume(const Skeleton& skeleton, const AvatarParams& params);

// Where the polygoniser should spend its detail: both hands (fingers need ~3 mm cells; the
// forearm enters each box from above) and the head (lids, lips, nostrils; the neck enters from
// below).
std::vector<DetailBox> avatar_detail_boxes(const Skeleton& skeleton, const AvatarParams& params);

}  // namespace gestura
