// Writes the seed corpora of the fuzz targets and their dictionaries, made at run time from the
// shared test data (read in place, never copied into the repository) and from gestura's own
// outputs (motions, avatars, compressed clips, keypoints written by the library).
//
//   gestura-fuzz-seeds SHARED_DATA SOURCE_DIR OUT
//
// OUT/<target>/ holds the seeds of one target, OUT/<target>.dict its libFuzzer dictionary.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/body/avatar_skeleton.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/io/bap.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/openpose_json.hpp"
#include "gestura/io/pose_format.hpp"
#include "gestura/sign/hamnosys_symbol.hpp"
#include "gestura/studio/figure_model.hpp"
#include "gestura/core/utf8.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path g_out;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Seeds are named by content, so a seed that two sources share is written once.
void seed(const std::string& target, const std::string& bytes) {
  if (bytes.empty()) return;
  const fs::path dir = g_out / target;
  fs::create_directories(dir);
  char name[32];
  std::snprintf(name, sizeof name, "%016zx", std::hash<std::string>{}(bytes));
  std::ofstream(dir / name, std::ios::binary) << bytes;
}

void dictionary(const std::string& target, const std::set<std::string>& tokens) {
  fs::create_directories(g_out);
  std::ofstream out(g_out / (target + ".dict"));
  for (const std::string& token : tokens) {
    out << '"';
    for (const unsigned char c : token) {
      if (c == '"' || c == '\\') out << '\\' << c;
      else if (c < 0x20 || c >= 0x7f) {
        char hex[5];
        std::snprintf(hex, sizeof hex, "\\x%02X", c);
        out << hex;
      } else out << c;
    }
    out << "\"\n";
  }
}

void for_each_line(const fs::path& path, const std::function<void(const std::string&)>& each) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) each(line);
}

// ---- notation ---------------------------------------------------------------------------------

void hamnosys_seeds(const fs::path& shared, const fs::path& source) {
  auto from_entry = [](const json& j) {
    const std::string text = j.value("hamnosys", "");
    if (!text.empty()) seed("hamnosys_unicode", text);
    const std::string names = j.value("names", "");
    if (!names.empty() && names != "None") seed("hamnosys_names", names);
  };
  for_each_line(shared / "hamnosys" / "signs.jsonl", [&](const std::string& line) { from_entry(json::parse(line)); });
  for (const auto& file : fs::directory_iterator(source / "data" / "lexicon"))
    if (file.path().extension() == ".jsonl")
      for_each_line(file.path(), [&](const std::string& line) { from_entry(json::parse(line)); });

  std::set<std::string> names{",", " "}, code_points, sigml_tokens;
  for (const gestura::sign::SymbolInfo& s : gestura::sign::symbol_table()) {
    names.insert(std::string(s.name));
    std::string utf8;
    gestura::utf8::append(utf8, s.codepoint);
    code_points.insert(utf8);
    sigml_tokens.insert("<" + std::string(s.name) + "/>");
  }
  dictionary("hamnosys_names", names);
  dictionary("hamnosys_unicode", code_points);
  for (const char* t : {"<sigml>", "</sigml>", "<hns_sign gloss=\"", "\">", "</hns_sign>", "<hamnosys_manual>",
                        "</hamnosys_manual>", "<hamnosys_nonmanual>", "</hamnosys_nonmanual>", "<hnm_mouthpicture picture=\"",
                        "<hnm_head tag=\"", "<hnm_eyebrows tag=\"", "<hamgestural_sign gloss=\"", "</hamgestural_sign>",
                        "<sign_manual", " both_hands=\"true\"", " lr_symm=\"true\"", " nondominant=\"true\"", "</sign_manual>",
                        "<sign_nonmanual>", "<handconfig handshape=\"", " extfidir=\"", " palmor=\"", " thumbpos=\"",
                        " mainbend=\"", "<location_bodyarm location=\"", " contact=\"", "<directedmotion direction=\"",
                        "<circularmotion axis=\"", "<tgt_motion>", "</tgt_motion>", "<rpt_motion repetition=\"",
                        "fromstart", "fromstart_several", "continue", "reverse", "<changeposture/>", "<par_motion>",
                        "<seq_motion>", "<![CDATA[", "]]>", "<!--", "-->", "&amp;", "&#x", "<?xml version=\"1.0\"?>"})
    sigml_tokens.insert(t);
  dictionary("sigml", sigml_tokens);
  dictionary("lexicon_sigml", sigml_tokens);
}

