// Joint-name tables and guessing: the MakeHuman rigs' own bone lists, the avatar's names, spelling
// variants, and what must stay unmapped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/skeleton/joint_names.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura;

using gestura::test::shared_data;

std::set<std::string> rig_bones(const std::string& rig) {
  std::ifstream file(shared_data() + "/makehuman/rigs/" + rig + ".mhskel");
  EXPECT_TRUE(file) << rig;
  const nlohmann::json json = nlohmann::json::parse(file);
  std::set<std::string> names;
  for (const auto& [name, bone] : json.at("bones").items()) names.insert(name);
  return names;
}

Skeleton chain_of(const std::vector<std::string>& names) {
  Skeleton s;
  int parent = -1;
  for (const std::string& n : names) parent = s.add_joint(n, parent, vec3(0, 0.1f, 0));
  return s;
}

TEST(JointNames, EveryTableNameExistsInItsRigOrAvatar) {
  const std::set<std::string> mh = rig_bones("default"), game = rig_bones("game_engine"), cmu = rig_bones("cmu_mb");
  const Skeleton avatar = build_avatar_skeleton();
  int avatar_hits = 0;
  for (const JointNameRow& row : joint_name_table()) {
    const auto& m = row[RigConvention::MakeHuman];
    const auto& g = row[RigConvention::MakeHumanGameEngine];
    const auto& c = row[RigConvention::Cmu];
    EXPECT_TRUE(m.empty() || mh.contains(m)) << m;
    EXPECT_TRUE(g.empty() || game.contains(g)) << g;
    EXPECT_TRUE(c.empty() || c.ends_with("HandIndex1") || cmu.contains(c)) << c;
    avatar_hits += avatar.find(row[RigConvention::HAnim]) >= 0;
  }
  // Every avatar joint that is not a site or an auxiliary foot joint has a row.
  EXPECT_EQ(avatar_hits, 10 + 2 * 26) << "rows naming avatar joints";
}

TEST(JointNames, LookupBothWays) {
  EXPECT_EQ(to_hanim("upperarm01.R", RigConvention::MakeHuman), "r_shoulder");
  EXPECT_EQ(to_hanim("RightForeArm", RigConvention::Cmu), "r_elbow");
  EXPECT_EQ(to_hanim("RThumb", RigConvention::Cmu), "r_thumb1");
  EXPECT_EQ(to_hanim("leftLittleDistal", RigConvention::Vrm), "l_pinky3");
  EXPECT_EQ(to_hanim("calf_r", RigConvention::MakeHumanGameEngine), "r_knee");
  EXPECT_EQ(to_hanim("upperarm01.R", RigConvention::Cmu), "");
  EXPECT_EQ(from_hanim("r_wrist", RigConvention::Vrm), "rightHand");
  EXPECT_EQ(from_hanim("vt1", RigConvention::Vrm), "upperChest");
  EXPECT_EQ(from_hanim("l_metatarsal", RigConvention::Cmu), "LeftToeBase");
  EXPECT_EQ(from_hanim("vl3", RigConvention::Cmu), "");
}

TEST(JointNames, MakeHumanRigsMapBonesTheTableLists) {
  for (const char* rig : {"cmu_mb", "game_engine"}) {
    Skeleton s;
    for (const std::string& n : rig_bones(rig)) s.add_joint(n, -1, vec3(0.0f));
    const std::vector<std::string> guessed = guess_hanim_names(s);
    int mapped = 0;
    for (const auto& g : guessed) mapped += !g.empty();
    // cmu_mb: 31 bones less the two hip joints and the two finger-1 bones... LeftHandFinger1 is an alias.
    EXPECT_EQ(mapped, std::string(rig) == "cmu_mb" ? 29 : 52) << rig;
  }
}

TEST(JointNames, LooseSpellingsAndSides) {
  const Skeleton s = chain_of({"mixamorig:Hips", "Left_UpperLeg", "r_lowerarm", "LowerLeg.R", "UPPERARM01_L",
                               "thumb_01.r", "rightIndexProximal", "Wrist_Left"});
  const std::vector<std::string> g = guess_hanim_names(s);
  EXPECT_EQ(g[0], "humanoid_root");
  EXPECT_EQ(g[1], "l_hip");
  EXPECT_EQ(g[2], "r_elbow");
  EXPECT_EQ(g[3], "r_knee");
  EXPECT_EQ(g[4], "l_shoulder");
  EXPECT_EQ(g[5], "r_thumb1");
  EXPECT_EQ(g[6], "r_index1");
  EXPECT_EQ(g[7], "l_wrist");
}

TEST(JointNames, UnknownNamesStayUnmappedAndNamesAreClaimedOnce) {
  const Skeleton s = chain_of({"Hips", "hips", "tail", "LHipJoint", "levator02.L", "Leftish"});
  const std::vector<std::string> g = guess_hanim_names(s);
  EXPECT_EQ(g[0], "humanoid_root");
  for (std::size_t j = 1; j < g.size(); ++j) EXPECT_EQ(g[j], "") << s.names[j];
}

TEST(JointNames, BvhEndSitesBecomeHAnimSites) {
  const Skeleton s = chain_of({"head", "head_end"});
  Skeleton hand = chain_of({"wrist.L", "finger2-1.L", "finger2-2.L", "finger2-3.L", "finger2-3.L_end"});
  EXPECT_EQ(guess_hanim_names(s)[1], "skull_tip");
  EXPECT_EQ(guess_hanim_names(hand)[4], "l_index_tip");
}

TEST(JointNames, MatchPairsAvatarWithItself) {
  const Skeleton avatar = build_avatar_skeleton();
  const std::vector<int> m = match_joints(avatar, avatar);
  int paired = 0;
  for (std::size_t j = 0; j < m.size(); ++j)
    if (m[j] >= 0) {
      EXPECT_EQ(m[j], static_cast<int>(j));
      ++paired;
    }
  EXPECT_GT(paired, 60);
}

}  // namespace
