// User avatars (--avatar FILE.vrm|FILE.glb): gestura's own avatar is turned here into the kind of
// file people bring — raised into a T-pose, joints renamed VRoid-style, the face as ARKit-named
// blend shapes plus VRM vowel expressions — written as VRM 1.0, as VRM 0.x (facing -Z, thumb
// bones named the 0.x way) and as a plain GLB, then imported: the skeleton must come back on
// gestura's H-Anim joints with the arms hanging like the default's, the face mapped onto the face
// channels, and the notes must say what an avatar without fingers or face will not show.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gestura/io/avatar_import.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/gltf_export.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "support/build_paths.hpp"
#include "support/cli.hpp"
#include "support/signing_avatar.hpp"

namespace {

using namespace gestura;
using nlohmann::json;

// VRoid-style node names and their VRM humanoid bones (1.0 names).
struct Bone {
  const char* hanim;
  const char* node;
  const char* vrm;
};
std::vector<Bone> bones() {
  std::vector<Bone> b = {{"humanoid_root", "J_Bip_C_Hips", "hips"},     {"vl5", "J_Bip_C_Spine", "spine"},
                         {"vt12", "J_Bip_C_Chest", "chest"},            {"vt1", "J_Bip_C_UpperChest", "upperChest"},
                         {"vc7", "J_Bip_C_Neck", "neck"},               {"skullbase", "J_Bip_C_Head", "head"},
                         {"temporomandibular", "J_Adj_C_Jaw", "jaw"},   {"l_eyeball_joint", "J_Adj_L_FaceEye", "leftEye"},
                         {"r_eyeball_joint", "J_Adj_R_FaceEye", "rightEye"}};
  static std::vector<std::string> storage;
  if (storage.empty())
    for (const char* side : {"L", "R"}) {
      const std::string s = side, lr = s == "L" ? "left" : "right", h = s == "L" ? "l_" : "r_";
      const std::pair<std::string, std::string> parts[] = {
          {"sternoclavicular", "Shoulder"}, {"shoulder", "UpperArm"}, {"elbow", "LowerArm"}, {"wrist", "Hand"},
          {"hip", "UpperLeg"},              {"knee", "LowerLeg"},     {"ankle", "Foot"},      {"thumb1", "ThumbMetacarpal"},
          {"thumb2", "ThumbProximal"},      {"thumb3", "ThumbDistal"}};
      for (const auto& [ours, vrm] : parts) storage.insert(storage.end(), {h + ours, "J_Bip_" + s + "_" + vrm, lr + vrm});
      for (const auto& [ours, vrm] : {std::pair{"index", "Index"}, {"middle", "Middle"}, {"ring", "Ring"}, {"pinky", "Little"}})
        for (const auto& [k, seg] : {std::pair{"1", "Proximal"}, {"2", "Intermediate"}, {"3", "Distal"}})
          storage.insert(storage.end(), {h + ours + k, "J_Bip_" + s + "_" + vrm + seg, lr + vrm + seg});
    }
  for (std::size_t i = 0; i + 2 < storage.size(); i += 3) b.push_back({storage[i].c_str(), storage[i + 1].c_str(), storage[i + 2].c_str()});
  return b;
}

// ARKit names for gestura's morphs (ARKit has one browInnerUp: the left one stands for it).
const std::pair<const char*, const char*> kArkit[] = {
    {"eyeBlink_L", "eyeBlinkLeft"},   {"eyeBlink_R", "eyeBlinkRight"},     {"eyeWide_L", "eyeWideLeft"},
    {"eyeWide_R", "eyeWideRight"},    {"eyeSquint_L", "eyeSquintLeft"},    {"eyeSquint_R", "eyeSquintRight"},
    {"browInnerUp_L", "browInnerUp"}, {"browOuterUp_L", "browOuterUpLeft"}, {"browOuterUp_R", "browOuterUpRight"},
    {"browDown_L", "browDownLeft"},   {"browDown_R", "browDownRight"},     {"cheekPuff", "cheekPuff"},
    {"mouthSmile_L", "mouthSmileLeft"}, {"mouthSmile_R", "mouthSmileRight"}, {"mouthFrown_L", "mouthFrownLeft"},
    {"mouthFrown_R", "mouthFrownRight"}, {"mouthPucker", "mouthPucker"},   {"mouthOpen", "jawOpen"},
    {"tongueOut", "tongueOut"}};

// A .glb's JSON and binary chunks.
GltfDocument split_glb(const std::vector<std::uint8_t>& glb) {
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, glb.data() + at, 4);
    return v;
  };
  const std::uint32_t json_length = u32(12);
  GltfDocument d;
  d.json.assign(reinterpret_cast<const char*>(glb.data()) + 20, json_length);
  const std::size_t bin = 20 + json_length;
  d.buffer.assign(glb.begin() + static_cast<std::ptrdiff_t>(bin + 8), glb.begin() + static_cast<std::ptrdiff_t>(bin + 8 + u32(bin)));
  return d;
}

