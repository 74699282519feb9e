#include "gestura/ik/reference_arm.hpp"

#include "gestura/core/error.hpp"

namespace gestura {

Skeleton reference_arm_skeleton() {
  Skeleton s;
  s.add_joint("humanoid_root", -1, vec3(0.0f));
  const int shoulder = s.add_joint("l_shoulder", 0, vec3(0.18f, 1.40f, 0.0f));
  const int elbow = s.add_joint("l_elbow", shoulder, vec3(0.0f, -0.30f, 0.0f));
  const int wrist = s.add_joint("l_wrist", elbow, vec3(0.0f, -0.26f, 0.0f));
  s.add_joint("l_hand_site", wrist, vec3(0.0f, -0.09f, 0.0f));
  s.dofs[shoulder] = JointDofs{RotationOrder::XYZ, 0b111, vec3(deg(-188.0f), deg(-85.0f), deg(-48.0f)),
                               vec3(deg(61.0f), deg(85.0f), deg(134.0f))};
  s.dofs[elbow] = JointDofs{RotationOrder::XYZ, 0b001, vec3(deg(-142.0f), 0.0f, 0.0f), vec3(0.0f)};
  s.dofs[wrist] = JointDofs{RotationOrder::YZX, 0b111, vec3(deg(-90.0f), deg(-77.0f), deg(-27.0f)),
                            vec3(deg(99.0f), deg(113.0f), deg(47.0f))};
  s.validate();
  return s;
}

IkChain arm_chain(const Skeleton& skeleton) {
  const int shoulder = skeleton.find("l_shoulder"), wrist = skeleton.find("l_wrist"),
            site = skeleton.find("l_hand_site");
  if (shoulder < 0 || wrist < 0 || site < 0)
    throw Error("arm chain: skeleton lacks l_shoulder, l_wrist or l_hand_site");
  return make_chain(skeleton, shoulder, wrist, skeleton.rest_translations[site]);
}

Pose arm_ready_pose(const Skeleton& skeleton) {
  Pose pose = rest_pose(skeleton);
  const int shoulder = skeleton.find("l_shoulder"), elbow = skeleton.find("l_elbow");
  if (shoulder < 0 || elbow < 0) throw Error("arm ready pose: skeleton lacks l_shoulder or l_elbow");
  pose.rotations[shoulder] = joint_rotation(skeleton, shoulder, vec3(deg(-30.0f), 0.0f, deg(20.0f)));
  pose.rotations[elbow] = joint_rotation(skeleton, elbow, vec3(deg(-70.0f), 0.0f, 0.0f));
  return pose;
}

}  // namespace gestura
