#pragma once
// MPEG-4 Body Animation Parameters (BAP) as text files, and their H-Anim 1.1 joints.
//
// File (one record per line, fields separated by blanks):
//   header   version name fps frame_count           e.g. "2.1 hello 30 120"
//   per frame, two lines:
//     mask   one 0/1 flag per BAP (186, or 296 with the version-2 extension BAPs)
//     values the frame number, then one integer per BAP whose flag is 1, in BAP order
// A BAP whose flag is 0 keeps its value from the previous frame (0 before the first).
// Units: rotation BAPs in 1e-5 rad; the three HumanoidRoot translation BAPs in 1e-5 m here (MPEG-4
// leaves their scale to the body definition; this reader fixes it so files round-trip exactly).
//
// Joint mapping (bap_table): every BAP 1..186 names an H-Anim joint and one local axis — x for
// flexion / tilt / pivot of the wrist and fingers1, y for twisting / torsion / turn, z for abduction /
// roll — after the MPEG-4 BAP list (sacroiliac, legs, shoulder girdle, arms, skullbase, vertebrae
// vc1..vl5, fingers pinky..index, thumb, HumanoidRoot). The angle is the joint's Euler angle about that
// axis in the skeleton's own rotation order and sign convention. The extension BAPs 187..296 are
// read and written but not mapped to joints.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr int kBapBodyCount = 186;      // BAPs 1..186
inline constexpr int kBapExtendedCount = 296;  // with the version-2 extension BAPs
inline constexpr double kBapAngleUnit = 1e-5;  // radians per unit
inline constexpr double kBapLengthUnit = 1e-5; // metres per unit (HumanoidRoot translations)

struct BapInfo {
  std::string name;    // e.g. "l_shoulder_flexion"
  std::string joint;   // H-Anim joint name, e.g. "l_shoulder" ("humanoid_root" for HumanoidRoot)
  int axis = 0;        // 0 x, 1 y, 2 z
  bool translation = false;
};

// BAPs 1..186 in order (index 0 is BAP 1).
const std::vector<BapInfo>& bap_table();
int find_bap(std::string_view name);  // 1-based BAP number, 0 when unknown

struct BapFile {
  std::string version = "2.1";
  std::string name = "gestura";
  float fps = 30.0f;
  int parameter_count = kBapBodyCount;       // 186 or 296 flags per mask line
  std::vector<std::int32_t> values;          // frames × parameter_count, masked-out values carried
  std::vector<std::uint8_t> mask;            // frames × parameter_count, as read (1 = sent)

  int frame_count() const { return parameter_count ? static_cast<int>(values.size()) / parameter_count : 0; }
};

inline constexpr int kBapMaxFrames = 1'000'000;

// Throws gestura::Error "source:line:col: ..." on malformed input: bad header, mask of the wrong
// length or with other than 0/1, wrong frame number, value count not matching the mask, values that
// are not integers or out of 32-bit range, fewer or more frames than the header says.
BapFile read_bap(std::string_view text, const std::string& source);
BapFile load_bap(const std::string& path);
// Writes every BAP that is nonzero in any frame, each frame (a sparse but lossless mask).
std::string write_bap(const BapFile& file);
void save_bap(const std::string& path, const BapFile& file);

// BAP frames → clip on `skeleton`: joints named in the table get rotation tracks (Euler angles in the
// joint's order), HumanoidRoot translations offset the root's rest translation. Joints the skeleton
// lacks are skipped; BAPs of joints that lack the axis as a free DoF are applied all the same.
Clip bap_to_clip(const BapFile& file, const Skeleton& skeleton);
// Clip → BAP frames at `fps`: each mapped joint's Euler angles (relative to rest, in its order)
// rounded to 1e-5 rad.
BapFile clip_to_bap(const Clip& clip, const Skeleton& skeleton, float fps, const std::string& name);

}  // namespace gestura
