#pragma once
// Static geometry from a glTF 2.0 file (.gltf or .glb): every triangle primitive of the default
// scene's node tree, placed by the node transforms, with its material's base colour. What a scene
// uses for furniture modelled elsewhere (alias-movement-through-environments.txt ch. 7: "shapes ...
// developed outside of the program ... then read in"). Skins, morph targets and animation are ignored.
#include <string>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

struct StaticMeshPart {
  std::vector<vec3> positions;   // metres, the file's frame (glTF: +Y up)
  std::vector<vec3> normals;     // from the file, or flat from the triangles when it has none
  std::vector<std::uint32_t> indices;
  vec3 color{0.8f};              // sRGB base colour of the primitive's material (white without one)
  std::string name;              // mesh name, or "mesh N"
};

// Throws gestura::Error naming the file and the glTF object ("meshes[2].primitives[0]: ...") for
// malformed, truncated or hostile files; primitives other than triangles are skipped.
std::vector<StaticMeshPart> read_gltf_static_mesh(const std::string& bytes, const std::string& source);

}  // namespace gestura
