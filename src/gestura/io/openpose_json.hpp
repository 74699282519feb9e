#pragma once
// OpenPose-style 2D keypoint JSON: one document per frame, as OpenPose writes
// "<name>_<12-digit frame>_keypoints.json", with BODY_25 body keypoints and 21 keypoints per hand
// projected through a pinhole camera. Each keypoint is three numbers x, y (pixels, from the
// top-left corner) and confidence; keypoints without joints are 0, 0, 0. Face and 3D arrays are
// written empty.
//
// The reader takes what OpenPose itself writes (any body model: BODY_25, COCO's 18 points,
// MPI's 15; faces of 70 points; 2D triples and 3D quadruples) and what gestura writes.
#include <cstddef>
#include <string>
#include <string_view>
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

// ---- reading ----------------------------------------------------------------------------------

// One person of a frame, the arrays as written: 2D ones hold x, y, confidence per keypoint, 3D
// ones x, y, z, confidence. An array the file leaves out is empty.
struct OpenPosePerson {
  int person_id = -1;
  std::vector<float> pose_2d, face_2d, hand_left_2d, hand_right_2d;
  std::vector<float> pose_3d, face_3d, hand_left_3d, hand_right_3d;
};

struct OpenPoseFrame {
  std::vector<OpenPosePerson> people;
};

struct OpenPoseSequence {
  std::vector<std::string> files;    // one per frame, in frame order
  std::vector<OpenPoseFrame> frames;
};

// Limits that keep hostile files cheap; larger inputs are errors naming the limit.
inline constexpr std::size_t kMaxOpenPoseFileBytes = 16u << 20;
inline constexpr std::size_t kMaxOpenPosePeople = 256;
inline constexpr std::size_t kMaxOpenPoseNumbers = 1u << 16;  // per keypoint array
inline constexpr std::size_t kMaxOpenPoseFrames = 1u << 20;

// Reads one frame document. Throws gestura::Error naming `source` and the place, e.g.
// "x.json: people[1].pose_keypoints_2d: 74 numbers, not whole x, y, confidence triples".
OpenPoseFrame read_openpose_frame(std::string_view json, const std::string& source);

// Reads keypoints from `path`:
//   a directory          every "*_keypoints.json" in it, ordered by the frame number before "_keypoints";
//   an existing file     that one frame;
//   NAME.json otherwise  the sequence gestura writes for NAME.json, NAME_<frame>_keypoints.json beside it.
// The frame numbers must run 0, 1, 2, ... without gaps. Throws gestura::Error naming the file.
OpenPoseSequence load_openpose_json(const std::string& path);

}  // namespace gestura
