#pragma once
// VRM 1.0 avatars (a .glb with the VRMC_vrm extension) imported as our Skeleton + Mesh.
//
// - Skeleton: every glTF node without a mesh, parents first (read_gltf_animation's rules). Joints
//   named by VRMC_vrm.humanoid.humanBones are renamed to H-Anim (hips → humanoid_root,
//   leftUpperArm → l_shoulder, ... via the joint-name table); other joints keep their node names.
// - Mesh: all triangle primitives of all mesh nodes merged. Skinned vertices are moved into the
//   skeleton's rest model space (v = Σ wᵢ · Restᵢ · IBMᵢ · v_file, so files whose inverse bind
//   matrices are not exactly the inverse rest pose still line up); unskinned mesh nodes are placed
//   by their rest transform and bound to their nearest joint ancestor. Morph targets become sparse
//   MorphTargets named from extras.targetNames (else "<mesh>_<index>"); targets with the same
//   index in the primitives of one mesh are one morph.
// - Expressions: VRMC_vrm.expressions (preset and custom) become our face channel names (visemes
//   aa E ih oh ou, expressions joy anger sadness surprise relaxed neutral, eyeBlink_L/_R, blink,
//   lookUp/Down/Left/Right; custom names unchanged) with their morph target binds.
// VRM 0.x (extension "VRM") is refused with an Error saying so. Every index is range-checked.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct VrmMorphBind {
  int morph = 0;        // index into VrmAvatar::mesh.morphs
  float weight = 1.0f;  // morph weight at full expression
};

struct VrmAvatar {
  Skeleton skeleton;
  Mesh mesh;
  std::vector<mat4> inverse_binds;  // per joint: the file's skin matrix, or the inverse rest pose
  std::map<std::string, std::string> humanoid;                      // VRM bone name → our joint name
  std::map<std::string, std::vector<VrmMorphBind>> face_channels;   // our face channel → binds
};

// Our face channel for a VRM 1.0 expression preset ("ee" → "E", "happy" → "joy",
// "blinkLeft" → "eyeBlink_L"); "" for a name that is not a preset.
std::string_view face_channel_for_vrm_preset(std::string_view preset);

VrmAvatar read_vrm(const std::string& bytes, const std::string& source);
VrmAvatar load_vrm(const std::string& path);

}  // namespace gestura