void sigml_seeds(const fs::path& shared) {
  for (const auto& file : fs::directory_iterator(shared / "sigml-isl")) {
    const std::string text = read_text(file.path());
    seed("sigml", text);
    seed("lexicon_sigml", text);
  }
  // The gestural form, written here.
  seed("sigml", R"(<sigml><hamgestural_sign gloss="wave"><sign_manual both_hands="true" lr_symm="true">
<handconfig handshape="flat" extfidir="u" palmor="l"/><location_bodyarm location="shoulders" contact="close"/>
<rpt_motion repetition="fromstart"><directedmotion direction="o"/></rpt_motion></sign_manual>
<sign_nonmanual><head_tier><head_movement movement="NO"/></head_tier></sign_nonmanual></hamgestural_sign></sigml>)");
}

// ---- motion files -----------------------------------------------------------------------------

struct Motions {
  gestura::Skeleton humanoid = gestura::synthetic_humanoid();
  gestura::Clip short_clip = gestura::synthetic_clip(humanoid, 0.2f, 30.0f);
  gestura::Skeleton avatar = gestura::build_avatar_skeleton();
  gestura::Clip avatar_still;
  Motions() { avatar_still.resize_joints(avatar.size()), avatar_still.duration = 0.1f; }
};

// A four-vertex strip on the left arm with two morphs: enough mesh for skins and VRM expressions.
gestura::Mesh small_mesh(const gestura::Skeleton& s) {
  using namespace gestura;
  Mesh mesh;
  const int a = s.find("l_shoulder"), e = s.find("l_elbow");
  const std::vector<vec3> rest = rest_joint_positions(s);
  for (int k = 0; k < 4; ++k) {
    mesh.positions.push_back(rest[static_cast<std::size_t>(k < 2 ? a : e)] + vec3(0.0f, 0.0f, k % 2 ? 0.05f : -0.05f));
    mesh.normals.push_back(vec3(1, 0, 0));
    mesh.materials.push_back(0);
    mesh.joints.push_back(JointIndices(k < 2 ? a : e, 0, 0, 0));
    mesh.weights.push_back(vec4(1, 0, 0, 0));
  }
  mesh.indices = {0, 2, 1, 1, 2, 3};
  mesh.morphs.push_back({"Fcl_MTH_A", {0, 1}, {vec3(0, 0.01f, 0), vec3(0, 0.02f, 0)}, {}});
  mesh.morphs.push_back({"Fcl_EYE_Close_L", {3}, {vec3(0.01f, 0, 0)}, {}});
  return mesh;
}