enum class Variant { Vrm1, Vrm0, PlainGlb, NoFingers, NoFace };

struct Made {
  std::string bytes;
  Avatar tposed;  // what was written, in gestura's names
};

// The default avatar with its arms raised sideways to a T-pose, made the bind pose.
Avatar t_posed() {
  Avatar a = test::signing_avatar().avatar;
  Skeleton& s = a.skeleton;
  std::vector<mat4> bind(s.size());
  local_to_model(s, rest_pose(s), bind);
  Pose pose = rest_pose(s);
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    const int sh = s.find(p + "shoulder"), el = s.find(p + "elbow");
    const vec3 dir = glm::normalize(vec3(bind[static_cast<std::size_t>(el)][3] - bind[static_cast<std::size_t>(sh)][3]));
    pose.rotations[static_cast<std::size_t>(sh)] = glm::rotation(dir, vec3(p == "l_" ? 1.0f : -1.0f, 0.0f, 0.0f));
  }
  std::vector<mat4> model(s.size()), skin(s.size());
  local_to_model(s, pose, model);
  for (std::size_t j = 0; j < s.size(); ++j) skin[j] = model[j] * glm::inverse(bind[j]);
  std::vector<vec3> positions(a.mesh.positions.size()), normals(a.mesh.normals.size());
  skin_positions_normals(skin, a.mesh.joints, a.mesh.weights, a.mesh.positions, a.mesh.normals, positions, normals);
  a.mesh.positions = positions;
  a.mesh.normals = normals;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const vec3 here(model[j][3]);
    s.rest_translations[j] = s.parents[j] < 0 ? here : here - vec3(model[static_cast<std::size_t>(s.parents[j])][3]);
  }
  return a;
}

