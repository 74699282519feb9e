#include "gestura/io/vrm.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/gltf_reader.hpp"
#include "gestura/skeleton/joint_names.hpp"
#include "gestura/io/json_excerpt.hpp"

namespace gestura {
namespace {

using nlohmann::json;

constexpr std::pair<std::string_view, std::string_view> kPresets[] = {
    {"aa", "aa"},          {"ih", "ih"},           {"ou", "ou"},         {"ee", "E"},
    {"oh", "oh"},          {"happy", "joy"},       {"angry", "anger"},   {"sad", "sadness"},
    {"relaxed", "relaxed"}, {"surprised", "surprise"}, {"neutral", "neutral"}, {"blink", "blink"},
    {"blinkLeft", "eyeBlink_L"}, {"blinkRight", "eyeBlink_R"}, {"lookUp", "lookUp"}, {"lookDown", "lookDown"},
    {"lookLeft", "lookLeft"}, {"lookRight", "lookRight"}};

// VRM 0.x blend shape presets → our face channels ("unknown" keeps the group's name).
constexpr std::pair<std::string_view, std::string_view> kPresets0[] = {
    {"a", "aa"},          {"i", "ih"},       {"u", "ou"},           {"e", "E"},        {"o", "oh"},
    {"joy", "joy"},       {"angry", "anger"}, {"sorrow", "sadness"}, {"fun", "relaxed"}, {"neutral", "neutral"},
    {"blink", "blink"},   {"blink_l", "eyeBlink_L"}, {"blink_r", "eyeBlink_R"}, {"lookup", "lookUp"},
    {"lookdown", "lookDown"}, {"lookleft", "lookLeft"}, {"lookright", "lookRight"}};

// Which of our materials a glTF material is, by its name (VRoid-style "…_EyeIris_…", "…_HairBack_…",
// "…_Tops_…", our own "skin", "cloth" …); anything unnamed or unknown is skin.
MaterialId material_of(const GltfReader& r, const json& prim, const std::string& where) {
  if (!prim.contains("material")) return MaterialId::Skin;
  const json& m = r.item("materials", prim["material"], where);
  std::string name = m.value("name", std::string());
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto has = [&](std::initializer_list<const char*> words) {
    return std::any_of(words.begin(), words.end(), [&](const char* w) { return name.find(w) != std::string::npos; });
  };
  if (has({"pupil"})) return MaterialId::Pupil;
  if (has({"iris"})) return MaterialId::Iris;
  if (has({"brow", "lash", "eyeline"})) return MaterialId::Brow;
  if (has({"eye-white", "eyewhite", "sclera", "eyeball", "eye_white"})) return MaterialId::EyeWhite;
  if (has({"teeth", "tooth"})) return MaterialId::Teeth;
  if (has({"tongue"})) return MaterialId::Tongue;
  if (has({"lip"})) return MaterialId::Lips;
  if (has({"mouth"})) return MaterialId::Mouth;
  if (has({"hair"})) return MaterialId::Hair;
  if (has({"cloth", "tops", "bottoms", "shirt", "pants", "trousers", "shoe", "jacket", "dress", "skirt", "sock", "glove",
           "coat", "sleeve", "suit"}))
    return MaterialId::Cloth;
  return MaterialId::Skin;
}

// VRM 0.x names the thumb's bones one step further out than 1.0 does.
std::string bone_name_1_0(const std::string& bone0) {
  for (const char* side : {"left", "right"}) {
    const std::string s = side;
    if (bone0 == s + "ThumbProximal") return s + "ThumbMetacarpal";
    if (bone0 == s + "ThumbIntermediate") return s + "ThumbProximal";
  }
  return bone0;
}

std::size_t index_in(const GltfReader& r, const json& value, std::size_t size, const std::string& where, const char* what) {
  if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() >= static_cast<long long>(size))
    r.fail(where, std::string("refers to a missing ") + what + " " + json_excerpt(value));
  return value.get<std::size_t>();
}

mat4 node_local(const GltfReader& r, const json& node, const std::string& where) {
  if (node.contains("matrix")) {
    const json& m = node["matrix"];
    if (!m.is_array() || m.size() != 16) r.fail(where, "matrix needs 16 numbers");
    mat4 out;
    for (int k = 0; k < 16; ++k) {
      if (!m[static_cast<std::size_t>(k)].is_number()) r.fail(where, "matrix needs 16 numbers");
      out[k / 4][k % 4] = m[static_cast<std::size_t>(k)].get<float>();
    }
    return out;
  }
  Transform t;
  t.translation = json_vec3(r, node, "translation", vec3(0.0f), where);
  t.scale = json_vec3(r, node, "scale", vec3(1.0f), where);
  if (node.contains("rotation")) {
    const json& a = node["rotation"];
    if (!a.is_array() || a.size() != 4 || !a[0].is_number() || !a[1].is_number() || !a[2].is_number() || !a[3].is_number())
      r.fail(where, "rotation needs 4 numbers");
    const quat q(a[3].get<float>(), a[0].get<float>(), a[1].get<float>(), a[2].get<float>());
    if (!is_finite(q) || glm::length(q) < 1e-6f) r.fail(where, "rotation is not a usable quaternion");
    t.rotation = glm::normalize(q);
  }
  return t.matrix();
}

}  // namespace

