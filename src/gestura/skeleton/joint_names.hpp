#pragma once
// Joint names across rig conventions, with H-Anim 1.1 as the hub every other convention maps to.
//
// Conventions: H-Anim 1.1 (ours), VRM 1.0 humanoid bones, the MakeHuman default rig (default.mhskel
// and the BVH files MakeHuman exports from it), MakeHuman's "game engine" rig, and the CMU
// motion-capture BVH names (also MakeHuman's cmu_mb rig). A row lists the same anatomical joint in
// every convention; empty means the convention has no such joint. The table is written for the
// left side and mirrored for the right at first use.
//
// guess_hanim_names() maps the joints of an arbitrary skeleton: an exact match in any column first,
// then a match ignoring case, separators ('.', '_', '-', ' ') and a namespace prefix ("mixamorig:"),
// with the side read from common markers (Left/Right, l_/r_, _l/_r, .L/.R, a leading L/R before a
// capital). BVH end sites ("<joint>_end") of a thumb/finger/head/toe joint map to the H-Anim site
// (l_index_tip, skull_tip, l_toe_tip, ...).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

enum class RigConvention : std::uint8_t { HAnim, Vrm, MakeHuman, MakeHumanGameEngine, Cmu };
inline constexpr int kRigConventionCount = 5;

std::string_view to_string(RigConvention convention);

// One anatomical joint: its name in each convention (indexed by RigConvention), "" when absent.
struct JointNameRow {
  std::string names[kRigConventionCount];
  const std::string& operator[](RigConvention c) const { return names[static_cast<int>(c)]; }
};

// Every row, left and right sides included.
std::span<const JointNameRow> joint_name_table();

// The H-Anim name of `name` in `from`, or "" when the table has none.
std::string to_hanim(std::string_view name, RigConvention from);
// The name in `to` of an H-Anim joint, or "" when that convention has no such joint.
std::string from_hanim(std::string_view hanim, RigConvention to);

// Per joint of `skeleton`, its guessed H-Anim name ("" when nothing fits). Each H-Anim name is
// given to at most one joint (the first that claims it in skeleton order).
std::vector<std::string> guess_hanim_names(const Skeleton& skeleton);

// target_to_source[t] = the source joint playing the role of target joint t, or -1: joints are
// paired when their names are equal, else when their guessed H-Anim names are equal.
std::vector<int> match_joints(const Skeleton& source, const Skeleton& target);

}  // namespace gestura
