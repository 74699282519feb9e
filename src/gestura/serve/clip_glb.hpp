#pragma once
// The animation of one utterance for a web player that already holds the avatar (GET
// /api/avatar.glb): binary glTF with the skeleton's nodes and one animation, no body. The face's
// morph weights drive a one-triangle stand-in mesh whose targets carry the avatar's morph names
// in the avatar's order (mesh.extras.targetNames), so a player moves the avatar's own targets by
// index. `extras` (any JSON object: glosses, timeline) is stored in the animation's extras.
#include <string>

#include <nlohmann/json.hpp>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::serve {

// Contract: clip valid for skeleton; avatar_mesh is the avatar's (only its morph names are read).
std::string clip_glb(const Skeleton& skeleton, const Clip& clip, const Mesh& avatar_mesh, const nlohmann::json& extras);

}  // namespace gestura::serve
