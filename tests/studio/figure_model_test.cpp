// The figure editor's model and the pose editor's IK drag without a window: tree edits that keep
// the figure valid and its joints in place, a branch mirrored onto the other side of a symmetric
// body, the skeleton file written and read back (and a broken one refused with nothing lost),
// picking a bone with a ray, dragging a wrist to a target.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/studio/figure_model.hpp"
#include "gestura/studio/limb_drag.hpp"
#include "lexicon/temp_dir.hpp"

namespace gestura::studio {
namespace {

using gestura::testing::TempDir;

std::vector<vec3> rest_positions(const Skeleton& s) {
  std::vector<mat4> model(s.size());
  local_to_model(s, rest_pose(s), model);
  std::vector<vec3> out(s.size());
  model_positions(model, out);
  return out;
}

TEST(FigureEditor, RenameAddAndRemoveKeepTheFigureValidAndTheOtherJointsInPlace) {
  FigureEditor f(build_avatar_skeleton());
  const Skeleton before = f.skeleton();
  const int elbow = f.skeleton().find("l_elbow");
  ASSERT_GE(elbow, 0);
  EXPECT_FALSE(f.rename(elbow, "r_elbow"));  // taken
  EXPECT_NE(std::string::npos, f.error().find("already"));
  EXPECT_FALSE(f.rename(elbow, "bad name"));
  ASSERT_TRUE(f.rename(elbow, "l_elbow2"));
  EXPECT_EQ(elbow, f.skeleton().find("l_elbow2"));
  const int added = f.add_joint(elbow, "l_forearm_mid", vec3(0.1f, 0, 0));
  ASSERT_GT(added, elbow);
  EXPECT_EQ(elbow, f.skeleton().parents[static_cast<std::size_t>(added)]);
  // Removing the elbow keeps the wrist (and everything below it) where it was.
  const std::vector<vec3> at = rest_positions(f.skeleton());
  const int wrist = f.skeleton().find("l_wrist");
  const vec3 wrist_at = at[static_cast<std::size_t>(wrist)];
  ASSERT_TRUE(f.remove_joint(elbow));
  EXPECT_LT(f.skeleton().find("l_elbow2"), 0);
  const std::vector<vec3> after = rest_positions(f.skeleton());
  EXPECT_LT(glm::length(after[static_cast<std::size_t>(f.skeleton().find("l_wrist"))] - wrist_at), 1e-5f);
  EXPECT_FALSE(f.remove_joint(0));  // the root
  // Undo all three edits: the avatar's skeleton again.
  ASSERT_TRUE(f.undo() && f.undo() && f.undo());
  EXPECT_EQ(before.names, f.skeleton().names);
  EXPECT_EQ(before.parents, f.skeleton().parents);
}

TEST(FigureEditor, MirroringTheLeftArmOntoTheRightGivesTheSymmetricAvatarsOwnRightArm) {
  FigureEditor f(build_avatar_skeleton());
  const Skeleton before = f.skeleton();
  const int shoulder = f.skeleton().find("l_shoulder");
  const std::size_t count = f.branch(shoulder).size();
  ASSERT_GT(count, 10u);  // shoulder, elbow, wrist and the fingers
  EXPECT_EQ(static_cast<int>(count), f.mirror_branch(shoulder));
  EXPECT_EQ(before.size(), f.skeleton().size());  // written onto the existing joints
  for (const int j : f.branch(f.skeleton().find("r_shoulder"))) {
    const std::size_t u = static_cast<std::size_t>(j);
    EXPECT_LT(glm::length(f.skeleton().rest_translations[u] - before.rest_translations[u]), 1e-4f) << before.names[u];
    for (int a = 0; a < 3; ++a)
      if (before.dofs[u].free(a)) {
        EXPECT_NEAR(before.dofs[u].min_angle[a], f.skeleton().dofs[u].min_angle[a], 1e-4f) << before.names[u] << " axis " << a;
        EXPECT_NEAR(before.dofs[u].max_angle[a], f.skeleton().dofs[u].max_angle[a], 1e-4f) << before.names[u] << " axis " << a;
      }
  }
  // A copied branch is a new limb under the same parent.
  const int copy = f.copy_branch(f.skeleton().find("l_index1"));
  ASSERT_GE(copy, 0);
  EXPECT_EQ("l_index1_copy", f.skeleton().names[static_cast<std::size_t>(copy)]);
  EXPECT_EQ(f.skeleton().find("l_wrist"), f.skeleton().parents[static_cast<std::size_t>(copy)]);
  EXPECT_EQ(-1, f.mirror_branch(f.skeleton().find("skullbase")));  // no side
}

TEST(FigureEditor, TheSkeletonFileReadsBackWithLimitsAndDhAndABrokenOneLosesNothing) {
  TempDir dir;
  FigureEditor f(build_avatar_skeleton());
  const int wrist = f.skeleton().find("r_wrist");
  ASSERT_TRUE(f.set_rest_offset(wrist, f.skeleton().rest_translations[static_cast<std::size_t>(wrist)] * 1.1f));
  ASSERT_TRUE(f.set_dh(wrist, f.dh_from_rest(wrist)));
  // The DH description of the rest offset puts the joint where the offset does.
  const vec3 via_dh(f.skeleton().dh[static_cast<std::size_t>(wrist)]->matrix(0.0f)[3]);
  EXPECT_LT(glm::length(via_dh - f.skeleton().rest_translations[static_cast<std::size_t>(wrist)]), 1e-5f);
  const std::string path = dir.file("figure.bvh");
  f.save(path);
  // A plain BVH that the readers of motion accept (retarget --to, render).
  const BvhFile bvh = load_bvh(path);
  EXPECT_EQ(f.skeleton().size(), bvh.skeleton.size());
  const Skeleton back = load_figure(path);
  // BVH lists joints depth-first, so the order may differ: joints are compared by name.
  ASSERT_EQ(f.skeleton().size(), back.size());
  const Skeleton& s = f.skeleton();
  for (std::size_t j = 0; j < s.size(); ++j) {
    const int b = back.find(s.names[j]);
    ASSERT_GE(b, 0) << s.names[j];
    const std::size_t u = static_cast<std::size_t>(b);
    const int parent = s.parents[j], back_parent = back.parents[u];
    EXPECT_EQ(parent < 0 ? std::string() : s.names[static_cast<std::size_t>(parent)],
              back_parent < 0 ? std::string() : back.names[static_cast<std::size_t>(back_parent)]);
    EXPECT_LT(glm::length(back.rest_translations[u] - s.rest_translations[j]), 1e-5f) << s.names[j];
    EXPECT_GT(std::abs(glm::dot(back.rest_rotations[u], s.rest_rotations[j])), 0.99999f) << s.names[j];
    EXPECT_EQ(s.dofs[j].axes, back.dofs[u].axes) << s.names[j];
    EXPECT_EQ(s.dofs[j].order, back.dofs[u].order) << s.names[j];
    EXPECT_NEAR(s.dofs[j].max_angle.x, back.dofs[u].max_angle.x, 1e-5f) << s.names[j];
  }
  const std::size_t back_wrist = static_cast<std::size_t>(back.find("r_wrist"));
  ASSERT_TRUE(back.dh.size() > back_wrist && back.dh[back_wrist]);
  EXPECT_NEAR(s.dh[static_cast<std::size_t>(wrist)]->a, back.dh[back_wrist]->a, 1e-6f);

  // A file that does not parse: a message naming the file, the figure unchanged.
  const std::string broken = dir.write("broken.bvh", "HIERARCHY\nROOT hips\n{\n  OFFSET 0 zero 0\n");
  const Skeleton kept = f.skeleton();
  EXPECT_FALSE(f.load(broken));
  EXPECT_NE(std::string::npos, f.error().find("broken.bvh")) << f.error();
  EXPECT_EQ(kept.names, f.skeleton().names);
  EXPECT_EQ(path, f.file());
}

// Found while writing fuzz_figure (fuzz/fuzz_figure.cpp), each input crashing it: the sidecar
// reader let nlohmann's own exception
// out for a value of the wrong type (the studio catches gestura::Error only, so it would have
// ended), and read a limit past float's range as infinity, which a save writes as null: a file
// the editor could not read back.
TEST(FigureFile, ASidecarValueOfTheWrongTypeIsAnErrorNamingTheFileAndJoint) {
  const std::string bvh = write_figure(build_avatar_skeleton(), "avatar.bvh").bvh;
  const auto refused = [&](const std::string& sidecar) {
    try {
      (void)read_figure(bvh, "avatar.bvh", std::string_view(sidecar), "avatar.figure.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(read)");
  };
  const std::string limits = R"(, "min_degrees": [-10, 0, 0], "max_degrees": [10, 0, 0]}}})";
  std::string why = refused(R"({"joints": {"l_elbow": {"order": 5, "axes": "x")" + limits);
  EXPECT_NE(std::string::npos, why.find("avatar.figure.json: joint 'l_elbow': 'order' must be a string")) << why;
  why = refused(R"({"joints": {"l_elbow": {"order": "ZXY", "axes": ["x"])" + limits);
  EXPECT_NE(std::string::npos, why.find("'axes' must be a string")) << why;
  // Not JSON at all: the place named.
  why = refused(R"({"joints": {"l_elbow": )");
  EXPECT_NE(std::string::npos, why.find("avatar.figure.json")) << why;
  EXPECT_NE(std::string::npos, why.find("not a figure file")) << why;
  why = refused(R"({"joints": {"l_elbow": {"axes": "x", "min_degrees": [1e999, 0, 0], "max_degrees": [10, 0, 0]}}})");
  EXPECT_NE(std::string::npos, why.find("not a figure file")) << why;  // past a double: the JSON library's overflow
  // A limit min above its max: the file named (the check is the skeleton's own).
  why = refused(R"({"joints": {"l_elbow": {"axes": "x", "min_degrees": [20, 0, 0], "max_degrees": [10, 0, 0]}}})");
  EXPECT_EQ(0u, why.find("avatar.figure.json: ")) << why;
  EXPECT_NE(std::string::npos, why.find("min > max")) << why;
}

TEST(FigureFile, NumbersPastTheFileLimitAreRefusedSoWhatLoadsAlwaysSavesAndReadsBack) {
  const std::string bvh = write_figure(build_avatar_skeleton(), "avatar.bvh").bvh;
  const auto read = [&](const std::string& sidecar) {
    return read_figure(bvh, "avatar.bvh", std::string_view(sidecar), "avatar.figure.json");
  };
  // 1e39 degrees is past float's range (it was read as infinity and saved as null).
  for (const std::string field : {R"("min_degrees": [-1e39, 0, 0], "max_degrees": [10, 0, 0])",
                                  R"("min_degrees": [-10, 0, 0], "max_degrees": [10, 0, 3.5e38])"}) {
    try {
      (void)read(R"({"joints": {"l_elbow": {"axes": "x", )" + field + "}}}");
      ADD_FAILURE() << "read " << field;
    } catch (const Error& e) {
      EXPECT_NE(std::string::npos, std::string(e.what()).find("magnitude at most 1e7")) << e.what();
    }
  }
  try {
    (void)read(R"({"joints": {"r_wrist": {"axes": "", "min_degrees": [0, 0, 0], "max_degrees": [0, 0, 0],
                  "dh": {"a": 1e30, "alpha_degrees": 0, "d": 0, "theta_degrees": 0}}}})");
    ADD_FAILURE() << "read a DH length of 1e30";
  } catch (const Error& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find("joint 'r_wrist': 'a' must be a number of magnitude at most 1e7")) << e.what();
  }
  // At the limit: read, saved, and read back the same.
  const Skeleton wide = read(R"({"joints": {"l_elbow": {"axes": "xz", "min_degrees": [-1e7, 0, -400], "max_degrees": [1e7, 0, 400],
                               "dh": {"a": -1e7, "alpha_degrees": 1e7, "d": 0.5, "theta_degrees": -90}}}})");
  const FigureTexts saved = write_figure(wide, "wide.bvh");
  const Skeleton back = read_figure(saved.bvh, "wide.bvh", std::string_view(saved.sidecar), "wide.figure.json");
  const auto e = static_cast<std::size_t>(back.find("l_elbow"));
  EXPECT_EQ(0b101, back.dofs[e].axes);
  EXPECT_FLOAT_EQ(glm::radians(-1e7f), back.dofs[e].min_angle.x);
  EXPECT_FLOAT_EQ(glm::radians(400.0f), back.dofs[e].max_angle.z);
  ASSERT_TRUE(back.dh.size() > e && back.dh[e]);
  EXPECT_FLOAT_EQ(-1e7f, back.dh[e]->a);
}

