#include "gestura/sign/phonology_joint_rotation.hpp"

namespace gestura {

FingerJointRotations finger_joint_rotations(const HandPosture& posture, Finger finger, Hand hand) {
  const FingerFlexion& flexion = posture.finger(finger);
  const float spread = posture.spread[static_cast<std::size_t>(finger) - 1];
  // A positive turn about +Z moves +Y toward −X. The radial side is +X for the right hand.
  const float toward_radial = finger == Finger::Index ? spread : -spread;
  const float about_z = hand == Hand::Right ? -toward_radial : toward_radial;
  const vec3 x{1.0f, 0.0f, 0.0f}, z{0.0f, 0.0f, 1.0f};
  FingerJointRotations out;
  out.mcp = glm::angleAxis(about_z, z) * glm::angleAxis(flexion.mcp, x);
  out.pip = glm::angleAxis(flexion.pip, x);
  out.dip = glm::angleAxis(flexion.dip, x);
  return out;
}

}  // namespace gestura
