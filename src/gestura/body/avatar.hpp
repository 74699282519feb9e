#pragma once
// The default virtual human, generated entirely by code: skeleton, one seamless skinned skin with
// clothing/skin/hair/lip/mouth materials, the face's rigid parts inside it (eyeballs, teeth, tongue:
// face_parts.hpp) in the same mesh, and facial morph targets.
//
//   Avatar a = build_avatar();                       // defaults: 1.70 m, neutral
//   a.mesh.vertex_count(), a.skeleton.find("l_wrist"), a.mesh.find_morph("aa") …
#include "gestura/body/avatar_params.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/body/skin_weights.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct AvatarOptions {
  SkinWeightMethod weights = SkinWeightMethod::FieldDiffused;
  float cell = 0.016f;  // coarse polygonisation cell at 1.70 m (metres); hands get 5×, the head 3× finer cells
};

struct Avatar {
  AvatarParams params;
  Skeleton skeleton;
  Mesh mesh;
};

// Throws gestura::Error for invalid params or options. Deterministic.
Avatar build_avatar(const AvatarParams& params = {}, const AvatarOptions& options = {});

}  // namespace gestura
