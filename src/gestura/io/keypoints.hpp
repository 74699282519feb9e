#pragma once
// Keypoints for pose-estimation formats (OpenPose BODY_25 and its 21-point hands), computed from
// the joints of any H-Anim-named skeleton, and the pinhole camera that turns them into pixels.
//
// A keypoint is a joint position, the midpoint of two joints, or a point fixed to a joint (an
// offset given in model space at rest that turns with the joint): the nose, ears, toes and heels
// are not joints. Joint names are found with guess_hanim_names, so any rig the name tables know
// works; a keypoint whose joints are missing gets confidence 0.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Model-space joint positions of `clip` sampled every 1/fps seconds over [0, duration]:
// frames × skeleton.size(), row-major. Throws gestura::Error for fps <= 0 or > 1000.
std::vector<vec3> sample_joint_positions(const Skeleton& skeleton, const Clip& clip, float fps, int* frame_count);

inline constexpr int kBody25Count = 25;
inline constexpr int kHandKeypointCount = 21;
extern const std::array<const char*, kBody25Count> kBody25Names;       // "Nose", "Neck", "RShoulder", ...
extern const std::array<const char*, kHandKeypointCount> kHandNames;   // "WRIST", "THUMB_CMC", ...

enum class KeypointSet : std::uint8_t { Body25, LeftHand, RightHand };

// Keypoints of one set for every sampled frame: frames × count positions (model space) and
// confidences (1 when the joints exist, 0 otherwise).
struct Keypoints {
  int frames = 0;
  int count = 0;
  std::vector<vec3> positions;
  std::vector<float> confidence;
};
Keypoints compute_keypoints(const Skeleton& skeleton, const Clip& clip, float fps, KeypointSet set);

// Limbs (pairs of keypoint indices) of each set, for drawing and for the .pose header.
std::span<const std::array<std::uint16_t, 2>> keypoint_limbs(KeypointSet set);

// A pinhole camera looking at `target` from `position`, +Y up; pixels from the top-left corner,
// x to the right, y down. The default frames a standing avatar from the front (it faces +Z).
struct PinholeCamera {
  vec3 position{0.0f, 1.0f, 3.2f};
  vec3 target{0.0f, 1.0f, 0.0f};
  float vertical_fov = deg(35.0f);
  int width = 1280, height = 720;

  // Pixel coordinates and depth along the view direction (negative = behind the camera).
  vec3 project(const vec3& point) const;
};

}  // namespace gestura