void motion_seeds(const fs::path& shared, const Motions& m) {
  for (const auto& file : fs::directory_iterator(shared / "makehuman" / "poses"))
    if (file.path().extension() == ".bvh") seed("bvh", read_text(file.path()));
  seed("bvh", gestura::write_bvh(gestura::make_bvh(m.humanoid, m.short_clip, 1.0f / 30.0f)));
  seed("bvh", gestura::write_bvh(gestura::make_bvh(m.avatar, m.avatar_still, 0.05f)));

  seed("bap", gestura::write_bap(gestura::clip_to_bap(m.short_clip, m.humanoid, 30.0f, "walk")));
  seed("bap", gestura::write_bap(gestura::clip_to_bap(m.avatar_still, m.avatar, 10.0f, "still")));

  const gestura::GltfDocument moving = gestura::make_gltf(m.humanoid, m.short_clip);
  seed("gltf", gestura::pack_glb(moving));
  seed("gltf", gestura::pack_gltf_embedded(moving));
  const gestura::Mesh mesh = small_mesh(m.avatar);
  seed("gltf", gestura::pack_glb(gestura::make_gltf(m.avatar, m.avatar_still, &mesh)));

  // VRM 1.0: our glTF plus a VRMC_vrm extension mapping VRM bones to H-Anim joints.
  const gestura::GltfDocument still = gestura::make_gltf(m.avatar, m.avatar_still, &mesh);
  json doc = json::parse(still.json);
  json bones = json::object();
  const std::pair<const char*, const char*> vrm_bones[] = {
      {"hips", "humanoid_root"}, {"spine", "vl5"}, {"head", "skullbase"}, {"leftUpperArm", "l_shoulder"},
      {"leftLowerArm", "l_elbow"}, {"rightUpperArm", "r_shoulder"}, {"leftHand", "l_wrist"}};
  for (const auto& [bone, joint] : vrm_bones)
    if (const int j = m.avatar.find(joint); j >= 0) bones[bone] = {{"node", j}};
  const std::size_t mesh_node = m.avatar.size();
  doc["extensionsUsed"] = {"VRMC_vrm"};
  doc["extensions"]["VRMC_vrm"] = {
      {"specVersion", "1.0"},
      {"meta", {{"name", "seed"}, {"authors", {"gestura"}}, {"licenseUrl", "https://vrm.dev/licenses/1.0/"}}},
      {"humanoid", {{"humanBones", bones}}},
      {"expressions",
       {{"preset",
         {{"aa", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 0}, {"weight", 1.0}}}}}},
          {"blinkLeft", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 1}, {"weight", 1.0}}}}}}}},
        {"custom", {{"tongueOut", {{"morphTargetBinds", {{{"node", mesh_node}, {"index", 1}, {"weight", 0.5}}}}}}}}}}};
  seed("vrm", gestura::pack_glb({doc.dump(), still.buffer}));

  seed("gcl", [&] {
    const gestura::CompressedClip c = gestura::compress(m.short_clip, m.humanoid);
    return std::string(c.bytes().begin(), c.bytes().end());
  }());
  seed("gcl", [&] {
    const gestura::CompressedClip c = gestura::compress(m.short_clip, m.humanoid, gestura::CompressionSettings{.max_error = 1e-2f});
    return std::string(c.bytes().begin(), c.bytes().end());
  }());

  for (const std::string& frame : gestura::openpose_json_frames(m.humanoid, m.short_clip, 10.0f)) seed("openpose_json", frame);
  json coco = {{"person_id", {-1}}, {"pose_keypoints_2d", std::vector<double>(54, 12.5)},
               {"face_keypoints_2d", std::vector<double>(210, 3.0)}, {"pose_keypoints_3d", std::vector<double>(72, 0.5)}};
  seed("openpose_json", json({{"version", 1.1}, {"people", {coco, coco}}}).dump());

  // .pose as gestura writes it: the skeleton layout, OpenPose 2D through a camera, and a short
  // two-frame file (small seeds mutate faster).
  for (const gestura::PoseLayout layout : {gestura::PoseLayout::Skeleton3D, gestura::PoseLayout::OpenPose2D})
    seed("pose", gestura::encode_pose(gestura::pose_from_clip(m.humanoid, m.short_clip, 10.0f, layout)));
  {
    gestura::PoseData pose = gestura::pose_from_clip(m.humanoid, m.short_clip, 10.0f, gestura::PoseLayout::Skeleton3D);
    pose.frames = 2;
    pose.data.resize(2 * pose.point_count() * static_cast<std::size_t>(pose.dims()));
    pose.confidence.resize(2 * pose.point_count());
    seed("pose", gestura::encode_pose(pose));
  }

  dictionary("pose", {std::string("\xCD\xCC\x4C\x3E", 4) /* 0.2f */, std::string("\xCD\xCC\xCC\x3D", 4) /* 0.1f */,
                      "XYZC", "XYC", "GESTURA_SKELETON", "pose_keypoints_2d", "POSE_LANDMARKS", std::string("\xFF\xFF", 2),
                      std::string("\x00\x00\x00\x00", 4), std::string("\xFF\xFF\xFF\x7F", 4)});
  dictionary("bvh", {"HIERARCHY", "ROOT", "JOINT", "End Site", "OFFSET", "CHANNELS", "MOTION", "Frames:", "Frame Time:",
                     "Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation", "{", "}", "\n", "\t",
                     "1e308", "-0", "nan", "inf"});
  const std::set<std::string> json_tokens{"{", "}", "[", "]", ":", ",", "\"", "null", "true", "false", "1e308", "-0",
                                          "\\u0000", "\\ud800"};
  std::set<std::string> gltf = json_tokens;
  for (const char* t : {"\"asset\"", "\"version\"", "\"2.0\"", "\"nodes\"", "\"children\"", "\"skins\"", "\"joints\"",
                        "\"inverseBindMatrices\"", "\"animations\"", "\"channels\"", "\"samplers\"", "\"input\"",
                        "\"output\"", "\"interpolation\"", "\"LINEAR\"", "\"STEP\"", "\"CUBICSPLINE\"", "\"target\"",
                        "\"node\"", "\"path\"", "\"rotation\"", "\"translation\"", "\"scale\"", "\"weights\"",
                        "\"accessors\"", "\"bufferView\"", "\"byteOffset\"", "\"byteLength\"", "\"byteStride\"",
                        "\"componentType\"", "\"count\"", "\"type\"", "\"VEC3\"", "\"VEC4\"", "\"SCALAR\"", "\"MAT4\"",
                        "\"bufferViews\"", "\"buffers\"", "\"uri\"", "\"data:application/octet-stream;base64,\"",
                        "\"meshes\"", "\"primitives\"", "\"attributes\"", "\"POSITION\"", "\"NORMAL\"", "\"JOINTS_0\"",
                        "\"WEIGHTS_0\"", "\"indices\"", "\"targets\"", "\"materials\"", "\"extensions\"",
                        "\"extensionsUsed\"", "\"VRMC_vrm\"", "\"specVersion\"", "\"humanoid\"", "\"humanBones\"",
                        "\"expressions\"", "\"preset\"", "\"custom\"", "\"morphTargetBinds\"", "\"index\"", "\"weight\"",
                        "glTF", "JSON", "\"hips\"", "\"leftHand\""})
    gltf.insert(t);
  gltf.insert(std::string("BIN\0", 4));
  dictionary("gltf", gltf);
  dictionary("vrm", gltf);
  std::set<std::string> openpose = json_tokens;
  for (const char* t : {"\"version\"", "\"people\"", "\"person_id\"", "\"pose_keypoints_2d\"", "\"face_keypoints_2d\"",
                        "\"hand_left_keypoints_2d\"", "\"hand_right_keypoints_2d\"", "\"pose_keypoints_3d\"",
                        "\"face_keypoints_3d\"", "\"hand_left_keypoints_3d\"", "\"hand_right_keypoints_3d\""})
    openpose.insert(t);
  dictionary("openpose_json", openpose);
  std::set<std::string> lexicon = json_tokens;
  for (const char* t : {"\"gloss\"", "\"lang\"", "\"ase\"", "\"variant\"", "\"hamnosys\"", "\"sigml\"", "\"clip_base64\"",
                        "\"keywords\"", "\"word\"", "\"meaning\"", "\"eng\"", "\"source\"", "\"licence\"", "\n"})
    lexicon.insert(t);
  dictionary("lexicon_jsonl", lexicon);
}