Made make_file(Variant variant) {
  Made made;
  made.tposed = t_posed();
  Avatar a = made.tposed;
  // Names as such files have them.
  std::vector<Bone> mapped = bones();
  if (variant == Variant::NoFingers)  // finger bones left unnamed for the humanoid: plain "Bone.NNN"
    std::erase_if(mapped, [](const Bone& b) {
      const std::string h = b.hanim;
      return h.find("thumb") != std::string::npos || h.find("index") != std::string::npos || h.find("middle") != std::string::npos ||
             h.find("ring") != std::string::npos || h.find("pinky") != std::string::npos;
    });
  for (std::size_t j = 0; j < a.skeleton.size(); ++j) a.skeleton.names[j] = "Bone." + std::to_string(j);
  std::vector<std::pair<int, const Bone*>> nodes;
  for (const Bone& b : mapped) {
    const int j = test::signing_avatar().avatar.skeleton.find(b.hanim);
    a.skeleton.names[static_cast<std::size_t>(j)] = b.node;
    nodes.push_back({j, &b});
  }
  std::vector<MorphTarget> morphs;
  int aa = -1, oh = -1;
  if (variant != Variant::NoFace) {
    for (const auto& [ours, arkit] : kArkit) {
      MorphTarget m = a.mesh.morphs[static_cast<std::size_t>(a.mesh.find_morph(ours))];
      m.name = arkit;
      morphs.push_back(m);
    }
    for (const auto& [ours, vroid] : {std::pair{"aa", "Fcl_MTH_A"}, {"oh", "Fcl_MTH_O"}}) {
      MorphTarget m = a.mesh.morphs[static_cast<std::size_t>(a.mesh.find_morph(ours))];
      m.name = vroid;
      (std::string(ours) == "aa" ? aa : oh) = static_cast<int>(morphs.size());
      morphs.push_back(m);
    }
  }
  a.mesh.morphs = morphs;
  if (variant == Variant::Vrm0) {  // VRM 0.x looks down -Z
    const auto turn = [](vec3& v) { v = vec3(-v.x, v.y, -v.z); };
    for (vec3& t : a.skeleton.rest_translations) turn(t);
    for (vec3& p : a.mesh.positions) turn(p);
    for (vec3& n : a.mesh.normals) turn(n);
    for (MorphTarget& m : a.mesh.morphs) {
      for (vec3& d : m.position_deltas) turn(d);
      for (vec3& d : m.normal_deltas) turn(d);
    }
  }
  // gestura's own avatar export (materials, sparse morph targets), its JSON then given the extension.
  GltfDocument g = split_glb(encode_glb(a.skeleton, a.mesh));
  json doc = json::parse(g.json);
  const std::size_t mesh_node = a.skeleton.size();
  if (variant == Variant::Vrm1 || variant == Variant::NoFingers || variant == Variant::NoFace) {
    json human = json::object();
    for (const auto& [j, b] : nodes) human[b->vrm] = {{"node", j}};
    json presets = json::object();
    if (aa >= 0) {
      presets["aa"] = {{"morphTargetBinds", {{{"node", mesh_node}, {"index", aa}, {"weight", 1.0}}}}};
      presets["oh"] = {{"morphTargetBinds", {{{"node", mesh_node}, {"index", oh}, {"weight", 1.0}}}}};
    }
    doc["extensionsUsed"] = {"VRMC_vrm"};
    doc["extensions"]["VRMC_vrm"] = {{"specVersion", "1.0"},
                                     {"meta", {{"name", "gestura test"}, {"authors", {"gestura"}}, {"licenseUrl", "https://vrm.dev/licenses/1.0/"}}},
                                     {"humanoid", {{"humanBones", human}}},
                                     {"expressions", {{"preset", presets}}}};
  } else if (variant == Variant::Vrm0) {
    json human = json::array();
    for (const auto& [j, b] : nodes) {
      std::string vrm = b->vrm;  // 0.x spells the thumb one bone further out
      for (const std::string side : {"left", "right"}) {
        if (vrm == side + "ThumbProximal") vrm = side + "ThumbIntermediate";
        else if (vrm == side + "ThumbMetacarpal") vrm = side + "ThumbProximal";
      }
      human.push_back({{"bone", vrm}, {"node", j}});
    }
    doc["extensionsUsed"] = {"VRM"};
    doc["extensions"]["VRM"] = {
        {"exporterVersion", "gestura test"},
        {"humanoid", {{"humanBones", human}}},
        {"blendShapeMaster",
         {{"blendShapeGroups",
           {{{"name", "A"}, {"presetName", "a"}, {"binds", {{{"mesh", 0}, {"index", aa}, {"weight", 100}}}}},
            {{"name", "O"}, {"presetName", "o"}, {"binds", {{{"mesh", 0}, {"index", oh}, {"weight", 100}}}}}}}}}};
  } else {
    // Plain GLB: Mixamo names, no extension.
    for (const auto& [j, b] : nodes) {
      std::string h = b->hanim;
      const std::pair<const char*, const char*> mixamo[] = {
          {"humanoid_root", "mixamorig:Hips"}, {"vl5", "mixamorig:Spine"}, {"vt12", "mixamorig:Spine1"},
          {"vt1", "mixamorig:Spine2"}, {"vc7", "mixamorig:Neck"}, {"skullbase", "mixamorig:Head"},
          {"l_sternoclavicular", "mixamorig:LeftShoulder"}, {"l_shoulder", "mixamorig:LeftArm"},
          {"l_elbow", "mixamorig:LeftForeArm"}, {"l_wrist", "mixamorig:LeftHand"},
          {"r_sternoclavicular", "mixamorig:RightShoulder"}, {"r_shoulder", "mixamorig:RightArm"},
          {"r_elbow", "mixamorig:RightForeArm"}, {"r_wrist", "mixamorig:RightHand"}};
      for (const auto& [ours, theirs] : mixamo)
        if (h == ours) doc["nodes"][static_cast<std::size_t>(j)]["name"] = theirs;
    }
  }
  g.json = doc.dump();
  made.bytes = pack_glb(g);
  return made;
}

