#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/makehuman.hpp"
#include "gestura/io/makehuman_face.hpp"
#include "gestura/skeleton/joint_names_makehuman.hpp"
#include "support/shared_data.hpp"

using namespace gestura;

namespace {

const std::string kDir = gestura::test::shared_data() + "/makehuman";

// Loaded once for the suite: the asset is 2.6 MB of text.
class MakeHuman : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (std::filesystem::exists(kDir + "/base.obj")) body_ = std::make_unique<MakeHumanBody>(load_makehuman(kDir));
  }
  static void TearDownTestSuite() { body_.reset(); }
  void SetUp() override {
    if (!body_) GTEST_SKIP() << "no MakeHuman data at " << kDir;
  }
  static std::unique_ptr<MakeHumanBody> body_;
};
std::unique_ptr<MakeHumanBody> MakeHuman::body_;

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_F(MakeHuman, BaseMeshHasAllVerticesInMetres) {
  const Mesh& m = body_->mesh.mesh;
  EXPECT_EQ(m.vertex_count(), 19158u);
  EXPECT_EQ(m.normals.size(), 19158u);
  EXPECT_EQ(m.triangle_count(), 2u * 18486u);  // every face of base.obj is a quad
  float lo = 1e9f, hi = -1e9f;
  for (const vec3& p : m.positions) {
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  EXPECT_GT(hi - lo, 1.5f);  // a person of 1.5–2 m, not 17 decimetre units
  EXPECT_LT(hi - lo, 2.0f);
  for (const vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
}

TEST_F(MakeHuman, BodyFilterKeepsTheBodyGroup) {
  ASSERT_GE(body_->mesh.find_group("body"), 0);
  EXPECT_GE(body_->mesh.find_group("helper-tights"), 0);
  const std::string_view body[] = {"body"};
  std::vector<std::uint32_t> original;
  const GroupedMesh only = keep_groups(body_->mesh, body, &original);
  EXPECT_EQ(only.mesh.vertex_count(), 13380u);
  EXPECT_EQ(only.groups.size(), 1u);
  ASSERT_EQ(original.size(), 13380u);
  EXPECT_EQ(only.mesh.positions[100], body_->mesh.mesh.positions[original[100]]);
  EXPECT_EQ(only.mesh.joints.size(), 13380u);
  for (std::uint32_t i : only.mesh.indices) ASSERT_LT(i, 13380u);
}

TEST_F(MakeHuman, RigHas163BonesInParentOrderAndValidates) {
  const MakeHumanRig& rig = body_->rig;
  EXPECT_EQ(rig.bone_count, 163u);
  EXPECT_EQ(rig.skeleton.size(), 173u);  // + 10 finger tip sites
  EXPECT_NO_THROW(rig.skeleton.validate());
  EXPECT_EQ(rig.inverse_bind.size(), rig.skeleton.size());
  EXPECT_EQ(rig.makehuman_names[0], "root");
  // FK of the rest pose puts every joint at its head; inverse bind undoes it.
  std::vector<mat4> model(rig.skeleton.size());
  local_to_model(rig.skeleton, rest_pose(rig.skeleton), model);
  for (std::size_t j = 0; j < model.size(); ++j) {
    ASSERT_NEAR(glm::distance(vec3(model[j][3]), rig.heads[j]), 0.0f, 1e-5f) << rig.skeleton.names[j];
    const mat4 skin = model[j] * rig.inverse_bind[j];
    ASSERT_NEAR(glm::length(vec3(skin[3])), 0.0f, 1e-5f);
  }
}

TEST_F(MakeHuman, MappedNamesExistAndSitAnatomically) {
  const Skeleton& s = body_->rig.skeleton;
  for (const char* name : {"humanoid_root", "skullbase", "l_wrist", "r_wrist", "l_elbow", "l_shoulder", "r_index3",
                           "l_thumb1", "r_pinky3", "l_hip", "r_knee", "l_ankle", "vl5", "vc4", "temporomandibular",
                           "l_index_tip", "r_thumb_tip", "l_levator02"})
    EXPECT_GE(s.find(name), 0) << name;
  for (const JointNamePair& pair : makehuman_hanim_names())
    EXPECT_GE(s.find(pair.hanim), 0) << pair.makehuman << " → " << pair.hanim;
  const auto at = [&](const char* name) { return body_->rig.heads[static_cast<std::size_t>(s.find(name))]; };
  EXPECT_GT(at("l_wrist").x, 0.3f);  // the avatar's left is +X
  EXPECT_LT(at("r_wrist").x, -0.3f);
  EXPECT_GT(at("skullbase").y, at("vc4").y);
  EXPECT_GT(at("l_elbow").y, at("l_wrist").y);
  EXPECT_EQ(s.parents[static_cast<std::size_t>(s.find("l_index2"))], s.find("l_index1"));
  EXPECT_EQ(s.parents[static_cast<std::size_t>(s.find("l_index_tip"))], s.find("l_index3"));
}

TEST_F(MakeHuman, WeightsAreFourNormalisedInfluencesOnEveryVertex) {
  const Mesh& m = body_->mesh.mesh;
  ASSERT_EQ(m.joints.size(), m.vertex_count());
  ASSERT_EQ(m.weights.size(), m.vertex_count());
  EXPECT_NO_THROW(check_influences(m.joints, m.weights, body_->rig.bone_count, 1e-5f));
  std::size_t multi = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const vec4 w = m.weights[v];
    ASSERT_GT(w.x, 0.0f);
    ASSERT_GE(w.x, w.y);
    ASSERT_GE(w.y, w.z);
    ASSERT_GE(w.z, w.w);
    multi += w.y > 0.0f;
  }
  EXPECT_GT(multi, 5000u);  // blended skin, not rigid parts
  // A fingertip vertex follows a finger bone of the same hand.
  const std::size_t tip = static_cast<std::size_t>(body_->rig.skeleton.find("l_index_tip"));
  const vec3 tip_at = body_->rig.heads[tip];
  std::size_t nearest = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    if (glm::distance(m.positions[v], tip_at) < glm::distance(m.positions[nearest], tip_at)) nearest = v;
  EXPECT_EQ(body_->rig.skeleton.names[m.joints[nearest].x].rfind("l_", 0), 0u)
      << body_->rig.skeleton.names[m.joints[nearest].x];
}

TEST(MakeHumanFace, PoseUnitsAndExpressions) {
  if (!std::filesystem::exists(kDir + "/poseunits/face-poseunits.bvh")) GTEST_SKIP() << "no MakeHuman data";
  const FacePoseUnits units =
      read_makehuman_face_units(kDir + "/poseunits/face-poseunits.json", kDir + "/poseunits/face-poseunits.bvh");
  EXPECT_EQ(units.units.size(), 60u);
  EXPECT_EQ(units.units[0], "Rest");
  EXPECT_EQ(units.bones.size(), 163u);
  ASSERT_GE(units.find_unit("JawDrop"), 0);
  const int jaw = units.find_bone("jaw");
  ASSERT_GE(jaw, 0);
  // JawDrop turns the jaw; Rest leaves it alone.
  const quat rest_jaw = units.unit(0)[static_cast<std::size_t>(jaw)];
  const quat drop_jaw = units.unit(static_cast<std::size_t>(units.find_unit("JawDrop")))[static_cast<std::size_t>(jaw)];
  EXPECT_NEAR(std::abs(rest_jaw.w), 1.0f, 1e-4f);
  EXPECT_GT(glm::angle(drop_jaw), deg(5.0f));
  // Opening the mouth turns the jaw about the left-right axis (x) and moves the chin down.
  const vec3 chin = drop_jaw * vec3(0, -0.7f, 0.6f);
  EXPECT_LT(chin.y, -0.7f);
  // Eye units check the Z-up → Y-up conversion: the left eye's gaze (+Z at rest) goes up for
  // LeftEyeUp and towards the avatar's left (+X) for LeftEyeturnLeft; the right eye stays.
  const auto gaze = [&](const char* unit, const char* bone) {
    return units.unit(static_cast<std::size_t>(units.find_unit(unit)))[static_cast<std::size_t>(units.find_bone(bone))] *
           vec3(0, 0, 1);
  };
  EXPECT_GT(gaze("LeftEyeUp", "eye.L").y, 0.2f);
  EXPECT_LT(gaze("LeftEyeDown", "eye.L").y, -0.2f);
  EXPECT_GT(gaze("LeftEyeturnLeft", "eye.L").x, 0.2f);
  EXPECT_GT(gaze("LeftEyeturnLeft", "eye.R").z, 0.999f);

  const std::vector<FaceExpression> expressions = read_makehuman_expressions(kDir + "/expressions");
  ASSERT_EQ(expressions.size(), 32u);
  EXPECT_EQ(expressions[0].name, "anger01");
  std::vector<quat> pose(units.bones.size());
  for (const FaceExpression& e : expressions) EXPECT_NO_THROW(expression_rotations(units, e, pose)) << e.name;
  const FaceExpression& anger = expressions[0];
  const auto it = std::find(anger.units.begin(), anger.units.end(), "UpperLipUp");
  ASSERT_NE(it, anger.units.end());
  EXPECT_FLOAT_EQ(anger.weights[static_cast<std::size_t>(it - anger.units.begin())], 1.0f);
}

TEST(MakeHumanErrors, MalformedObjNamesLineAndColumn) {
  EXPECT_EQ(error_of([] { parse_grouped_obj("v 0 0 0\nv 1 0 x\n", "bad.obj"); }),
            "bad.obj:2:7: expected a finite number");
  EXPECT_EQ(error_of([] { parse_grouped_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "bad.obj"); }),
            "bad.obj:4:7: vertex index 4 out of range (3 defined)");
  EXPECT_EQ(error_of([] { parse_grouped_obj("v 0 0 0\nv 1 0 0\nf 1 2\n", "bad.obj"); }),
            "bad.obj:3:6: face with fewer than 3 corners");
  EXPECT_EQ(error_of([] { parse_grouped_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/5 2 3\n", "bad.obj"); }),
            "bad.obj:4:5: texture coordinate index 5 out of range (0 defined)");
  EXPECT_EQ(error_of([] { parse_grouped_obj(std::string("\x7f\x45LF\0\x01", 6), "junk.obj"); }), "junk.obj: no vertices");
  EXPECT_EQ(error_of([] { read_grouped_obj("/nonexistent/base.obj"); }), "/nonexistent/base.obj: cannot open file");
  // A good one: a quad becomes two triangles, units scale, negative indices are relative.
  const GroupedMesh quad = parse_grouped_obj("g a\nv 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\nf -4 -3 -2 -1\n", "q.obj");
  EXPECT_EQ(quad.mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_FLOAT_EQ(quad.mesh.positions[2].x, 1.0f);
  EXPECT_EQ(quad.mesh.normals[0], vec3(0, 0, 1));
}

TEST(MakeHumanErrors, MalformedRigNamesLineOrField) {
  const std::vector<vec3> positions(4, vec3(0.0f));
  EXPECT_EQ(error_of([&] { parse_makehuman_rig("{\n  \"bones\": {,\n}", "bad.mhskel", positions); }).rfind(
                "bad.mhskel:2:13: invalid JSON", 0),
            0u);
  // A number past a double's range is another kind of JSON library exception (found by fuzzing
  // the OpenPose reader, which had the same gap); it too is a located error.
  EXPECT_EQ(error_of([&] { parse_makehuman_rig("{\"bones\": 1e999999}", "big.mhskel", positions); }).rfind(
                "big.mhskel: invalid JSON", 0),
            0u);
  const std::string missing_parent = R"({"bones": {"a": {"head": "a_h", "tail": "a_t", "parent": "zz"}},
                                         "joints": {"a_h": [0], "a_t": [1]}})";
  EXPECT_EQ(error_of([&] { parse_makehuman_rig(missing_parent, "r.mhskel", positions); }),
            "r.mhskel: field 'bones.a.parent': unknown bone 'zz'");
  const std::string bad_vertex = R"({"bones": {"a": {"head": "a_h", "tail": "a_t", "parent": null}},
                                     "joints": {"a_h": [0], "a_t": [9]}})";
  EXPECT_EQ(error_of([&] { parse_makehuman_rig(bad_vertex, "r.mhskel", positions); }),
            "r.mhskel: field 'joints.a_t[0]': expected a vertex index below 4");
  const std::string no_tail = R"({"bones": {"a": {"head": "a_h", "parent": null}}, "joints": {"a_h": [0]}})";
  EXPECT_EQ(error_of([&] { parse_makehuman_rig(no_tail, "r.mhskel", positions); }),
            "r.mhskel: field 'bones.a.tail': missing");
  const std::string cycle = R"({"bones": {"a": {"head": "h", "tail": "h", "parent": "b"},
                                          "b": {"head": "h", "tail": "h", "parent": "a"}}, "joints": {"h": [0]}})";
  EXPECT_NE(error_of([&] { parse_makehuman_rig(cycle, "r.mhskel", positions); }).find("cycle"), std::string::npos);

  // A valid two-bone rig, then its weights: top four kept, renormalised, bad entries named.
  const std::vector<vec3> line{vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 2, 0), vec3(0, 3, 0)};
  const std::string two = R"({"bones": {"b": {"head": "b_h", "tail": "b_t", "parent": "a"},
                                         "a": {"head": "a_h", "tail": "b_h", "parent": null}},
                              "joints": {"a_h": [0], "b_h": [1, 2], "b_t": [3]}})";
  const MakeHumanRig rig = parse_makehuman_rig(two, "two.mhskel", line);
  ASSERT_EQ(rig.skeleton.size(), 2u);
  EXPECT_EQ(rig.makehuman_names[0], "a");  // parents first whatever the file order
  EXPECT_NEAR(rig.heads[1].y, 1.5f, 1e-6f);
  Mesh mesh;
  mesh.positions = line;
  parse_makehuman_weights(R"({"weights": {"a": [[0, 1.0], [1, 0.3]], "b": [[1, 0.9]]}})", "w.mhw", rig, mesh);
  EXPECT_EQ(mesh.joints[1], JointIndices(1, 0, 0, 0));
  EXPECT_NEAR(mesh.weights[1].x, 0.75f, 1e-6f);
  EXPECT_NEAR(mesh.weights[1].y, 0.25f, 1e-6f);
  EXPECT_EQ(mesh.weights[3], vec4(1, 0, 0, 0));  // unweighted → root
  EXPECT_EQ(error_of([&] { parse_makehuman_weights(R"({"weights": {"a": [[7, 1.0]]}})", "w.mhw", rig, mesh); }),
            "w.mhw: field 'weights.a[0]': vertex 7 outside the mesh (4)");
  EXPECT_EQ(error_of([&] { parse_makehuman_weights(R"({"weights": {"q": []}})", "w.mhw", rig, mesh); }),
            "w.mhw: field 'weights.q': no bone of that name in the rig");
}