// ---- text files -------------------------------------------------------------------------------

void text_seeds(const fs::path& source) {
  seed("subtitles", "1\n00:00:01,000 --> 00:00:03,500\nHello, how are <i>you</i>?\n\n2\n00:00:04,000 --> 00:00:06,000\n"
                    "I am &amp; fine &lt;3\nsecond line\n\n3\n00:04:37,666 --> 00:04:40,000\nLate cue\n");
  seed("subtitles", "\xEF\xBB\xBFWEBVTT - a talk\n\nNOTE written by gestura\n\nSTYLE\n::cue { color: red }\n\n"
                    "intro\n00:00.000 --> 00:02.500 align:start line:10%\n<v Anna>Where do you <b>live</b>?</v>\n\n"
                    "01:00:00.000 --> 01:00:01.000\n<c.loud>Tokyo</c> <00:00:00.500>now\n");
  seed("subtitles", "1\r\n00:00:00,000 --> 00:00:00,001\r\n\r\n\r\n2\r\n00:00:05,000 --> 00:00:04,000\r\nbackwards\r\n");
  dictionary("subtitles", {"-->", "WEBVTT", "NOTE", "STYLE", "REGION", "00:00:00,000", "00:00.000", "99:59:59.999", "\n\n",
                           "\r\n", "<i>", "</i>", "<b>", "<v ", "<c.", "&amp;", "&lt;", "&#", "align:", "line:", "position:"});

  // The built-in lexicon, four entries to a seed, and the forms of an entry the importer knows.
  std::vector<std::string> lines;
  for (const auto& file : fs::directory_iterator(source / "data" / "lexicon"))
    if (file.path().extension() == ".jsonl") for_each_line(file.path(), [&](const std::string& l) { lines.push_back(l); });
  for (std::size_t i = 0; i < lines.size(); i += 4) {
    std::string chunk;
    for (std::size_t k = i; k < lines.size() && k < i + 4; ++k) chunk += lines[k] + "\n";
    seed("lexicon_jsonl", chunk);
  }
  seed("lexicon_jsonl",
       R"({"gloss":"HOUSE","lang":"ase","variant":2,"sigml":"<hns_sign gloss=\"house\"><hamnosys_manual><hamflathand/></hamnosys_manual></hns_sign>","keywords":[{"word":"home","lang":"eng","meaning":"dwelling"},"house"],"source":"s","licence":"CC0-1.0"})"
       "\n\n"
       R"({"gloss":"CLIP","lang":"bfi","clip_base64":"AAECAwQFBgc=","keywords":"a,b,c"})"
       "\n");
}