const Made& made(Variant v) {
  static std::map<Variant, Made> cache;
  if (!cache.contains(v)) cache[v] = make_file(v);
  return cache.at(v);
}

ImportedAvatar imported(Variant v) {
  return import_avatar(read_rigged_gltf(made(v).bytes, "test.vrm"), "test.vrm");
}

vec3 joint_at(const Avatar& a, const char* name) {
  const std::vector<vec3> p = rest_joint_positions(a.skeleton);
  const int j = a.skeleton.find(name);
  EXPECT_GE(j, 0) << name;
  return j >= 0 ? p[static_cast<std::size_t>(j)] : vec3(0.0f);
}

void expect_like_the_default(const Avatar& a) {
  const Avatar& ref = test::signing_avatar().avatar;
  a.skeleton.validate();
  // Every joint the signing rig needs, and the rig builds.
  EXPECT_NO_THROW(make_signing_rig(a));
  // Standing on the floor, facing +Z, the left side at +X, the arms hanging like the default's.
  EXPECT_NEAR(a.params.height, ref.params.height, 0.03f);
  EXPECT_GT(joint_at(a, "l_wrist").x, 0.1f);
  EXPECT_LT(joint_at(a, "r_wrist").x, -0.1f);
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    const auto dir = [&](const Avatar& x, const std::string& from, const std::string& to) {
      return glm::normalize(joint_at(x, to.c_str()) - joint_at(x, from.c_str()));
    };
    EXPECT_GT(glm::dot(dir(a, p + "shoulder", p + "elbow"), dir(ref, p + "shoulder", p + "elbow")), std::cos(deg(3.0f))) << side;
    EXPECT_GT(glm::dot(dir(a, p + "elbow", p + "wrist"), dir(ref, p + "elbow", p + "wrist")), std::cos(deg(3.0f))) << side;
    EXPECT_GT(glm::dot(dir(a, p + "wrist", p + "middle1"), dir(ref, p + "wrist", p + "middle1")), std::cos(deg(5.0f))) << side;
    // The arm's skin came down with the bones: the middle finger's tip is near the thigh.
    EXPECT_LT(glm::distance(joint_at(a, (p + "middle_tip").c_str()), joint_at(ref, (p + "middle_tip").c_str())), 0.05f) << side;
  }
  const vec3 nose_side = joint_at(a, "skullbase");
  EXPECT_NEAR(nose_side.x, 0.0f, 0.01f);
}

