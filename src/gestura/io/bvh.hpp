#pragma once
// Biovision Hierarchy (BVH) motion files: reading into a Skeleton + Clip and writing them back.
//
// Meaning of the file, as read here:
// - Joints are listed depth-first, so the BVH order is a valid Skeleton order (parents first).
//   Every "End Site" becomes a leaf joint named "<parent>_end" with no channels, flagged in
//   `end_site`, so that FK gives fingertip / head-top positions and export writes it back.
// - A joint's local transform is T(offset + position channels) · R(rotation channels); rest
//   rotations are identity. Rotation channels are Euler angles in degrees read left to right as
//   outermost first: "Zrotation Xrotation Yrotation" is R = Rz·Rx·Ry = RotationOrder::ZXY.
// - Frame k is at time k · frame_time. Rotation tracks use slerp, translation tracks lerp; a joint
//   without rotation (position) channels has an empty rotation (translation) track.
// - Units and axes are the file's unless BvhReadOptions say otherwise: BVH names neither its unit
//   nor its up axis. The MakeHuman files are decimetres and Z-up ({0.1f, true} gives our metres,
//   +Y up); after an axis change the same channel layout is written in the new axes.
//
// Writing samples the clip at every frame time and turns rotations back into Euler angles with
// the previous frame as hint, so angle sequences do not flip; values are printed with the shortest
// decimal form that reads back to the same float.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

enum class BvhChannel : std::uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

std::string_view to_string(BvhChannel channel);
inline bool is_position(BvhChannel c) { return c <= BvhChannel::Zposition; }
inline int axis_of(BvhChannel c) { return static_cast<int>(c) % 3; }

// The channels of one joint in file order (0 to 6, each at most once).
struct BvhChannels {
  std::uint8_t count = 0;
  std::array<BvhChannel, 6> order{};

  BvhChannel operator[](int i) const { return order[static_cast<std::size_t>(i)]; }
  void push(BvhChannel c) { order[count++] = c; }
  bool has_rotation() const;
  bool has_position() const;
  // Rotation order implied by the rotation channels; axes without a channel (always angle 0) are
  // put innermost, so any subset of rotation channels maps to one of the six orders.
  RotationOrder rotation_order() const;
};

struct BvhFile {
  Skeleton skeleton;                   // joints in file order, end sites included
  std::vector<std::uint8_t> end_site;  // per joint: 1 for an End Site leaf
  std::vector<BvhChannels> channels;   // per joint, the file's channel layout
  float frame_time = 1.0f / 30.0f;     // seconds
  int frame_count = 0;
  Clip clip;                           // tracks per skeleton joint; duration = (frames − 1) · frame_time

  int channel_count() const;           // values per motion line
  int root() const;                    // index of the ROOT joint (0 when read from a file)
};

struct BvhReadOptions {
  float scale = 1.0f;  // multiplies offsets and position channels (e.g. 0.1 for dm → m); 1e-6..1e6
  bool z_up = false;   // the file is Z-up facing −Y (MakeHuman, Blender): turn it to +Y up facing +Z
};

// Limits that keep hostile files from exhausting memory; larger input is rejected with an Error.
inline constexpr int kBvhMaxJoints = 32767;        // Skeleton parents are int16
inline constexpr long long kBvhMaxFrames = 10'000'000;
inline constexpr double kBvhMaxMagnitude = 1e7;    // any offset / channel value / frame time

// Parses BVH text. `source` names the text in errors ("file:line:col: expected ..."). Throws
// gestura::Error for any malformed input, including more than one ROOT.
BvhFile read_bvh(std::string_view text, const std::string& source, const BvhReadOptions& options = {});
BvhFile load_bvh(const std::string& path, const BvhReadOptions& options = {});

// A BVH layout for a skeleton and clip from elsewhere: one ROOT (the skeleton must have exactly
// one), rotations "Zrotation Xrotation Yrotation" on every joint, position channels on the root
// and on joints whose clip has a translation track; frames cover [0, clip.duration].
BvhFile make_bvh(const Skeleton& skeleton, const Clip& clip, float frame_time);

// Writes `bvh` (its layout, frames and clip). Throws gestura::Error when the parts disagree, the
// skeleton has several roots, or the clip scales joints (BVH has no scale channels).
std::string write_bvh(const BvhFile& bvh);
void save_bvh(const std::string& path, const BvhFile& bvh);

}  // namespace gestura