// ---- the world, the server and the studio -------------------------------------------------------

const std::set<std::string> kJsonTokens{"{", "}", "[", "]", ":", ",", "\"", "null", "true", "false", "1e308", "-0",
                                        "1e7", "10000001", "\\u0000", "\\ud800"};

void world_seeds(const fs::path& source) {
  // Scenes: the example living room and small scenes written here (each shape, a door, groups,
  // prototypes, characters, lights and cameras of every kind).
  std::string living_room;
  for (const auto& file : fs::directory_iterator(source / "data" / "scenes"))
    if (file.path().extension() == ".json") {
      seed("scene_json", read_text(file.path()));
      if (living_room.empty()) living_room = read_text(file.path());
    }
  seed("scene_json", R"({"version": 1, "name": "tiny", "objects": [{"name": "floor", "shape": "plane", "size": [4, 4]}]})");
  seed("scene_json", R"({"version": 1, "name": "shapes", "background": [0.2, 0.3, 0.4],
  "materials": {"red": {"color": "#ff0000", "specular": 0.5}, "blue": "#0000ff"},
  "prototypes": {"stool": {"material": "red", "parts": [
    {"shape": "cylinder", "radius": 0.2, "height": 0.05, "position": [0, 0.45, 0], "segments": 16},
    {"shape": "sphere", "radius": 0.05, "position": [0, 0.1, 0], "segments": 8}]}},
  "objects": [
    {"name": "floor", "shape": "box", "size": [6, 0.1, 6], "position": [0, -0.05, 0], "material": "blue"},
    {"name": "stool", "instance": "stool", "position": [1, 0, 1], "rotation": 45},
    {"name": "pillar", "shape": "cylinder", "radius": 0.1, "height": 2, "position": [-1, 1, 0], "rotation": [90, 0, 0], "obstacle": false},
    {"name": "door", "position": [3, 0, 1], "rotation": [0, -90, 0], "door": {"handle": [0.77, 1.02, 0.06], "open_angle": -95, "angle": 10},
     "parts": [{"shape": "box", "size": [0.86, 2.08, 0.04], "position": [0.45, 1.045, 0]}]},
    {"name": "statue", "shape": "mesh", "file": "statue.glb", "unit": 0.01}],
  "places": {"window": {"position": [-2, 0], "facing": 90}, "shelf": {"position": [0, 1.2, 2]}},
  "characters": [{"name": "anna", "sex": "female", "height": 1.66, "build": 0.9, "place": "window", "colors": {"cloth": "#2e3d5c"}},
                 {"name": "ben", "avatar": "default", "position": [1, -1], "facing": 180, "radius": 0.35, "speed": 1.1}],
  "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3], "color": "#fff4e6", "intensity": 1, "shadows": true},
             {"type": "point", "position": [0, 2.5, 0], "intensity": 0.5}, {"type": "ambient", "color": [0.8, 0.8, 0.9]}],
  "cameras": [{"name": "wide", "position": [0, 2, 5], "target": [0, 1, 0], "fov": 50},
              {"name": "plan", "projection": "orthographic", "position": [0, 10, 0], "target": [0, 0, 0], "view_height": 8},
              {"name": "follow", "position": [0, 1.6, 3], "look_at": "anna"}],
  "script": "anna walks to the stool; ben opens the door"})");
  std::set<std::string> scene = kJsonTokens;
  for (const char* t : {"\"version\"", "\"name\"", "\"seed\"", "\"background\"", "\"materials\"", "\"color\"", "\"specular\"",
                        "\"prototypes\"", "\"parts\"", "\"objects\"", "\"shape\"", "\"box\"", "\"plane\"", "\"cylinder\"",
                        "\"sphere\"", "\"mesh\"", "\"size\"", "\"radius\"", "\"height\"", "\"segments\"", "\"file\"",
                        "\"unit\"", "\"position\"", "\"rotation\"", "\"material\"", "\"instance\"", "\"door\"", "\"handle\"",
                        "\"open_angle\"", "\"angle\"", "\"obstacle\"", "\"places\"", "\"facing\"", "\"characters\"",
                        "\"avatar\"", "\"build\"", "\"sex\"", "\"female\"", "\"male\"", "\"place\"", "\"colors\"",
                        "\"speed\"", "\"lights\"", "\"type\"", "\"directional\"", "\"point\"", "\"ambient\"",
                        "\"direction\"", "\"intensity\"", "\"shadows\"", "\"cameras\"", "\"target\"", "\"look_at\"",
                        "\"fov\"", "\"projection\"", "\"orthographic\"", "\"view_height\"", "\"script\"", "\"#a9b4bf\""})
    scene.insert(t);
  dictionary("scene_json", scene);

  // Scripts: the example scene's, the forms the script reader documents, and the JSON form.
  if (!living_room.empty()) {
    const json doc = json::parse(living_room, nullptr, false);
    if (doc.is_object() && doc.contains("script") && doc["script"].is_array())
      for (const json& line : doc["script"])
        if (line.is_string()) seed("scene_script", line.get<std::string>());
  }
  seed("scene_script", "anna walks to the chair; anna says \"Hello, sit down please.\"; ben turns to anna\n"
                       "ben walks to the door and opens it\nmeanwhile anna follows ben at 1.5\n"
                       "anna walks to the window while signing \"It is raining.\"\nwait 2; at 12 s: ben looks at anna\n");
  seed("scene_script", "ben turns left 45 degrees, then turns around; anna faces the door\nanna reaches for the cup then "
                       "takes it\nben touches the chair and closes the door\nanna goes to the window at 0.8 m/s; "
                       "ben stops looking; anna stops following; ben stops\n");
  seed("scene_script", R"([{"actor": "anna", "do": "walk", "to": "chair", "speed": 1.2}, {"wait": 2},
 {"actor": "ben", "do": "turn", "to": "anna", "with_previous": true}, {"actor": "ben", "do": "say", "text": "hello"},
 "anna opens the door"])");
  std::set<std::string> script = {"\"", ";", ",", "\n", ":", " and ", " then ", " while ", "meanwhile ", "at ", " s:",
                                  "anna", "ben", "chair", "door", "cup", "window", "it", "the ", "m/s", "degrees"};
  for (const char* verb : {"walks to", "goes to", "runs to", "moves to", "turns to", "turns towards", "turns left",
                           "turns right", "turns around", "faces", "says", "signs", "looks at", "stops looking",
                           "follows", "stops following", "stops", "reaches for", "grasps", "takes", "touches", "opens",
                           "closes", "wait"})
    script.insert(verb);
  for (const char* t : {"\"actor\"", "\"do\"", "\"to\"", "\"text\"", "\"speed\"", "\"angle\"", "\"distance\"", "\"wait\"",
                        "\"with_previous\"", "\"at\"", "\"script\"", "[", "]", "{", "}"})
    script.insert(t);
  dictionary("scene_script", script);
}