TEST(AvatarImport, Vrm1InTPoseComesBackOnTheSigningSkeleton) {
  const ImportedAvatar v = imported(Variant::Vrm1);
  expect_like_the_default(v.avatar);
  // Joints the file lacked were added between its own: lumbar, thoracic, neck.
  for (const char* j : {"vl3", "vt6", "vc4", "l_index_tip", "skull_tip"}) EXPECT_GE(v.avatar.skeleton.find(j), 0) << j;
  // Materials from the file's material names: the shirt stays cloth, the hair hair.
  const auto& mats = v.avatar.mesh.materials;
  EXPECT_GT(std::count(mats.begin(), mats.end(), static_cast<std::uint8_t>(MaterialId::Cloth)), 1000);
  EXPECT_GT(std::count(mats.begin(), mats.end(), static_cast<std::uint8_t>(MaterialId::Hair)), 100);
  // The face: every channel made (ARKit shapes, visemes mixed, vowels from the expressions).
  for (const char* channel : {"aa", "oh", "E", "PP", "eyeBlink_L", "browInnerUp_R", "mouthOpen", "mouthSmile_L", "tongueOut"})
    EXPECT_GE(v.avatar.mesh.find_morph(channel), 0) << channel;
  const bool notes_mention_missing = std::any_of(v.notes.begin(), v.notes.end(), [](const std::string& n) {
    return n.find("no face") != std::string::npos || n.find("no finger") != std::string::npos;
  });
  EXPECT_FALSE(notes_mention_missing);
  // The jawOpen-made mouthOpen moves the lower lip down by what the original did.
  const Avatar& ref = test::signing_avatar().avatar;
  const MorphTarget& ours = v.avatar.mesh.morphs[static_cast<std::size_t>(v.avatar.mesh.find_morph("mouthOpen"))];
  const MorphTarget& theirs = ref.mesh.morphs[static_cast<std::size_t>(ref.mesh.find_morph("mouthOpen"))];
  float lowest_ours = 0.0f, lowest_theirs = 0.0f;
  for (const vec3& d : ours.position_deltas) lowest_ours = std::min(lowest_ours, d.y);
  for (const vec3& d : theirs.position_deltas) lowest_theirs = std::min(lowest_theirs, d.y);
  EXPECT_NEAR(lowest_ours, lowest_theirs, 1e-4f);
}

TEST(AvatarImport, Vrm0FacingMinusZIsTurnedAndItsThumbsNamedRight) {
  const ImportedAvatar v = imported(Variant::Vrm0);
  expect_like_the_default(v.avatar);
  EXPECT_GE(v.avatar.mesh.find_morph("aa"), 0);
  // The thumb's first joint is the metacarpal one: nearest the wrist.
  EXPECT_LT(glm::distance(joint_at(v.avatar, "l_thumb1"), joint_at(v.avatar, "l_wrist")),
            glm::distance(joint_at(v.avatar, "l_thumb2"), joint_at(v.avatar, "l_wrist")));
  // The face looks to +Z: the nose tip (the most forward head vertex) is in front of the skull base.
  float front = -1e9f;
  for (std::size_t i = 0; i < v.avatar.mesh.positions.size(); ++i)
    if (v.avatar.mesh.positions[i].y > joint_at(v.avatar, "skullbase").y) front = std::max(front, v.avatar.mesh.positions[i].z);
  EXPECT_GT(front, joint_at(v.avatar, "skullbase").z + 0.05f);
}

TEST(AvatarImport, PlainGlbWithMixamoNamesIsRecognised) {
  const ImportedAvatar v = imported(Variant::PlainGlb);
  // Only the arm and spine bones carry Mixamo names here: the fingers stay "Bone.N", so the note says so.
  EXPECT_GE(v.avatar.skeleton.find("l_shoulder"), 0);
  EXPECT_NO_THROW(make_signing_rig(v.avatar));
  EXPECT_TRUE(std::any_of(v.notes.begin(), v.notes.end(), [](const std::string& n) { return n.find("no finger bones") != std::string::npos; }));
  EXPECT_GE(v.avatar.mesh.find_morph("eyeBlink_L"), 0) << "ARKit names need no VRM extension";
}

TEST(AvatarImport, NotesSayWhatAnAvatarWithoutFingersOrFaceWillNotShow) {
  const ImportedAvatar fingers = imported(Variant::NoFingers);
  int finger_notes = 0;
  for (const std::string& n : fingers.notes) finger_notes += n.find("has no finger bones: handshapes will not show") != std::string::npos;
  EXPECT_EQ(finger_notes, 2) << "one per hand";
  EXPECT_NO_THROW(make_signing_rig(fingers.avatar)) << "signs still place and move the hands";
  const ImportedAvatar face = imported(Variant::NoFace);
  EXPECT_TRUE(std::any_of(face.notes.begin(), face.notes.end(), [](const std::string& n) {
    return n.find("no face shapes") != std::string::npos && n.find("mouthing") != std::string::npos;
  }));
  EXPECT_LT(face.avatar.mesh.find_morph("aa"), 0);
}

