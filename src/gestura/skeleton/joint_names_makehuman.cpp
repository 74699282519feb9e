#include "gestura/skeleton/joint_names_makehuman.hpp"

#include <array>

namespace gestura {

namespace {

// Chosen by where each MakeHuman bone's head sits on the base mesh (its head is the joint):
// upperleg01 starts at the hip, upperarm01 at the glenohumeral joint, lowerarm01 at the elbow;
// the *02 bones of the limbs start mid-segment (twist helpers) and stay unmapped. The five spine
// bones run from the lumbar curve (spine05) to the upper thorax (spine01); neck01 starts at C7.
// metacarpal1..4 carry index..pinky (the thumb's finger1 hangs off the wrist directly).
#define SIDED(mh, hanim) {mh ".L", "l_" hanim}, {mh ".R", "r_" hanim}
constexpr JointNamePair kTable[] = {
    {"root", "humanoid_root"},
    {"spine05", "vl5"},
    {"spine04", "vl3"},
    {"spine03", "vl1"},
    {"spine02", "vt12"},
    {"spine01", "vt6"},
    {"neck01", "vc7"},
    {"neck02", "vc4"},
    {"neck03", "vc2"},
    {"head", "skullbase"},
    {"jaw", "temporomandibular"},
    SIDED("eye", "eyeball_joint"),
    SIDED("clavicle", "sternoclavicular"),
    SIDED("shoulder01", "acromioclavicular"),
    SIDED("upperarm01", "shoulder"),
    SIDED("lowerarm01", "elbow"),
    SIDED("wrist", "wrist"),
    SIDED("finger1-1", "thumb1"),
    SIDED("finger1-2", "thumb2"),
    SIDED("finger1-3", "thumb3"),
    SIDED("metacarpal1", "index0"),
    SIDED("finger2-1", "index1"),
    SIDED("finger2-2", "index2"),
    SIDED("finger2-3", "index3"),
    SIDED("metacarpal2", "middle0"),
    SIDED("finger3-1", "middle1"),
    SIDED("finger3-2", "middle2"),
    SIDED("finger3-3", "middle3"),
    SIDED("metacarpal3", "ring0"),
    SIDED("finger4-1", "ring1"),
    SIDED("finger4-2", "ring2"),
    SIDED("finger4-3", "ring3"),
    SIDED("metacarpal4", "pinky0"),
    SIDED("finger5-1", "pinky1"),
    SIDED("finger5-2", "pinky2"),
    SIDED("finger5-3", "pinky3"),
    SIDED("upperleg01", "hip"),
    SIDED("lowerleg01", "knee"),
    SIDED("foot", "ankle"),
};
#undef SIDED

}  // namespace

std::span<const JointNamePair> makehuman_hanim_names() { return kTable; }

std::string joint_name_from_makehuman(std::string_view bone) {
  for (const JointNamePair& pair : kTable)
    if (pair.makehuman == bone) return std::string(pair.hanim);
  if (bone.size() > 2 && bone[bone.size() - 2] == '.') {
    const char side = bone.back();
    if (side == 'L' || side == 'l') return "l_" + std::string(bone.substr(0, bone.size() - 2));
    if (side == 'R' || side == 'r') return "r_" + std::string(bone.substr(0, bone.size() - 2));
  }
  return std::string(bone);
}

}  // namespace gestura
