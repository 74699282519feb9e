#include "gestura/ik/reference_arm.hpp"

#include <string>

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

IkChain arm_chain(const Skeleton& skeleton, std::string_view side, std::string_view effector) {
  const std::string prefix = std::string(side) + "_";
  auto need = [&](const std::string& name) {
    const int j = skeleton.find(name);
    if (j < 0) throw Error("arm chain: skeleton has no joint '" + name + "'");
    return j;
  };
  const int shoulder = need(prefix + "shoulder"), wrist = need(prefix + "wrist");
  std::string site(effector);
  if (site.empty()) site = skeleton.find(prefix + "hand_site") >= 0 ? prefix + "hand_site" : prefix + "middle1";
  const int tip = need(site);
  // The effector's rest position in the wrist's frame, through whatever joints lie between.
  const Pose rest = rest_pose(skeleton);
  const mat4 wrist_model = parent_model_matrix(skeleton, rest, wrist) * Transform{rest.translations[wrist], rest.rotations[wrist], rest.scales[wrist]}.matrix();
  const mat4 tip_model = parent_model_matrix(skeleton, rest, tip) * Transform{rest.translations[tip], rest.rotations[tip], rest.scales[tip]}.matrix();
  const vec3 offset = vec3(glm::inverse(wrist_model) * tip_model[3]);
  IkChain chain = make_chain(skeleton, shoulder, wrist, offset);
  bool below_wrist = false;
  for (int j = tip; j >= 0; j = skeleton.parents[j]) below_wrist = below_wrist || j == wrist;
  if (!below_wrist) throw Error("arm chain: '" + site + "' is not below '" + prefix + "wrist'");
  return chain;
}

Pose arm_ready_pose(const Skeleton& skeleton, std::string_view side) {
  Pose pose = rest_pose(skeleton);
  const std::string prefix = std::string(side) + "_";
  const int shoulder = skeleton.find(prefix + "shoulder"), elbow = skeleton.find(prefix + "elbow");
  if (shoulder < 0 || elbow < 0) throw Error("arm ready pose: skeleton lacks " + prefix + "shoulder or " + prefix + "elbow");
  const float mirror = side == "r" ? -1.0f : 1.0f;
  pose.rotations[shoulder] = joint_rotation(skeleton, shoulder, vec3(deg(-30.0f), 0.0f, mirror * deg(20.0f)));
  pose.rotations[elbow] = joint_rotation(skeleton, elbow, vec3(deg(-70.0f), 0.0f, 0.0f));
  return pose;
}

}  // namespace gestura