std::string_view face_channel_for_vrm_preset(std::string_view preset) {
  for (const auto& [vrm, ours] : kPresets)
    if (vrm == preset) return ours;
  return "";
}

namespace {

VrmAvatar read_any(const std::string& bytes, const std::string& source, bool plain_allowed) {
  const GltfReader r(bytes, source);
  const json& doc = r.doc();
  const json* ext = nullptr;
  const json* ext0 = nullptr;
  if (doc.contains("extensions") && doc["extensions"].is_object()) {
    if (doc["extensions"].contains("VRMC_vrm")) ext = &doc["extensions"]["VRMC_vrm"];
    else if (doc["extensions"].contains("VRM")) ext0 = &doc["extensions"]["VRM"];
  }
  if (ext && !ext->is_object()) r.fail("extensions.VRMC_vrm", "is not an object");
  if (ext0 && !ext0->is_object()) r.fail("extensions.VRM", "is not an object");
  if (!ext && !ext0 && !plain_allowed) r.fail("extensions", "no VRMC_vrm (VRM 1.0) or VRM (0.x) extension: not a VRM file");

  GltfAnimation nodes_as_joints = read_gltf_animation(bytes, source);
  VrmAvatar out;
  out.kind = ext ? "VRM 1.0" : ext0 ? "VRM 0.x" : "glTF";
  out.faces_minus_z = ext0 != nullptr;
  out.skeleton = std::move(nodes_as_joints.skeleton);
  const json& nodes = r.array("nodes");
  std::vector<int> joint_of(nodes.size(), -1), parent(nodes.size(), -1);
  for (std::size_t j = 0; j < nodes_as_joints.node_of_joint.size(); ++j)
    joint_of[static_cast<std::size_t>(nodes_as_joints.node_of_joint[j])] = static_cast<int>(j);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].contains("children"))
      for (const json& c : nodes[i]["children"]) parent[c.get<std::size_t>()] = static_cast<int>(i);  // checked by the reader above

  // Humanoid bones → H-Anim names.
  const auto name_bone = [&](const std::string& bone, std::size_t n, const std::string& where) {
    const int j = joint_of[n];
    if (j < 0) r.fail(where, "names a mesh node, not a joint");
    std::string name = to_hanim(bone, RigConvention::Vrm);
    if (name.empty()) name = out.skeleton.names[static_cast<std::size_t>(j)];
    // Make room: a node already called like the H-Anim joint keeps its identity under a new name.
    if (const int clash = out.skeleton.find(name); clash >= 0 && clash != j)
      out.skeleton.names[static_cast<std::size_t>(clash)] += "_node" + std::to_string(nodes_as_joints.node_of_joint[static_cast<std::size_t>(clash)]);
    out.skeleton.names[static_cast<std::size_t>(j)] = name;
    out.humanoid[bone] = name;
  };
  if (ext) {
    const json& humanoid = ext->contains("humanoid") ? (*ext)["humanoid"] : json();
    if (!humanoid.is_object() || !humanoid.contains("humanBones") || !humanoid["humanBones"].is_object())
      r.fail("VRMC_vrm", "needs humanoid.humanBones");
    for (const auto& [bone, value] : humanoid["humanBones"].items()) {
      const std::string where = "VRMC_vrm.humanoid.humanBones." + bone;
      if (!value.is_object() || !value.contains("node")) r.fail(where, "needs a node");
      name_bone(bone, index_in(r, value["node"], nodes.size(), where, "node"), where);
    }
    if (!out.humanoid.contains("hips")) r.fail("VRMC_vrm.humanoid.humanBones", "has no hips");
  } else if (ext0) {
    const json& humanoid = ext0->contains("humanoid") ? (*ext0)["humanoid"] : json();
    if (!humanoid.is_object() || !humanoid.contains("humanBones") || !humanoid["humanBones"].is_array())
      r.fail("VRM", "needs humanoid.humanBones (a list)");
    for (std::size_t i = 0; i < humanoid["humanBones"].size(); ++i) {
      const json& value = humanoid["humanBones"][i];
      const std::string where = "VRM.humanoid.humanBones[" + std::to_string(i) + "]";
      if (!value.is_object() || !value.contains("bone") || !value["bone"].is_string() || !value.contains("node"))
        r.fail(where, "needs a bone name and a node");
      name_bone(bone_name_1_0(value["bone"].get<std::string>()), index_in(r, value["node"], nodes.size(), where, "node"), where);
    }
    if (!out.humanoid.contains("hips")) r.fail("VRM.humanoid.humanBones", "has no hips");
  } else {
    // A plain glTF: the joint-name tables say which joint is which.
    const std::vector<std::string> hanim = guess_hanim_names(out.skeleton);
    for (std::size_t j = 0; j < hanim.size(); ++j) {
      if (hanim[j].empty() || hanim[j] == out.skeleton.names[j]) continue;
      if (const int clash = out.skeleton.find(hanim[j]); clash >= 0 && static_cast<std::size_t>(clash) != j)
        out.skeleton.names[static_cast<std::size_t>(clash)] += "_node" + std::to_string(nodes_as_joints.node_of_joint[static_cast<std::size_t>(clash)]);
      out.skeleton.names[j] = hanim[j];
    }
  }

  // Rest pose and default inverse binds.
  std::vector<mat4> rest(out.skeleton.size());
  local_to_model(out.skeleton, rest_pose(out.skeleton), rest);
  out.inverse_binds.resize(rest.size());
  for (std::size_t j = 0; j < rest.size(); ++j) out.inverse_binds[j] = glm::inverse(rest[j]);
  auto nearest_joint = [&](std::size_t node) {
    for (int p = static_cast<int>(node); p >= 0; p = parent[static_cast<std::size_t>(p)])
      if (joint_of[static_cast<std::size_t>(p)] >= 0) return joint_of[static_cast<std::size_t>(p)];
    return 0;
  };

  // Meshes.
  std::map<std::pair<std::size_t, std::size_t>, int> morph_of;  // (mesh, target) → morph index
  std::map<std::size_t, std::size_t> mesh_of_node;
  Mesh& mesh = out.mesh;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].contains("mesh")) continue;
    const std::string nwhere = "nodes[" + std::to_string(n) + "]";
    const std::size_t mi = index_in(r, nodes[n]["mesh"], r.array("meshes").size(), nwhere, "mesh");
    mesh_of_node[n] = mi;
    const json& gmesh = r.item("meshes", nodes[n]["mesh"], nwhere);
    std::vector<int> skin_joints;
    std::vector<mat4> skin_ibm;
    if (nodes[n].contains("skin")) {
      const json& skin = r.item("skins", nodes[n]["skin"], nwhere);
      const std::string swhere = "skins[" + json_excerpt(nodes[n]["skin"]) + "]";
      if (!skin.contains("joints") || !skin["joints"].is_array() || skin["joints"].empty()) r.fail(swhere, "needs joints");
      for (const json& jn : skin["joints"]) {
        const int j = joint_of[index_in(r, jn, nodes.size(), swhere, "joint node")];
        if (j < 0) r.fail(swhere, "lists a mesh node as a joint");
        skin_joints.push_back(j);
      }
      skin_ibm.assign(skin_joints.size(), mat4(1.0f));
      if (skin.contains("inverseBindMatrices")) {
        int width = 0;
        const std::vector<float> m = r.accessor(skin["inverseBindMatrices"], swhere, &width);
        if (width != 16 || m.size() != skin_joints.size() * 16) r.fail(swhere, "inverseBindMatrices do not match its joints");
        for (std::size_t k = 0; k < skin_joints.size(); ++k) {
          for (int e = 0; e < 16; ++e) skin_ibm[k][e / 4][e % 4] = m[k * 16 + static_cast<std::size_t>(e)];
          out.inverse_binds[static_cast<std::size_t>(skin_joints[k])] = skin_ibm[k];
        }
      }
    }
    const int rigid_joint = nearest_joint(n);
    const mat4 rigid = rest[static_cast<std::size_t>(rigid_joint)] * node_local(r, nodes[n], nwhere);
    std::vector<std::string> target_names;
    if (gmesh.contains("extras") && gmesh["extras"].is_object() && gmesh["extras"].contains("targetNames") &&
        gmesh["extras"]["targetNames"].is_array())
      for (const json& t : gmesh["extras"]["targetNames"]) target_names.push_back(t.is_string() ? t.get<std::string>() : "");
    if (!gmesh.contains("primitives") || !gmesh["primitives"].is_array()) r.fail("meshes[" + std::to_string(mi) + "]", "needs primitives");
    std::map<std::string, std::pair<std::size_t, std::size_t>> shared;  // attributes → (first vertex, count)
    for (std::size_t pi = 0; pi < gmesh["primitives"].size(); ++pi) {
      const json& prim = gmesh["primitives"][pi];
      const std::string pwhere = "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
      if (!prim.is_object() || !prim.contains("attributes") || !prim["attributes"].is_object()) r.fail(pwhere, "needs attributes");
      if (prim.value("mode", 4) != 4) continue;  // points and lines are not body surface
      const json& attr = prim["attributes"];
      if (!attr.contains("POSITION")) r.fail(pwhere, "has no POSITION");
      // Primitives of one mesh that share their vertex attributes (one per material, as our own
      // export writes them) share the vertices too: only their triangles and materials differ.
      const std::string shared_key = attr.dump() + (prim.contains("targets") ? prim["targets"].dump() : std::string());
      const auto shared_it = shared.find(shared_key);
      const bool reused = shared_it != shared.end();
      int width = 0;
      std::size_t count = 0, base = 0;
      std::vector<float> jnt;
      bool skinned = false;
      if (reused) {
        base = shared_it->second.first, count = shared_it->second.second;
      } else {
        const std::vector<float> pos = r.accessor(attr["POSITION"], pwhere, &width);
        if (width != 3) r.fail(pwhere, "POSITION is not VEC3");
        count = pos.size() / 3, base = mesh.positions.size();
        if (base + count > 0xFFFFFFFFull) r.fail(pwhere, "too many vertices");
        std::vector<float> nrm, wgt;
        if (attr.contains("NORMAL")) {
          nrm = r.accessor(attr["NORMAL"], pwhere, &width);
          if (width != 3 || nrm.size() != pos.size()) r.fail(pwhere, "NORMAL does not match POSITION");
        }
        skinned = !skin_joints.empty() && attr.contains("JOINTS_0") && attr.contains("WEIGHTS_0");
        if (skinned) {
          jnt = r.accessor(attr["JOINTS_0"], pwhere, &width);
          if (width != 4 || jnt.size() != count * 4) r.fail(pwhere, "JOINTS_0 does not match POSITION");
          wgt = r.accessor(attr["WEIGHTS_0"], pwhere, &width);
          if (width != 4 || wgt.size() != count * 4) r.fail(pwhere, "WEIGHTS_0 does not match POSITION");
        }
        for (std::size_t v = 0; v < count; ++v) {
          const vec4 p(pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2], 1.0f);
          vec3 normal = nrm.empty() ? vec3(0, 1, 0) : vec3(nrm[v * 3], nrm[v * 3 + 1], nrm[v * 3 + 2]);
          JointIndices ji(static_cast<std::uint16_t>(rigid_joint), 0, 0, 0);
          vec4 w(1, 0, 0, 0);
          mat4 to_model = rigid;
          if (skinned) {
            to_model = mat4(0.0f);
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) {
              const float idx = jnt[v * 4 + static_cast<std::size_t>(k)];
              if (idx < 0 || idx >= float(skin_joints.size()) || idx != std::floor(idx))
                r.fail(pwhere, "vertex " + std::to_string(v) + " names skin joint " + std::to_string(idx) + " of " +
                                   std::to_string(skin_joints.size()));
              const auto s = static_cast<std::size_t>(idx);
              ji[k] = static_cast<std::uint16_t>(skin_joints[s]);
              w[k] = std::max(0.0f, wgt[v * 4 + static_cast<std::size_t>(k)]);
              sum += w[k];
              to_model += w[k] * (rest[static_cast<std::size_t>(skin_joints[s])] * skin_ibm[s]);
            }
            if (!(sum > 0.0f)) w = vec4(1, 0, 0, 0), to_model = rest[ji[0]] * skin_ibm[0], sum = 1.0f;
            w /= sum;
            to_model /= sum;
          }
          mesh.positions.push_back(vec3(to_model * p));
          const vec3 n3 = mat3(to_model) * normal;
          mesh.normals.push_back(glm::length(n3) > 1e-12f ? glm::normalize(n3) : vec3(0, 1, 0));
          mesh.materials.push_back(0);
          mesh.joints.push_back(ji);
          mesh.weights.push_back(w);
        }
        shared[shared_key] = {base, count};
      }
      const std::size_t first_index = mesh.indices.size();
      if (prim.contains("indices")) {
        const std::vector<float> idx = r.accessor(prim["indices"], pwhere, &width);
        if (width != 1 || idx.size() % 3) r.fail(pwhere, "indices are not whole triangles");
        for (float i : idx) {
          if (i < 0 || i >= float(count)) r.fail(pwhere, "index " + std::to_string(i) + " past its " + std::to_string(count) + " vertices");
          mesh.indices.push_back(static_cast<std::uint32_t>(base + static_cast<std::size_t>(i)));
        }
      } else {
        if (count % 3) r.fail(pwhere, "vertex count is not whole triangles");
        for (std::size_t i = 0; i < count; ++i) mesh.indices.push_back(static_cast<std::uint32_t>(base + i));
      }
      const MaterialId material = material_of(r, prim, pwhere);
      for (std::size_t k = first_index; k < mesh.indices.size(); ++k) mesh.materials[mesh.indices[k]] = static_cast<std::uint8_t>(material);
      if (!reused && prim.contains("targets")) {
        if (!prim["targets"].is_array()) r.fail(pwhere, "targets is not an array");
        for (std::size_t t = 0; t < prim["targets"].size(); ++t) {
          const json& target = prim["targets"][t];
          const std::string twhere = pwhere + ".targets[" + std::to_string(t) + "]";
          if (!target.is_object()) r.fail(twhere, "not an object");
          auto [it, fresh] = morph_of.emplace(std::pair{mi, t}, static_cast<int>(mesh.morphs.size()));
          if (fresh) {
            std::string name = t < target_names.size() && !target_names[t].empty()
                                   ? target_names[t]
                                   : gmesh.value("name", "mesh" + std::to_string(mi)) + "_" + std::to_string(t);
            if (mesh.find_morph(name) >= 0) name += "_mesh" + std::to_string(mi);
            mesh.morphs.push_back({name, {}, {}, {}});
          }
          MorphTarget& morph = mesh.morphs[static_cast<std::size_t>(it->second)];
          if (!target.contains("POSITION")) continue;
          const std::vector<float> d = r.accessor(target["POSITION"], twhere, &width);
          if (width != 3 || d.size() != count * 3) r.fail(twhere, "POSITION deltas do not match the vertices");
          for (std::size_t v = 0; v < count; ++v) {
            const vec3 dv(d[v * 3], d[v * 3 + 1], d[v * 3 + 2]);
            if (dv == vec3(0.0f)) continue;
            morph.vertices.push_back(static_cast<std::uint32_t>(base + v));
            // Deltas turn with the vertex's bind transform into model space.
            const std::size_t at = base + v;
            const JointIndices& j4 = mesh.joints[at];
            mat3 m = mat3(rigid);
            if (skinned) {
              m = mat3(0.0f);
              for (int k = 0; k < 4; ++k) {
                const auto s = static_cast<std::size_t>(jnt[v * 4 + static_cast<std::size_t>(k)]);
                m += mesh.weights[at][k] * mat3(rest[j4[k]] * skin_ibm[s]);
              }
            }
            morph.position_deltas.push_back(m * dv);
          }
        }
      }
    }
  }

  // Expressions.
  if (ext && ext->contains("expressions") && (*ext)["expressions"].is_object()) {
    for (const char* group : {"preset", "custom"}) {
      const json& g = (*ext)["expressions"].contains(group) ? (*ext)["expressions"][group] : json();
      if (!g.is_object()) continue;
      for (const auto& [name, expr] : g.items()) {
        const std::string where = std::string("VRMC_vrm.expressions.") + group + "." + name;
        std::string channel(group == std::string("preset") ? face_channel_for_vrm_preset(name) : std::string_view(name));
        if (channel.empty()) channel = name;
        std::vector<VrmMorphBind>& binds = out.face_channels[channel];
        if (!expr.is_object() || !expr.contains("morphTargetBinds")) continue;
        if (!expr["morphTargetBinds"].is_array()) r.fail(where, "morphTargetBinds is not an array");
        for (const json& b : expr["morphTargetBinds"]) {
          if (!b.is_object() || !b.contains("node") || !b.contains("index")) r.fail(where, "a bind needs node and index");
          const std::size_t n = index_in(r, b["node"], nodes.size(), where, "node");
          const auto m = mesh_of_node.find(n);
          if (m == mesh_of_node.end()) r.fail(where, "binds node " + std::to_string(n) + ", which has no mesh");
          const auto morph = morph_of.find({m->second, b["index"].is_number_integer() ? b["index"].get<std::size_t>() : ~std::size_t(0)});
          if (morph == morph_of.end()) r.fail(where, "binds morph target " + json_excerpt(b["index"]) + " that the mesh does not have");
          const float weight = b.contains("weight") && b["weight"].is_number() ? b["weight"].get<float>() : 1.0f;
          if (!std::isfinite(weight)) r.fail(where, "weight is not finite");
          binds.push_back({morph->second, weight});
        }
      }
    }
  }
  if (ext0 && ext0->contains("blendShapeMaster") && (*ext0)["blendShapeMaster"].is_object() &&
      (*ext0)["blendShapeMaster"].contains("blendShapeGroups") && (*ext0)["blendShapeMaster"]["blendShapeGroups"].is_array()) {
    const json& groups = (*ext0)["blendShapeMaster"]["blendShapeGroups"];
    for (std::size_t gi = 0; gi < groups.size(); ++gi) {
      const json& g = groups[gi];
      const std::string where = "VRM.blendShapeMaster.blendShapeGroups[" + std::to_string(gi) + "]";
      if (!g.is_object()) r.fail(where, "is not an object");
      const std::string preset = g.contains("presetName") && g["presetName"].is_string() ? g["presetName"].get<std::string>() : "unknown";
      std::string channel;
      for (const auto& [vrm, ours] : kPresets0)
        if (vrm == preset) channel = ours;
      if (channel.empty()) channel = g.contains("name") && g["name"].is_string() ? g["name"].get<std::string>() : preset;
      std::vector<VrmMorphBind>& binds = out.face_channels[channel];
      if (!g.contains("binds")) continue;
      if (!g["binds"].is_array()) r.fail(where, "binds is not an array");
      for (const json& b : g["binds"]) {
        if (!b.is_object() || !b.contains("mesh") || !b.contains("index")) r.fail(where, "a bind needs mesh and index");
        const std::size_t mi = index_in(r, b["mesh"], r.array("meshes").size(), where, "mesh");
        const auto morph = morph_of.find({mi, b["index"].is_number_integer() ? b["index"].get<std::size_t>() : ~std::size_t(0)});
        if (morph == morph_of.end()) r.fail(where, "binds morph target " + b["index"].dump() + " that the mesh does not have");
        const float weight = b.contains("weight") && b["weight"].is_number() ? b["weight"].get<float>() / 100.0f : 1.0f;
        if (!std::isfinite(weight)) r.fail(where, "weight is not finite");
        binds.push_back({morph->second, weight});
      }
    }
  }
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

VrmAvatar read_vrm(const std::string& bytes, const std::string& source) { return read_any(bytes, source, false); }
VrmAvatar read_rigged_gltf(const std::string& bytes, const std::string& source) { return read_any(bytes, source, true); }
VrmAvatar load_rigged_gltf(const std::string& path) { return read_rigged_gltf(read_file(path), path); }

VrmAvatar load_vrm(const std::string& path) { return read_vrm(read_file(path), path); }

}  // namespace gestura
