#pragma once
// The built-in test motion (`gestura render --test-motion`, the benchmark): the right hand comes up
// into the signing space, waves three times and goes down again over 2 s. For seeing the avatar
// move without a motion file; sign synthesis makes the real motions.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Needs r_shoulder, r_elbow and r_wrist with the avatar's axis convention (avatar_skeleton.hpp);
// throws gestura::Error naming the first one missing.
Clip make_wave_clip(const Skeleton& skeleton);

}  // namespace gestura
