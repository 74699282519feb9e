#pragma once
// The binary ".pose" format of the pose-format toolkit used in sign-language research
// (sign-language-processing/pose), version 0.2, written from its published layout. All numbers
// little-endian; a string is a uint16 byte length followed by UTF-8 bytes.
//
//   header  float32 version (0.2) · uint16 width, height, depth · uint16 component count
//           per component: string name · string point format (e.g. "XYZC": the last letter is the
//             confidence, the others are dimensions) · uint16 point, limb, color counts ·
//             point names (strings) · limbs (uint16 from, to) · colors (uint16 r, g, b)
//   body    float32 fps · uint32 frame count · uint16 people count ·
//           float32 data[frames][people][points][dims] · float32 confidence[frames][people][points]
// Points of all components are concatenated in component order; dims is the longest format
// length minus one. Version 0.1 files (read only) differ in the body: uint16 fps and frame count,
// the frame count being whatever the remaining bytes hold.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/io/holistic_landmarks.hpp"
#include "gestura/io/keypoints.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct PoseComponent {
  std::string name;
  std::string format = "XYZC";
  std::vector<std::string> points;
  std::vector<std::array<std::uint16_t, 2>> limbs;
  std::vector<std::array<std::uint16_t, 3>> colors;
};

struct PoseData {
  float version = 0.2f;
  std::uint16_t width = 0, height = 0, depth = 0;
  std::vector<PoseComponent> components;
  float fps = 30.0f;
  std::uint32_t frames = 0;
  std::uint16_t people = 1;
  std::vector<float> data;        // frames × people × points × dims
  std::vector<float> confidence;  // frames × people × points

  int dims() const;               // longest format length − 1
  std::size_t point_count() const;
};

// Writes version 0.2 (a pose read from a 0.1 file too: `version` is what was read, not what is
// written). Throws gestura::Error naming the part that does not fit the format (a name over 65,535 bytes,
// more than 65,535 points, a limb index past the points, data sizes that disagree, no component).
std::string encode_pose(const PoseData& pose);
void save_pose(const std::string& path, const PoseData& pose);

// Reads versions 0.1 and 0.2. Throws gestura::Error naming `source` and the byte offset for a
// truncated or inconsistent file (a limb past its points, a format without a confidence letter,
// a body whose size disagrees with its header), an unknown version or a file of over 2 GiB of data.
PoseData decode_pose(const std::string& bytes, const std::string& source);
PoseData load_pose(const std::string& path);
// The index of the first point of component `name` in the concatenated points, or -1.
int pose_component_offset(const PoseData& pose, const std::string& name);

enum class PoseLayout : std::uint8_t {
  Skeleton3D,  // one component "GESTURA_SKELETON": every joint, "XYZC", model space in metres (+Y up)
  OpenPose2D,  // "pose_keypoints_2d" (BODY_25), "hand_left_keypoints_2d", "hand_right_keypoints_2d":
               // "XYC" pixels through `camera`; width/height = the camera image
};

PoseData pose_from_clip(const Skeleton& skeleton, const Clip& clip, float fps, PoseLayout layout,
                        const PinholeCamera& camera = {});

// MediaPipe Holistic as pose-format's holistic reader lays it out (what sign.mt and the
// pose-evaluation tools read): components POSE_LANDMARKS (33), FACE_LANDMARKS (468),
// LEFT_HAND_LANDMARKS (21), RIGHT_HAND_LANDMARKS (21), POSE_WORLD_LANDMARKS (33), all "XYZC";
// width/height = the camera's image. X, Y are pixels through `camera` (top-left origin, y down);
// Z is MediaPipe's relative depth — smaller is nearer the camera, in units of the image width —
// about the hips' midpoint for the body, the wrist for a hand, the face points' centre for the
// face. The world landmarks are metres about the hips' midpoint along the camera's right, down and
// forward axes, with x multiplied by the width and y by the height as pose-format stores them.
// Confidence is 1 for a placed point in front of the camera, 0 otherwise. `cameras` holds one
// camera for all frames or one per frame (a camera that moves); throws gestura::Error otherwise.
PoseData holistic_pose(const HolisticTrack& track, std::span<const PinholeCamera> cameras, float fps);

}  // namespace gestura
