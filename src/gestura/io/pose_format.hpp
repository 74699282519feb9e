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
// length minus one.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
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

// Throws gestura::Error naming the part that does not fit the format (a name over 65,535 bytes,
// more than 65,535 points, a limb index past the points, data sizes that disagree, no component).
std::string encode_pose(const PoseData& pose);
void save_pose(const std::string& path, const PoseData& pose);

enum class PoseLayout : std::uint8_t {
  Skeleton3D,  // one component "GESTURA_SKELETON": every joint, "XYZC", model space in metres (+Y up)
  OpenPose2D,  // "pose_keypoints_2d" (BODY_25), "hand_left_keypoints_2d", "hand_right_keypoints_2d":
               // "XYC" pixels through `camera`; width/height = the camera image
};

PoseData pose_from_clip(const Skeleton& skeleton, const Clip& clip, float fps, PoseLayout layout,
                        const PinholeCamera& camera = {});

}  // namespace gestura
