#pragma once
// Joint positions over time as JSON, for analysis and comparison with pose-estimation data:
//   {"fps": 30, "joints": [names], "frames": [[[x, y, z], …], …]}
// Metres, +Y up, the avatar facing +Z, H-Anim 1.1 names (fingertip sites included as joints).
#include <string>

#include "gestura/anim/clip.hpp"

namespace gestura {

std::string joint_positions_json(const Skeleton& skeleton, const Clip& clip, float fps);
// Writes through a temporary file renamed on success; throws gestura::Error naming the path.
void write_joint_positions_json(const std::string& path, const Skeleton& skeleton, const Clip& clip, float fps);

}  // namespace gestura