// Found the same way: a BVH whose joint name is not UTF-8 (Latin-1 from an old exporter)
// loaded, and saving it threw nlohmann's exception (JSON text is UTF-8), ending the studio with
// the user's work. It still loads (so it can be repaired); saving names the joint.
TEST(FigureFile, AJointNameThatIsNotUtf8LoadsAndItsSaveIsRefusedByNameUntilRenamed) {
  TempDir dir;
  const std::string path = dir.write("latin1.bvh",
                                     "HIERARCHY\nROOT hips\n{\n OFFSET 0 1 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                                     " JOINT t\xEAte\n {\n  OFFSET 0 0.5 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                                     "  End Site\n  {\n   OFFSET 0 0.2 0\n  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.04\n0 1 0 0 0 0 0 30 0\n");
  FigureEditor f(build_avatar_skeleton());
  ASSERT_TRUE(f.load(path)) << f.error();
  const int head = f.skeleton().find("t\xEAte");
  ASSERT_GE(head, 0);
  const std::string out = dir.file("out.bvh");
  try {
    f.save(out);
    ADD_FAILURE() << "saved a joint name that is not UTF-8";
  } catch (const Error& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find("joint 1's name is not UTF-8")) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(figure_sidecar_path(out)));
  ASSERT_TRUE(f.rename(head, "tete"));
  ASSERT_TRUE(f.rename(f.skeleton().find("t\xEAte_end"), "tete_end"));  // its End Site, named after it
  f.save(out);
  const Skeleton back = load_figure(out);
  ASSERT_EQ(3u, back.size());
  EXPECT_GE(back.find("tete"), 0);
  EXPECT_GT(std::abs(glm::dot(back.rest_rotations[static_cast<std::size_t>(back.find("tete"))],
                              f.skeleton().rest_rotations[static_cast<std::size_t>(head)])), 0.99999f);
}

