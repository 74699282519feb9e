#include "gestura/skeleton/joint_names.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace gestura {
namespace {

// H-Anim, VRM 1.0, MakeHuman default, MakeHuman game engine, CMU mocap.
struct Spelling {
  const char* names[kRigConventionCount];
};

// Joints on the midline.
constexpr Spelling kCentre[] = {
    {{"humanoid_root", "hips", "root", "pelvis", "Hips"}},
    {{"vl5", "spine", "spine05", "spine_01", "LowerBack"}},
    {{"vl3", "", "spine04", "", ""}},
    {{"vt12", "chest", "spine03", "spine_02", "Spine"}},
    {{"vt6", "", "spine02", "", ""}},
    {{"vt1", "upperChest", "spine01", "spine_03", "Spine1"}},
    {{"vc7", "neck", "neck01", "neck_01", "Neck"}},
    {{"vc4", "", "neck02", "", "Neck1"}},
    {{"vc2", "", "neck03", "", ""}},
    {{"skullbase", "head", "head", "head", "Head"}},
    {{"temporomandibular", "jaw", "jaw", "", ""}},
};

// Left-side joints; the right side is derived by mirror_name().
constexpr Spelling kLeft[] = {
    {{"l_eyeball_joint", "leftEye", "eye.L", "", ""}},
    {{"l_sternoclavicular", "leftShoulder", "clavicle.L", "clavicle_l", "LeftShoulder"}},
    {{"l_acromioclavicular", "", "shoulder01.L", "", ""}},
    {{"l_shoulder", "leftUpperArm", "upperarm01.L", "upperarm_l", "LeftArm"}},
    {{"l_elbow", "leftLowerArm", "lowerarm01.L", "lowerarm_l", "LeftForeArm"}},
    {{"l_wrist", "leftHand", "wrist.L", "hand_l", "LeftHand"}},
    {{"l_thumb1", "leftThumbMetacarpal", "finger1-1.L", "thumb_01_l", "LThumb"}},
    {{"l_thumb2", "leftThumbProximal", "finger1-2.L", "thumb_02_l", ""}},
    {{"l_thumb3", "leftThumbDistal", "finger1-3.L", "thumb_03_l", ""}},
    {{"l_index0", "", "metacarpal1.L", "", "LeftFingerBase"}},
    {{"l_index1", "leftIndexProximal", "finger2-1.L", "index_01_l", "LeftHandIndex1"}},
    {{"l_index2", "leftIndexIntermediate", "finger2-2.L", "index_02_l", ""}},
    {{"l_index3", "leftIndexDistal", "finger2-3.L", "index_03_l", ""}},
    {{"l_middle0", "", "metacarpal2.L", "", ""}},
    {{"l_middle1", "leftMiddleProximal", "finger3-1.L", "middle_01_l", ""}},
    {{"l_middle2", "leftMiddleIntermediate", "finger3-2.L", "middle_02_l", ""}},
    {{"l_middle3", "leftMiddleDistal", "finger3-3.L", "middle_03_l", ""}},
    {{"l_ring0", "", "metacarpal3.L", "", ""}},
    {{"l_ring1", "leftRingProximal", "finger4-1.L", "ring_01_l", ""}},
    {{"l_ring2", "leftRingIntermediate", "finger4-2.L", "ring_02_l", ""}},
    {{"l_ring3", "leftRingDistal", "finger4-3.L", "ring_03_l", ""}},
    {{"l_pinky0", "", "metacarpal4.L", "", ""}},
    {{"l_pinky1", "leftLittleProximal", "finger5-1.L", "pinky_01_l", ""}},
    {{"l_pinky2", "leftLittleIntermediate", "finger5-2.L", "pinky_02_l", ""}},
    {{"l_pinky3", "leftLittleDistal", "finger5-3.L", "pinky_03_l", ""}},
    {{"l_hip", "leftUpperLeg", "upperleg01.L", "thigh_l", "LeftUpLeg"}},
    {{"l_knee", "leftLowerLeg", "lowerleg01.L", "calf_l", "LeftLeg"}},
    {{"l_ankle", "leftFoot", "foot.L", "foot_l", "LeftFoot"}},
    {{"l_metatarsal", "leftToes", "toe3-1.L", "ball_l", "LeftToeBase"}},
};

// Other spellings met in the wild for the same joint (CMU variants), as (name, H-Anim).
constexpr std::pair<const char*, const char*> kAliases[] = {
    {"LeftHandFinger1", "l_index1"}, {"RightHandFinger1", "r_index1"},
    {"LHipJoint", ""},               {"RHipJoint", ""},
};

// H-Anim sites at the end of a chain, for BVH end sites named "<joint>_end".
constexpr std::pair<const char*, const char*> kSites[] = {
    {"thumb3", "thumb_tip"}, {"index3", "index_tip"}, {"middle3", "middle_tip"},
    {"ring3", "ring_tip"},   {"pinky3", "pinky_tip"}, {"metatarsal", "toe_tip"},
};

std::string replace_first(std::string s, std::string_view from, std::string_view to) {
  const auto at = s.find(from);
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// The right-side spelling of a left-side name in its own convention.
std::string mirror_name(const std::string& left, RigConvention c) {
  if (left.empty()) return left;
  switch (c) {
    case RigConvention::HAnim: return "r_" + left.substr(2);
    case RigConvention::Vrm: return "right" + left.substr(4);
    case RigConvention::MakeHuman: return left.substr(0, left.size() - 2) + ".R";
    case RigConvention::MakeHumanGameEngine: return left.substr(0, left.size() - 2) + "_r";
    case RigConvention::Cmu:
      return left.starts_with("Left") ? replace_first(left, "Left", "Right") : "R" + left.substr(1);
  }
  return left;
}

std::vector<JointNameRow> build_table() {
  std::vector<JointNameRow> rows;
  auto add = [&](const Spelling& s, bool mirror) {
    JointNameRow row;
    for (int c = 0; c < kRigConventionCount; ++c) {
      row.names[c] = s.names[c];
      if (mirror) row.names[c] = mirror_name(row.names[c], static_cast<RigConvention>(c));
    }
    rows.push_back(std::move(row));
  };
  for (const Spelling& s : kCentre) add(s, false);
  for (const Spelling& s : kLeft) add(s, false);
  for (const Spelling& s : kLeft) add(s, true);
  return rows;
}

// A name reduced to what survives spelling variants: side ('l', 'r' or 0) and lower-case letters
// and digits of the rest.
struct NameKey {
  char side = 0;
  std::string base;
  auto operator<=>(const NameKey&) const = default;
};

NameKey name_key(std::string_view name) {
  if (const auto colon = name.rfind(':'); colon != std::string_view::npos) name = name.substr(colon + 1);
  NameKey key;
  std::string n(name);
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return s;
  };
  auto is_sep = [](char ch) { return ch == '.' || ch == '_' || ch == '-' || ch == ' '; };
  const std::string l = lower(n);
  std::string rest = n;
  if (l.starts_with("left")) key.side = 'l', rest = n.substr(4);
  else if (l.starts_with("right")) key.side = 'r', rest = n.substr(5);
  else if (n.size() > 2 && (l[0] == 'l' || l[0] == 'r') && is_sep(n[1])) key.side = l[0], rest = n.substr(2);
  else if (n.size() > 1 && (n[0] == 'L' || n[0] == 'R') && std::isupper(static_cast<unsigned char>(n[1])))
    key.side = static_cast<char>(std::tolower(n[0])), rest = n.substr(1);
  else {
    const std::string lr = lower(rest);
    if (lr.ends_with("left")) key.side = 'l', rest.resize(rest.size() - 4);
    else if (lr.ends_with("right")) key.side = 'r', rest.resize(rest.size() - 5);
    else if (rest.size() > 2 && is_sep(rest[rest.size() - 2]) && (lr.back() == 'l' || lr.back() == 'r'))
      key.side = lr.back(), rest.resize(rest.size() - 2);
  }
  for (char ch : rest)
    if (std::isalnum(static_cast<unsigned char>(ch))) key.base += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return key;
}

struct Index {
  std::vector<JointNameRow> rows;
  std::map<std::string, std::string, std::less<>> exact;  // any spelling → H-Anim
  std::map<NameKey, std::string> loose;                    // key of any spelling → H-Anim
  std::map<std::string, std::string, std::less<>> columns[kRigConventionCount];
};

const Index& index() {
  static const Index built = [] {
    Index ix;
    ix.rows = build_table();
    auto learn = [&](const std::string& name, const std::string& hanim) {
      if (name.empty()) return;
      ix.exact.emplace(name, hanim);
      ix.loose.emplace(name_key(name), hanim);
    };
    for (const JointNameRow& row : ix.rows) {
      const std::string& hanim = row[RigConvention::HAnim];
      for (int c = 0; c < kRigConventionCount; ++c) {
        learn(row.names[c], hanim);
        if (!row.names[c].empty()) ix.columns[c].emplace(row.names[c], hanim);
      }
    }
    for (const auto& [alias, hanim] : kAliases) ix.exact.emplace(alias, hanim);
    // H-Anim sites (fingertips, toe tips, skull top) are names of their own.
    ix.exact.emplace("skull_tip", "skull_tip");
    for (const auto& [joint, site] : kSites)
      for (const char* side : {"l_", "r_"}) ix.exact.emplace(side + std::string(site), side + std::string(site));
    return ix;
  }();
  return built;
}

std::string site_of(const std::string& hanim) {
  if (hanim == "skullbase") return "skull_tip";
  if (hanim.size() < 3 || hanim[1] != '_') return "";
  for (const auto& [joint, site] : kSites)
    if (hanim.substr(2) == joint) return hanim.substr(0, 2) + site;
  return "";
}

}  // namespace

