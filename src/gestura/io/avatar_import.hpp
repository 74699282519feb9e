#pragma once
// A user's own rigged avatar — a VRM (1.0 or 0.x) or any skinned glTF/GLB — made into an Avatar
// that every command can show and the signing rig can drive.
//
// The skeleton is retargeted onto gestura's H-Anim skeleton:
//   - joints are named from the VRM humanoid bones or, for a plain glTF, by the joint-name tables
//     (skeleton/joint_names: Mixamo, MakeHuman, CMU … spellings);
//   - the rest pose is baked so every rest rotation is the identity (H-Anim's rule, which the joint
//     limits and sign synthesis assume), a VRM 0.x model is turned to face +Z, feet put on y = 0;
//   - the arms, hands and fingers are re-posed from the file's T- or A-pose onto the default
//     avatar's rest directions (arms hanging, palms to the thighs, fingers straight), the mesh
//     skinned into that pose and made the bind pose;
//   - joints the signing rig needs and the file lacks are added: the lumbar, thoracic and neck
//     joints between the ones it has, the clavicles, finger tips at the end of each finger's skin,
//     the crown; a hand without finger bones gets the default hand's finger joints (scaled), which
//     move no skin;
//   - every joint named like one of the default skeleton's takes its degrees of freedom and limits.
// The face is mapped onto gestura's face channels (io/face_channel_map.hpp).
// Notes say, in plain words, what this avatar will not show (no finger bones, no face shapes …).
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/io/vrm.hpp"

namespace gestura {

struct ImportedAvatar {
  Avatar avatar;
  std::vector<std::string> notes;
};

// Throws gestura::Error naming the file and what is wrong: unreadable or malformed files (the
// readers name the place), no skinned mesh, a rig without hips, head, upper arms, forearms or hands.
ImportedAvatar import_avatar(VrmAvatar file, const std::string& source);
ImportedAvatar load_file_avatar(const std::string& path);

// True for a spec that names an avatar file: ends in .vrm, .glb or .gltf (any case).
bool is_avatar_file(const std::string& spec);

}  // namespace gestura
