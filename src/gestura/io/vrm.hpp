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
// VRM 0.x (extension "VRM") is read too: humanoid.humanBones as a list, the thumb's
// Proximal/Intermediate/Distal taken as 1.0's Metacarpal/Proximal/Distal, blendShapeMaster groups
// as expressions (presets a i u e o joy angry sorrow fun blink blink_l blink_r look*; weights
// 0..100 scaled to 0..1); such a model faces -Z (faces_minus_z). Every index is range-checked.
// read_rigged_gltf() reads a plain skinned glTF/GLB too: joints named by guess_hanim_names.
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
  std::string kind = "VRM 1.0";     // "VRM 1.0", "VRM 0.x" or "glTF"
  bool faces_minus_z = false;       // VRM 0.x models look down -Z
};

// Our face channel for a VRM 1.0 expression preset ("ee" → "E", "happy" → "joy",
// "blinkLeft" → "eyeBlink_L"); "" for a name that is not a preset.
std::string_view face_channel_for_vrm_preset(std::string_view preset);

// Throws gestura::Error (naming the place) for a file without a VRM extension.
VrmAvatar read_vrm(const std::string& bytes, const std::string& source);
VrmAvatar load_vrm(const std::string& path);
// A VRM (0.x or 1.0) or any skinned glTF/GLB.
VrmAvatar read_rigged_gltf(const std::string& bytes, const std::string& source);
VrmAvatar load_rigged_gltf(const std::string& path);

}  // namespace gestura