void front_door_seeds() {
  // Request bodies of gestura serve (docs/server.md) and the other forms the field tables read.
  seed("request_json", R"({"text": "Hello, how are you?", "lang": "ase", "speed": 1.2, "mouthing": false, "fps": 30})");
  seed("request_json", R"({"hamnosys": "\ue001\ue00d\ue020\ue03c\ue058", "speed": 0.8})");
  seed("request_json", R"({"names": "hamflathand,hamextfingeru,hampalml,hamforehead,hamtouch", "gloss": "HELLO"})");
  seed("request_json", R"({"text": "my name is anna", "lang": "ase", "open": true})");
  seed("request_json", R"({"text": "where do you live", "size": "640x360", "camera": "front", "nonmanuals": true})");
  seed("request_json", R"({"text": "", "speed": 1e308, "fps": -1, "avatar": "ana", "height": 1.6, "output": "x.glb"})");
  std::set<std::string> request = kJsonTokens;
  for (const char* t : {"\"text\"", "\"lang\"", "\"speed\"", "\"mouthing\"", "\"nonmanuals\"", "\"fps\"", "\"size\"",
                        "\"camera\"", "\"hamnosys\"", "\"names\"", "\"gloss\"", "\"open\"", "\"avatar\"", "\"height\"",
                        "\"build\"", "\"sex\"", "\"output\"", "\"ase\"", "\"bfi\"", "\"front\"", "\"1280x720\""})
    request.insert(t);
  dictionary("request_json", request);

  // The studio's recovery file, as the studio writes it (studio/recovery.cpp).
  seed("studio_draft", R"({"draft": {"gloss": "HOUSE", "lang": "ase", "variant": 1,
  "names": "hamflathand,hamextfingeru,hampalml,hamshoulders,hamparbegin,hammovedo,hamreplace,hamextfingerd,hamparend",
  "keywords": "house,home", "meaning": "a dwelling", "source": "me", "licence": "CC0-1.0", "from_builtin": true,
  "origin": {"gloss": "HOUSE", "lang": "ase", "variant": 2}}})");
  seed("studio_draft", R"({"draft": {"gloss": "NEW", "lang": "bfi", "names": "hamfist, hamthumbacrossmod hamextfingeru"}})");
  seed("studio_draft", R"({"draft": {"gloss": "X", "lang": "ase", "names": "hamflathand,hamparbegin"}})");
  std::set<std::string> draft = kJsonTokens;
  for (const char* t : {"\"draft\"", "\"gloss\"", "\"lang\"", "\"variant\"", "\"names\"", "\"keywords\"", "\"meaning\"",
                        "\"source\"", "\"licence\"", "\"from_builtin\"", "\"origin\"", "hamflathand", "hamfist",
                        "hamextfingeru", "hampalml", "hamparbegin", "hamparend", "hamseqbegin", "hamrepeatfromstart"})
    draft.insert(t);
  dictionary("studio_draft", draft);
}