TEST(MakeHumanErrors, MalformedFaceFiles) {
  const std::string json = R"({"framemapping": ["Rest", "Up"]})";
  const std::string bvh = "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 3 Xrotation Yrotation Zrotation\n}\n"
                          "MOTION\nFrames: 2\nFrame Time: 0.04\n0 0 0\n90 0 0\n";
  const FacePoseUnits ok = parse_makehuman_face_units(json, "f.json", bvh, "f.bvh");
  ASSERT_EQ(ok.rotations.size(), 2u);
  // 90° about BVH x is 90° about our x (the axis change maps x to x).
  const vec3 turned = ok.rotations[1] * vec3(0, 1, 0);
  EXPECT_NEAR(turned.z, 1.0f, 1e-5f);
  EXPECT_EQ(error_of([&] { parse_makehuman_face_units(json, "f.json", bvh.substr(0, bvh.size() - 3), "f.bvh"); }),
            "f.bvh:11: unexpected end of file");
  std::string bad = bvh;
  bad.replace(bad.find("90"), 2, "9x");
  EXPECT_EQ(error_of([&] { parse_makehuman_face_units(json, "f.json", bad, "f.bvh"); }),
            "f.bvh:11: expected a number, found '9x'");
  EXPECT_EQ(error_of([&] { parse_makehuman_expression(R"({"name": "x", "unit_poses": {"Up": "high"}})", "e.mhpose"); }),
            "e.mhpose: field 'unit_poses.Up': expected a number");
}

