#pragma once
// Writing a motion made by a command (sign, reach, retarget) to the file -o names, chosen by its
// extension: .json joint positions, .bvh motion, .glb/.gltf animation (with the body when there is
// one), or .png/.gif/.mp4/.webm pictures of the body performing it. The flags that shape pictures
// (--size, --fps, --camera, --sheet) are read here so every such command takes the same ones.
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::cli {

struct MotionOutput {
  std::string path;
  std::string size = "1280x720", camera = "front";
  int fps = 30;
  bool sheet = false;  // .png only: 16 frames in a 4x4 grid
  // Frame spacing of .json/.bvh; 0 means 1/fps. Retargeting keeps the source's own rate this way.
  float motion_frame_time = 0.0f;
};

constexpr const char* kMotionOutputUsage =
    "OUT by extension: .json joint positions ({\"fps\", \"joints\", \"frames\"}; metres, +Y up, facing +Z,\n"
    "H-Anim names), .bvh motion, .glb/.gltf animation with the avatar's body, .pose MediaPipe Holistic\n"
    "landmarks (pose-format; pixels as the pictures of the same --size/--camera show them), or pictures of the avatar:\n"
    ".png (one moment; --sheet: 16 frames in a 4x4 grid), .gif, .mp4, .webm\n"
    "(--size WxH [1280x720], --fps N [30], --camera LIST [front]).";

// When args[i] is -o/--output, --size, --fps, --camera or --sheet, reads it into `out` (advancing i)
// and returns true. A bad --fps throws gestura::Error.
bool parse_motion_output_flag(const std::vector<std::string>& args, std::size_t& i, MotionOutput& out);

// True when writing `out` needs the body (a mesh skinned to the clip's skeleton).
bool output_shows_body(const MotionOutput& out);

// Checks before any work is done: an extension this writes and, for pictures, valid picture options.
// Throws gestura::Error naming the file and the extensions it accepts.
void check_motion_output(const MotionOutput& out);

// Contract: clip valid for skeleton; body (may be null unless output_shows_body for pictures) skinned
// to the skeleton. still_time: the moment a single .png shows. Returns the frames written.
int write_motion(const MotionOutput& out, const Skeleton& skeleton, const Clip& clip, const Mesh* body,
                 float still_time);

}  // namespace gestura::cli