std::string_view to_string(RigConvention convention) {
  switch (convention) {
    case RigConvention::HAnim: return "H-Anim 1.1";
    case RigConvention::Vrm: return "VRM 1.0";
    case RigConvention::MakeHuman: return "MakeHuman default";
    case RigConvention::MakeHumanGameEngine: return "MakeHuman game engine";
    case RigConvention::Cmu: return "CMU mocap";
  }
  return "?";
}

std::span<const JointNameRow> joint_name_table() { return index().rows; }

std::string to_hanim(std::string_view name, RigConvention from) {
  const auto& column = index().columns[static_cast<int>(from)];
  const auto it = column.find(name);
  return it == column.end() ? std::string() : it->second;
}

std::string from_hanim(std::string_view hanim, RigConvention to) {
  for (const JointNameRow& row : index().rows)
    if (row[RigConvention::HAnim] == hanim) return row[to];
  return "";
}

std::vector<std::string> guess_hanim_names(const Skeleton& skeleton) {
  const Index& ix = index();
  std::vector<std::string> out(skeleton.size());
  std::map<std::string, int> taken;
  auto claim = [&](std::size_t j, const std::string& hanim) {
    if (hanim.empty() || taken.contains(hanim)) return;
    taken.emplace(hanim, static_cast<int>(j));
    out[j] = hanim;
  };
  // Exact spellings win over loose ones anywhere in the skeleton, so run them first.
  for (std::size_t j = 0; j < skeleton.size(); ++j)
    if (const auto it = ix.exact.find(skeleton.names[j]); it != ix.exact.end()) claim(j, it->second);
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    if (!out[j].empty() || ix.exact.contains(skeleton.names[j])) continue;
    const std::string& name = skeleton.names[j];
    const int parent = skeleton.parents[j];
    if (name.ends_with("_end") && parent >= 0 && name.substr(0, name.size() - 4) == skeleton.names[parent]) {
      claim(j, site_of(out[static_cast<std::size_t>(parent)]));
      continue;
    }
    if (const auto it = ix.loose.find(name_key(name)); it != ix.loose.end()) claim(j, it->second);
  }
  return out;
}

std::vector<int> match_joints(const Skeleton& source, const Skeleton& target) {
  const std::vector<std::string> s = guess_hanim_names(source);
  const std::vector<std::string> t = guess_hanim_names(target);
  std::map<std::string, int> by_name;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (!s[j].empty()) by_name.emplace(s[j], static_cast<int>(j));
  std::vector<int> out(target.size(), -1);
  for (std::size_t j = 0; j < t.size(); ++j) {
    if (const int same = source.find(target.names[j]); same >= 0) out[j] = same;
    else if (const auto it = by_name.find(t[j]); !t[j].empty() && it != by_name.end()) out[j] = it->second;
  }
  return out;
}

}  // namespace gestura
