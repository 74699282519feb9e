#pragma once
// OpenPose-style 2D keypoint JSON: one document per frame, as OpenPose writes
// "<name>_<12-digit frame>_keypoints.json", with BODY_25 body keypoints and 21 keypoints per hand
// projected through a pinhole camera. Each keypoint is three numbers x, y (pixels, from the
// top-left corner) and confidence; keypoints without joints are 0, 0, 0. Face and 3D arrays are
// written empty.
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/io/keypoints.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// One JSON text per sampled frame (every 1/fps seconds over the clip).
std::vector<std::string> openpose_json_frames(const Skeleton& skeleton, const Clip& clip, float fps,
                                              const PinholeCamera& camera = {});

// Writes "<stem>_<frame:012>_keypoints.json" beside `path` (whose extension is dropped); returns
// the paths written. Throws gestura::Error when a file cannot be written.
std::vector<std::string> save_openpose_json(const std::string& path, const Skeleton& skeleton, const Clip& clip,
                                            float fps, const PinholeCamera& camera = {});

}  // namespace gestura
