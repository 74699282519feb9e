#pragma once
// Reading motion files by extension (any case), one table for every command that takes a motion:
// info, convert, render, view, compress. The go-between is a BvhFile (skeleton, clip, channel
// layout): a BVH keeps its own layout, other formats get make_bvh's.
//
//   .bvh         BVH (--scale, --z-up apply)
//   .glb .gltf   glTF animation: nodes become joints, sampled at 30 frames per second
//   .vrm         a VRM 1.0 avatar's skeleton at rest (one frame), joints renamed to H-Anim
//   .bap         MPEG-4 BAP angles on the default avatar's skeleton
//   .gcl         a compressed clip; its skeleton comes from the BVH it was made from (--skeleton)
#include <string>
#include <string_view>
#include <vector>

#include "gestura/io/bvh.hpp"

namespace gestura::app {

struct MotionReadOptions {
  float scale = 1.0f;    // BVH: multiplies lengths
  bool z_up = false;     // BVH: the file is Z-up facing -Y
  std::string skeleton;  // .gcl: the BVH it was compressed from (read with scale and z_up)
};

struct MotionFile {
  std::string format;  // "BVH", "glTF", "VRM", "BAP", "gcl"
  BvhFile motion;
};

// The extensions read_motion_file reads, ".bap, .bvh, ..." for messages.
std::string motion_file_extensions();
bool is_motion_file(std::string_view path);

// Throws AppError: not_found for a missing file, usage at `field` for an extension it cannot read or
// options that do not apply (naming them), input for malformed files (file:line:col).
MotionFile read_motion_file(const std::string& path, const MotionReadOptions& options, std::string_view field);

}  // namespace gestura::app
