#pragma once
// MakeHuman assets (hm08 base mesh, default rig, its weights) as a gestura Mesh + Skeleton.
//
// Directory layout as in /work/shared/data/makehuman: base.obj, rigs/default.mhskel,
// rigs/default_weights.mhw. MakeHuman models are in decimetres, +Y up, facing +Z, left = +X: we
// only scale by 0.1 to metres (the origin stays where MakeHuman has it, about the pelvis; feet
// at y ≈ −0.84 m). Malformed files throw gestura::Error naming file and line (OBJ, JSON syntax)
// or the JSON field.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr float kMakeHumanUnit = 0.1f;  // metres per MakeHuman unit (decimetre)

// An OBJ mesh with the group ("g") of every triangle. The hm08 base mesh keeps helper geometry
// (tights, skirt, hair, teeth, tongue, eyelashes, joint cubes) after the body in its vertex list.
struct GroupedMesh {
  Mesh mesh;                                  // positions in metres, area-weighted normals, all Skin
  std::vector<std::string> groups;            // group names in order of first use
  std::vector<std::uint16_t> triangle_groups; // per triangle, index into groups
  int find_group(std::string_view name) const;  // -1 when absent
};

// Reads v / f (v, v/vt, v//vn, v/vt/vn; polygons fanned into triangles; negative indices
// relative) and g; texture coordinates are checked but not kept (Mesh has none). Other statements
// are ignored. `unit` scales positions (kMakeHumanUnit for MakeHuman files).
GroupedMesh read_grouped_obj(const std::string& path, float unit = kMakeHumanUnit);
GroupedMesh parse_grouped_obj(std::string_view text, const std::string& name, float unit = kMakeHumanUnit);

// The default rig: one joint per bone at the bone's head, then one site per finger tip
// (l_thumb_tip … r_pinky_tip, at the tail of the distal phalanx). Joint frames are aligned with the
// model axes (rest rotations identity; MakeHuman's bone rolls are not used), so the inverse bind
// matrix of a joint is a translation by minus its head.
struct MakeHumanRig {
  Skeleton skeleton;                        // names via joint_name_from_makehuman
  std::vector<std::string> makehuman_names; // per joint: the bone name ("" for tip sites)
  std::vector<vec3> heads, tails;           // per joint, model space, metres (site: tail = head)
  std::vector<mat4> inverse_bind;           // per joint
  std::size_t bone_count = 0;               // joints [0, bone_count) are bones, the rest sites
  int find_bone(std::string_view makehuman_name) const;  // joint index or -1
};

// Joint places are averages of the listed mesh vertices (`positions`, already in metres).
MakeHumanRig read_makehuman_rig(const std::string& path, std::span<const vec3> positions);
MakeHumanRig parse_makehuman_rig(std::string_view json_text, const std::string& name, std::span<const vec3> positions);

// Vertex groups (bone name → [[vertex, weight], …]) into mesh.joints / mesh.weights: the four largest
// influences per vertex, renormalised to sum 1, in decreasing weight (unused slots: joint 0,
// weight 0). A vertex no group names gets the root joint with weight 1.
void read_makehuman_weights(const std::string& path, const MakeHumanRig& rig, Mesh& mesh);
void parse_makehuman_weights(std::string_view json_text, const std::string& name, const MakeHumanRig& rig, Mesh& mesh);

struct MakeHumanBody {
  GroupedMesh mesh;  // every vertex of base.obj, skinned
  MakeHumanRig rig;
};

// base.obj + rigs/default.mhskel + rigs/default_weights.mhw from `directory`.
MakeHumanBody load_makehuman(const std::string& directory);

// The part of a mesh used by the triangles of the named groups (e.g. {"body"} drops the helpers):
// vertices renumbered in their original order, per-vertex arrays and morph targets carried over.
// `original_vertex`, when given, receives the source index of every kept vertex.
GroupedMesh keep_groups(const GroupedMesh& source, std::span<const std::string_view> groups,
                        std::vector<std::uint32_t>* original_vertex = nullptr);

}  // namespace gestura
