#pragma once
// From a HandPosture's anatomical angles to joint rotations, for the four fingers, expressed in
// the hand-local frame of HandFrame (+Y along the straight finger, +Z out of the palm, +X = Y × Z).
// A skeleton whose finger joints are not aligned with that frame at rest conjugates these by its
// own rest offsets.
//
// Flexion turns the finger from +Y toward the palm side (+Z): a positive turn about local +X, for
// either hand. Spread turns about local +Z: the index toward the thumb (local +X for the right
// hand, −X for the left), the other fingers away from it. The MCP applies spread first, then
// flexion about the spread finger's own lateral axis; PIP and DIP are pure flexion.
// The thumb is not covered: its CMC axes are oblique to the palm and depend on the skeleton.
#include "gestura/core/math.hpp"
#include "gestura/sign/phonology_direction.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

struct FingerJointRotations {
  quat mcp{1.0f, 0.0f, 0.0f, 0.0f};
  quat pip{1.0f, 0.0f, 0.0f, 0.0f};
  quat dip{1.0f, 0.0f, 0.0f, 0.0f};
};

// `finger` is Index..Pinky; Finger::Thumb throws std::out_of_range.
FingerJointRotations finger_joint_rotations(const HandPosture& posture, Finger finger, Hand hand);

}  // namespace gestura
