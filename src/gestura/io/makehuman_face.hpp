#pragma once
// MakeHuman face pose units and expressions.
//
// poseunits/face-poseunits.json names the frames of face-poseunits.bvh: each frame is one "pose
// unit" (LeftBrowDown, JawDrop, TongueOut, …; frame 0 is "Rest") given as rotations of the default
// rig's bones. An expression (expressions/*.mhpose) is a weighted mix of units, e.g. anger01 =
// 0.643·LeftBrowDown + 1.0·UpperLipUp + …
//
// Rotations are converted to our frame: the BVH is Z-up with the character facing −Y (Blender
// convention) and its joints are axis-aligned (BVH has no rest orientation), so a rotation q becomes
// C·q·C⁻¹ with C = −90° about X, which makes it a local rotation of our axis-aligned MakeHuman rig
// joints (see MakeHumanRig) relative to rest.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

struct FacePoseUnits {
  std::vector<std::string> units;   // frame names, "Rest" first
  std::vector<std::string> bones;   // MakeHuman bone names of the BVH joints, file order
  std::vector<quat> rotations;      // units.size() × bones.size(), unit-major: [u * bones.size() + b]
  int find_unit(std::string_view name) const;  // -1 when absent
  int find_bone(std::string_view name) const;
  std::span<const quat> unit(std::size_t u) const { return {rotations.data() + u * bones.size(), bones.size()}; }
};

// The .json names the frames of the .bvh; the counts must agree.
FacePoseUnits read_makehuman_face_units(const std::string& json_path, const std::string& bvh_path);
FacePoseUnits parse_makehuman_face_units(std::string_view json_text, const std::string& json_name,
                                         std::string_view bvh_text, const std::string& bvh_name);

struct FaceExpression {
  std::string name;                 // e.g. "anger01"
  std::vector<std::string> units;   // pose unit names
  std::vector<float> weights;       // one per unit
};

FaceExpression read_makehuman_expression(const std::string& path);
FaceExpression parse_makehuman_expression(std::string_view json_text, const std::string& name);
// Every *.mhpose of a directory, sorted by name.
std::vector<FaceExpression> read_makehuman_expressions(const std::string& directory);

// Per bone of `units`: the expression's rotation, each unit applied at its weight as
// slerp(identity, unit rotation, weight) and composed in the expression's order. Unknown unit names
// throw gestura::Error. out.size() == units.bones.size().
void expression_rotations(const FacePoseUnits& units, const FaceExpression& expression, std::span<quat> out);

}  // namespace gestura
