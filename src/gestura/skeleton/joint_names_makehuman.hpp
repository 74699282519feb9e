#pragma once
// MakeHuman default-rig bone names → our H-Anim 1.1 style joint names.
#include <span>
#include <string>
#include <string_view>

namespace gestura {

struct JointNamePair {
  std::string_view makehuman;
  std::string_view hanim;
};

// Every MakeHuman bone that has an H-Anim counterpart (twist bones, toes, breasts and face muscles
// have none).
std::span<const JointNamePair> makehuman_hanim_names();

// The H-Anim name when the table has one; otherwise the MakeHuman name with its side suffix turned
// into our prefix ("levator02.L" → "l_levator02", "tongue00" unchanged).
std::string joint_name_from_makehuman(std::string_view makehuman_bone);

}  // namespace gestura
