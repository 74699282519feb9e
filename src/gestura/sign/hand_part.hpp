#pragma once
// The part of the hand HamNoSys names for a contact — "the index fingertip touches the chin",
// "the palm on the chest" — as a point on the posed hand.
//
// Finger parts (tip, pad, nail, middle joint, base, side) are found on the finger's own joints,
// so a bent finger's pad faces where the bent finger's pad really is; with no finger named they
// are taken on the fingers the handshape extends (the index alone when it curls them all). Hand
// parts (palm, back, thumb and little-finger sides, ball of the thumb, both sides of the wrist)
// are found on the palm.
#include <optional>

#include "gestura/sign/hamnosys_model.hpp"
#include "gestura/sign/signing_rig.hpp"

namespace gestura {

// The part's point on the hand's surface and the direction the surface faces there, in the
// wrist's frame. `pose` holds the hand's finger rotations (apply_hand_posture); `shape` is the same posture, for
// which fingers are extended. Empty for a site that is not on the hand (a body or arm site).
std::optional<SurfacePoint> hand_part_site(const SigningRig& rig, Hand hand, const Pose& pose, const HandPosture& shape,
                                           const sign::SitePoint& part);

}  // namespace gestura