TEST(LimbDrag, ARayThroughTheForearmPicksItAndDraggingTheWristReachesTheTarget) {
  const Skeleton s = build_avatar_skeleton();
  Pose pose = rest_pose(s);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  const int elbow = s.find("r_elbow"), wrist = s.find("r_wrist");
  const vec3 mid = 0.5f * (vec3(model[static_cast<std::size_t>(elbow)][3]) + vec3(model[static_cast<std::size_t>(wrist)][3]));
  // From in front of the avatar (it faces +Z), straight at the middle of the forearm.
  EXPECT_EQ(elbow, pick_bone(s, model, mid + vec3(0, 0, 2), vec3(0, 0, -1)));
  EXPECT_EQ(-1, pick_bone(s, model, mid + vec3(0, 1.5f, 2), vec3(0, 0, -1)));  // above the head
  const auto limb = limb_of(s, s.find("r_index2"));
  ASSERT_TRUE(limb);
  EXPECT_EQ(wrist, limb->end);
  EXPECT_TRUE(limb->arm);
  // The wrist in front of the chest.
  const vec3 shoulder(model[static_cast<std::size_t>(s.find("r_shoulder"))][3]);
  const vec3 target = shoulder + vec3(0.1f, -0.25f, 0.3f);
  const float left = drag_limb(s, pose, *limb, target);
  local_to_model(s, pose, model);
  EXPECT_LT(glm::length(vec3(model[static_cast<std::size_t>(wrist)][3]) - target), 0.01f);
  EXPECT_NEAR(left, glm::length(vec3(model[static_cast<std::size_t>(wrist)][3]) - target), 1e-4f);
  for (std::size_t j = 0; j < s.size(); ++j) EXPECT_TRUE(within_limits(s, static_cast<int>(j), pose.rotations[j])) << s.names[j];
  // A target far out of reach (or not a point) leaves a valid pose, pointing the arm at it.
  Pose far = rest_pose(s);
  EXPECT_GT(drag_limb(s, far, *limb, vec3(1e30f, 0.0f, 0.0f)), 1.0f);
  EXPECT_TRUE(std::isinf(drag_limb(s, far, *limb, vec3(NAN, 0.0f, 0.0f))));
  for (std::size_t j = 0; j < s.size(); ++j) EXPECT_TRUE(std::isfinite(far.rotations[j].w)) << s.names[j];
  // A foot.
  const auto leg = limb_of(s, s.find("l_knee"));
  ASSERT_TRUE(leg);
  EXPECT_FALSE(leg->arm);
}

}  // namespace
}  // namespace gestura::studio
