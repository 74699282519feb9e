#pragma once
// Where an avatar comes from, by a short spec the command line can carry:
//
//   "default"         the generated virtual human (build_avatar with `params`)
//   "ana", "ben", …   a built-in look of it (avatar_look.hpp); `params` that differ from the
//                     defaults change the look
//   "makehuman:DIR"   the MakeHuman base mesh and default rig in DIR (base.obj, rigs/default.mhskel,
//                     rigs/default_weights.mhw), standing on y = 0 and facing +Z like the default
//   "FILE.vrm", "FILE.glb", "FILE.gltf"
//                     a user's rigged avatar: VRM 1.0 / 0.x or a skinned glTF (io/avatar_import.hpp)
//
// All give the H-Anim joints the signing rig needs, so every downstream command works on any.
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"

namespace gestura {

// Throws gestura::Error for an unknown spec, a missing directory or malformed asset files (the
// readers name file and line). An avatar file's notes (what it will not show: no finger bones, no
// face shapes …) go to `notes`, or without it to stderr as "note: …" lines.
Avatar load_avatar(const std::string& spec, const AvatarParams& params = {}, std::vector<std::string>* notes = nullptr);

// The MakeHuman body as an Avatar: body and eyeball geometry only (the helper tights, skirt, hair,
// teeth and joint cubes dropped), feet on y = 0, all skin except the eyes (white, iris, pupil).
// The A-pose is re-posed so the arms hang like the default avatar's (mesh re-skinned into that
// bind pose), joints named like the default skeleton's take its degrees of freedom and limits, and
// the joints MakeHuman lacks are added (vt1, skull_tip). params.height is the measured height.
Avatar load_makehuman_avatar(const std::string& directory);

}  // namespace gestura
