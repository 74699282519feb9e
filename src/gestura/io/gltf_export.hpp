#pragma once
// Binary glTF 2.0 (GLB) export of a skinned, morphable mesh and its skeleton.
//
// Layout: every joint is a node (named as in the skeleton, rest translation/rotation/scale,
// children by the parent array); one extra node holds the mesh and the skin. The skin lists the
// joint nodes in skeleton order with inverse bind matrices of the rest pose. The mesh has one
// primitive per material in use (all sharing the vertex attributes POSITION, NORMAL, JOINTS_0,
// WEIGHTS_0) so viewers colour skin, cloth, hair, eyes and lips apart; morph targets are sparse
// POSITION (and NORMAL, when present) accessors, named in mesh.extras.targetNames.
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Display name and sRGB-ish base colour of each MaterialId (index = id).
struct MaterialLook {
  const char* name;
  vec4 base_colour;
  float roughness;
};
const MaterialLook& material_look(MaterialId id);

// Throws gestura::Error when the mesh is inconsistent (array sizes, indices out of range, joint
// indices beyond the skeleton, non-finite values).
std::vector<std::uint8_t> encode_glb(const Skeleton& skeleton, const Mesh& mesh, const std::string& name = "gestura");
// Writes encode_glb() to `path`; throws gestura::Error naming the path when it cannot be written.
void write_glb(const std::string& path, const Skeleton& skeleton, const Mesh& mesh, const std::string& name = "gestura");

}  // namespace gestura