// The figure editor's skeleton files (studio/figure_model): a sidecar alone is read beside the
// avatar's skeleton file; BVH, NUL, sidecar is a pair (fuzz/fuzz_figure.cpp).
void figure_seeds(const fs::path& shared, const Motions& m) {
  using gestura::studio::write_figure;
  const auto pair = [](const gestura::studio::FigureTexts& t) { return t.bvh + std::string(1, '\0') + t.sidecar; };
  gestura::Skeleton avatar = m.avatar;
  seed("figure", write_figure(avatar, "avatar.bvh").sidecar);
  // Limits on a few axes, a DH description, a joint with no free axis.
  for (const char* name : {"l_elbow", "r_wrist", "skullbase"})
    if (const int j = avatar.find(name); j >= 0) {
      const auto u = static_cast<std::size_t>(j);
      avatar.dofs[u] = gestura::JointDofs{gestura::RotationOrder::ZXY, 5, gestura::vec3(-0.7f, 0, -1.2f), gestura::vec3(2.4f, 0, 0.3f)};
      avatar.dh.resize(avatar.size());
      avatar.dh[u] = gestura::DenavitHartenberg{0.25f, 0.1f, 0.02f, -0.4f};
    }
  if (const int j = avatar.find("vl5"); j >= 0) avatar.dofs[static_cast<std::size_t>(j)].axes = 0;
  seed("figure", write_figure(avatar, "avatar.bvh").sidecar);
  seed("figure", pair(write_figure(avatar, "avatar.bvh")));
  seed("figure", pair(write_figure(m.humanoid, "humanoid.bvh")));
  seed("figure", R"({"format": "gestura figure", "version": 1, "skeleton": "avatar.bvh", "joints": {"l_elbow":
  {"order": "YXZ", "axes": "xy", "min_degrees": [-150, -10, 0], "max_degrees": [0, 90, 0],
   "dh": {"a": 0.26, "alpha_degrees": 0, "d": 0, "theta_degrees": -90}}}})");
  // A plain BVH from elsewhere (no sidecar: every rotation axis free).
  seed("figure", read_text(shared / "makehuman" / "poses" / "tpose.bvh") + std::string(1, '\0'));
  std::set<std::string> figure = kJsonTokens;
  for (const char* t : {"\"format\"", "\"gestura figure\"", "\"version\"", "\"skeleton\"", "\"joints\"", "\"order\"",
                        "\"axes\"", "\"min_degrees\"", "\"max_degrees\"", "\"dh\"", "\"a\"", "\"alpha_degrees\"",
                        "\"d\"", "\"theta_degrees\"", "\"XYZ\"", "\"XZY\"", "\"YXZ\"", "\"YZX\"", "\"ZXY\"", "\"ZYX\"",
                        "\"xyz\"", "\"l_elbow\"", "\"r_wrist\"", "\"humanoid_root\"", "HIERARCHY", "ROOT", "JOINT",
                        "End Site", "OFFSET", "CHANNELS", "MOTION", "Frames:", "Frame Time:", "Xrotation", "Yrotation",
                        "Zrotation", "Xposition", "_end", "1e39", "3.5e38"})
    figure.insert(t);
  figure.insert(std::string(1, '\0'));
  dictionary("figure", figure);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: gestura-fuzz-seeds SHARED_DATA SOURCE_DIR OUT\n";
    return 2;
  }
  const fs::path shared = argv[1], source = argv[2];
  g_out = argv[3];
  try {
    fs::remove_all(g_out);  // seeds of an older version must not linger
    hamnosys_seeds(shared, source);
    sigml_seeds(shared);
    const Motions motions;
    motion_seeds(shared, motions);
    text_seeds(source);
    world_seeds(source);
    front_door_seeds();
    figure_seeds(shared, motions);
  } catch (const std::exception& e) {
    std::cerr << "gestura-fuzz-seeds: " << e.what() << "\n";
    return 1;
  }
  for (const auto& dir : fs::directory_iterator(g_out))
    if (dir.is_directory())
      std::cout << dir.path().filename().string() << ": "
                << std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}) << " seeds\n";
  return 0;
}