TEST(JointNamesMakeHuman, TableFirstThenSideSuffixBecomesPrefix) {
  EXPECT_EQ(joint_name_from_makehuman("wrist.L"), "l_wrist");
  EXPECT_EQ(joint_name_from_makehuman("finger2-3.R"), "r_index3");
  EXPECT_EQ(joint_name_from_makehuman("finger1-1.L"), "l_thumb1");
  EXPECT_EQ(joint_name_from_makehuman("upperarm01.R"), "r_shoulder");
  EXPECT_EQ(joint_name_from_makehuman("head"), "skullbase");
  EXPECT_EQ(joint_name_from_makehuman("levator02.L"), "l_levator02");
  EXPECT_EQ(joint_name_from_makehuman("upperarm02.R"), "r_upperarm02");
  EXPECT_EQ(joint_name_from_makehuman("tongue00"), "tongue00");
}

TEST_F(MakeHuman, BendingTheElbowMovesTheForearmRigidlyAndNothingElse) {
  const MakeHumanRig& rig = body_->rig;
  const Mesh& m = body_->mesh.mesh;
  const Skeleton& s = rig.skeleton;
  const int elbow = s.find("l_elbow");
  ASSERT_GE(elbow, 0);
  // Joints below the elbow (parents come first, so one forward pass marks the subtree).
  std::vector<bool> below(s.size(), false);
  below[static_cast<std::size_t>(elbow)] = true;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.parents[j] >= 0 && below[static_cast<std::size_t>(s.parents[j])]) below[j] = true;
  Pose pose = rest_pose(s);
  const quat bend = glm::angleAxis(deg(90.0f), vec3(0, 1, 0));
  pose.rotations[static_cast<std::size_t>(elbow)] = bend;
  std::vector<mat4> model(s.size()), skin(s.size());
  local_to_model(s, pose, model);
  skinning_matrices(model, rig.inverse_bind, skin);
  std::vector<vec3> out(m.vertex_count());
  skin_positions(skin, m.joints, m.weights, m.positions, out);
  const vec3 pivot = rig.heads[static_cast<std::size_t>(elbow)];
  std::size_t moved = 0, still = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    bool all_below = true, none_below = true;
    for (int k = 0; k < 4; ++k) {
      if (m.weights[v][k] == 0.0f) continue;
      const bool b = below[m.joints[v][k]];
      all_below = all_below && b;
      none_below = none_below && !b;
    }
    if (all_below) {
      ASSERT_NEAR(glm::distance(out[v], pivot + bend * (m.positions[v] - pivot)), 0.0f, 1e-5f) << v;
      ++moved;
    } else if (none_below) {
      ASSERT_NEAR(glm::distance(out[v], m.positions[v]), 0.0f, 1e-5f) << v;
      ++still;
    }
  }
  EXPECT_GT(moved, 500u);   // forearm and hand
  EXPECT_GT(still, 10000u);  // the rest of the body
}