TEST(AvatarImport, ARigWithoutArmsIsANamedError) {
  // A mesh with a two-joint rig: hips and head only.
  Skeleton s;
  s.add_joint("Hips", -1, vec3(0, 1, 0));
  s.add_joint("Head", 0, vec3(0, 0.6f, 0));
  Mesh m;
  m.positions = {vec3(0, 1, 0), vec3(0.1f, 1, 0), vec3(0, 1.6f, 0)};
  m.normals.assign(3, vec3(0, 0, 1));
  m.materials.assign(3, 0);
  m.joints.assign(3, JointIndices(0));
  m.weights.assign(3, vec4(1, 0, 0, 0));
  m.indices = {0, 1, 2};
  Clip still;
  still.resize_joints(2);
  try {
    import_avatar(read_rigged_gltf(pack_glb(make_gltf(s, still, &m)), "stick.glb"), "stick.glb");
    ADD_FAILURE() << "accepted a rig without arms";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("stick.glb: the rig has no bone for the left upper arm"), std::string::npos) << e.what();
  }
}

TEST(AvatarImportCli, EveryAvatarCommandTakesAVrmFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gestura_import_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string vrm = (dir / "signer.vrm").string(), glb = (dir / "signer.glb").string();
  std::ofstream(vrm, std::ios::binary) << made(Variant::Vrm1).bytes;
  std::ofstream(glb, std::ios::binary) << made(Variant::NoFingers).bytes;
  const test::CliRun render = test::run_cli("render --rest --size 320x180 --avatar '" + vrm + "' -o '" + (dir / "rest.png").string() + "'");
  EXPECT_EQ(render.status, 0) << render.output;
  EXPECT_NE(render.output.find("note: " + vrm + ": VRM 1.0 avatar"), std::string::npos) << render.output;
  const test::CliRun say = test::run_cli("say house --avatar '" + vrm + "' -o '" + (dir / "house.json").string() + "'");
  EXPECT_EQ(say.status, 0) << say.output;
  const test::CliRun sign = test::run_cli("sign --names hamflathand,hamextfingeru,hampalml,hamchest --avatar '" + glb + "' -o '" +
                                          (dir / "sign.bvh").string() + "'");
  EXPECT_EQ(sign.status, 0) << sign.output;
  EXPECT_NE(sign.output.find("no finger bones"), std::string::npos) << sign.output;
  const test::CliRun info = test::run_cli("avatar info --avatar '" + vrm + "'");
  EXPECT_EQ(info.status, 0) << info.output;
  const test::CliRun missing = test::run_cli("render --rest --avatar '" + (dir / "nope.vrm").string() + "' -o '" + (dir / "x.png").string() + "'");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("nope.vrm: cannot open"), std::string::npos) << missing.output;
  std::filesystem::remove_all(dir);
}

TEST(AvatarImport, TheTestFilesAreValidGltf) {
  if (!std::filesystem::exists(gestura::test::source_dir() + "/tools/node_modules/gltf-validator"))
    GTEST_SKIP() << "tools/node_modules/gltf-validator missing (cd tools && npm install)";
  for (Variant v : {Variant::Vrm1, Variant::Vrm0}) {
    const std::string path = (std::filesystem::temp_directory_path() / ("gestura_import_" + std::to_string(getpid()) + ".vrm")).string();
    std::ofstream(path, std::ios::binary) << made(v).bytes;
    const test::CliRun r = test::run_command("node '" + gestura::test::source_dir() + "/tools/validate-gltf.mjs' '" + path + "'");
    std::filesystem::remove(path);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("\"numErrors\": 0"), std::string::npos) << r.output;
  }
}

}  // namespace
