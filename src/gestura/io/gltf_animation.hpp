#pragma once
// glTF 2.0 animation files: any skeleton and clip as a node hierarchy with one animation, written as
// .glb (binary) or .gltf (JSON with the buffer embedded as a data URI), and read back.
//
// Writing
// - One node per joint (name, rest translation / rotation / scale), parents before children; the
//   roots form the scene. With a mesh, a skin over all joints (inverse bind matrices from the
//   rest pose) and a skinned triangle primitive with POSITION, NORMAL, JOINTS_0, WEIGHTS_0 and
//   morph targets (dense POSITION / NORMAL deltas), their names in mesh.extras.targetNames.
// - One animation: per joint and component a channel. Step tracks become STEP samplers; linear,
//   slerp and nlerp tracks become LINEAR with their own keys (glTF rotations interpolate by slerp;
//   nlerp differs by < 0.1° between close keys); spline tracks (Catmull-Rom, cardinal, TCB, squad)
//   are resampled at `resample_fps` and written LINEAR. Scalar channels whose names equal morph
//   target names drive the mesh's "weights" (sampled at the union of their key times).
//   CUBICSPLINE is not written.
//
// Reading (for round trips and for importing animation): joints are all nodes without a mesh, in
// depth-first order from the scene roots; channels targeting them become tracks (LINEAR rotation →
// Slerp, LINEAR → Linear, STEP → Step, CUBICSPLINE → the key values, Catmull-Rom between them);
// "weights" channels become scalar channels named after mesh.extras.targetNames. Every index,
// accessor and buffer range is checked before use; malformed input throws gestura::Error naming
// the object ("accessors[3]: ...").
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/io/gltf_reader.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct GltfWriteOptions {
  float resample_fps = 30.0f;  // for spline tracks; > 0
};

// The glTF JSON document and its binary buffer, before packing into .glb or .gltf.
struct GltfDocument {
  std::string json;
  std::vector<std::uint8_t> buffer;
};

// Contract: clip valid for skeleton; mesh (optional) skinned to the skeleton's joints.
GltfDocument make_gltf(const Skeleton& skeleton, const Clip& clip, const Mesh* mesh = nullptr,
                       const GltfWriteOptions& options = {});
std::string pack_glb(const GltfDocument& document);
std::string pack_gltf_embedded(const GltfDocument& document);
// Chooses .glb / .gltf by the extension of `path`.
void save_gltf(const std::string& path, const Skeleton& skeleton, const Clip& clip, const Mesh* mesh = nullptr,
               const GltfWriteOptions& options = {});

struct GltfAnimation {
  Skeleton skeleton;
  Clip clip;
  std::vector<int> node_of_joint;  // glTF node index per joint
};

// `bytes` is a .glb or a .gltf JSON text with its buffers as data URIs (external files are not
// read). `source` names it in errors.
GltfAnimation read_gltf_animation(const std::string& bytes, const std::string& source);
GltfAnimation load_gltf_animation(const std::string& path);

}  // namespace gestura
