#pragma once
// The parts of the default face that are not skin: two eyeballs, the upper and lower rows of teeth
// and the tongue. Each is its own small closed surface lying inside the skin — the eyeballs under
// the lids, the rest in the oral cavity — and rides one joint rigidly: the eyeballs their eye joints
// (so gaze turns them), the upper teeth the skull, the lower teeth and the tongue the jaw.
//
// Built directly as triangle meshes rather than polygonised: they need finer and more regular
// detail than the skin's lattice gives (the iris and pupil are rings of latitude around the gaze
// axis, the teeth a swept profile along the dental arch) for a few hundred triangles each.
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Eyeballs, teeth and tongue for an avatar skeleton (build_avatar_skeleton) of height scale × 1.70 m,
// with normals, materials and rigid skin weights; no morphs. Throws gestura::Error when the
// skeleton lacks the eye, skull or jaw joints.
Mesh build_face_parts(const Skeleton& skeleton, float scale);

// Appends `part` to `mesh`: vertices, per-vertex arrays and (shifted) indices. Both must have the
// per-vertex arrays filled and no morph targets yet.
void append_mesh(Mesh& mesh, const Mesh& part);

}  // namespace gestura
