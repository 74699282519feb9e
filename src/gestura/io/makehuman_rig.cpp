// The MakeHuman default rig (.mhskel) and its vertex weights (.mhw).
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "gestura/io/makehuman.hpp"
#include "gestura/io/makehuman_files.hpp"
#include "gestura/skeleton/joint_names_makehuman.hpp"

namespace gestura {

using nlohmann::json;
using namespace makehuman_detail;

int MakeHumanRig::find_bone(std::string_view makehuman_name) const {
  for (std::size_t i = 0; i < bone_count; ++i)
    if (makehuman_names[i] == makehuman_name) return static_cast<int>(i);
  return -1;
}

namespace {

// Average of the listed vertices: how .mhskel places every bone end on the mesh.
vec3 joint_place(const json& joints, const std::string& joint, std::span<const vec3> positions,
                 const std::string& name) {
  const json& list = member(joints, joint.c_str(), json::value_t::array, name, "joints");
  if (list.empty()) field_error(name, "joints." + joint, "no vertices listed");
  vec3 sum(0.0f);
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_number_unsigned() || list[i].get<std::uint64_t>() >= positions.size())
      field_error(name, "joints." + joint + "[" + std::to_string(i) + "]",
                  "expected a vertex index below " + std::to_string(positions.size()));
    sum += positions[list[i].get<std::size_t>()];
  }
  return sum / static_cast<float>(list.size());
}

}  // namespace

MakeHumanRig parse_makehuman_rig(std::string_view json_text, const std::string& name, std::span<const vec3> positions) {
  const json doc = parse_json(json_text, name);
  const json& bones = member(doc, "bones", json::value_t::object, name, "");
  const json& joints = member(doc, "joints", json::value_t::object, name, "");
  if (bones.empty()) field_error(name, "bones", "no bones");

  // Order bones parents-first (depth first from the roots, siblings in file order).
  std::vector<std::string> bone_names;
  std::unordered_map<std::string, std::vector<std::string>> children;
  std::vector<std::string> roots;
  for (const auto& [bone, value] : bones.items()) {
    const std::string field = "bones." + bone;
    const json& parent = value.contains("parent") ? value["parent"] : json();
    if (parent.is_null()) {
      roots.push_back(bone);
    } else if (!parent.is_string()) {
      field_error(name, field + ".parent", "expected a bone name or null");
    } else {
      if (!bones.contains(parent.get<std::string>()))
        field_error(name, field + ".parent", "unknown bone '" + parent.get<std::string>() + "'");
      children[parent.get<std::string>()].push_back(bone);
    }
  }
  std::vector<std::string> stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    std::string bone = std::move(stack.back());
    stack.pop_back();
    const auto it = children.find(bone);
    if (it != children.end()) stack.insert(stack.end(), it->second.rbegin(), it->second.rend());
    bone_names.push_back(std::move(bone));
  }
  if (bone_names.size() != bones.size())
    field_error(name, "bones", "parent links form a cycle (" + std::to_string(bones.size() - bone_names.size()) +
                                   " bones unreachable from a root)");

  MakeHumanRig rig;
  std::unordered_map<std::string, int> index;
  for (const std::string& bone : bone_names) {
    const std::string field = "bones." + bone;
    const json& value = bones[bone];
    const json& head_joint = member(value, "head", json::value_t::string, name, field);
    const json& tail_joint = member(value, "tail", json::value_t::string, name, field);
    const vec3 head = joint_place(joints, head_joint.get<std::string>(), positions, name);
    const vec3 tail = joint_place(joints, tail_joint.get<std::string>(), positions, name);
    const json& parent = value.contains("parent") ? value["parent"] : json();
    const int parent_index = parent.is_null() ? -1 : index.at(parent.get<std::string>());
    const vec3 offset = parent_index < 0 ? head : head - rig.heads[static_cast<std::size_t>(parent_index)];
    index[bone] = rig.skeleton.add_joint(joint_name_from_makehuman(bone), parent_index, offset);
    rig.makehuman_names.push_back(bone);
    rig.heads.push_back(head);
    rig.tails.push_back(tail);
  }
  rig.bone_count = bone_names.size();

  // Finger tip sites at the tails of the distal phalanges, when the rig has them.
  static constexpr std::array<const char*, 5> kFingers = {"thumb", "index", "middle", "ring", "pinky"};
  for (const char* side : {"L", "R"}) {
    for (std::size_t f = 0; f < kFingers.size(); ++f) {
      const std::string distal = "finger" + std::to_string(f + 1) + "-3." + side;
      const auto it = index.find(distal);
      if (it == index.end()) continue;
      const vec3 tip = rig.tails[static_cast<std::size_t>(it->second)];
      rig.skeleton.add_joint(std::string(side[0] == 'L' ? "l_" : "r_") + kFingers[f] + "_tip", it->second,
                             tip - rig.heads[static_cast<std::size_t>(it->second)]);
      rig.makehuman_names.emplace_back();
      rig.heads.push_back(tip);
      rig.tails.push_back(tip);
    }
  }
  for (const vec3& head : rig.heads) rig.inverse_bind.push_back(glm::translate(mat4(1.0f), -head));
  try {
    rig.skeleton.validate();
  } catch (const Error& e) {
    throw Error(SourceLocation{name}, e.message());
  }
  return rig;
}

MakeHumanRig read_makehuman_rig(const std::string& path, std::span<const vec3> positions) {
  return parse_makehuman_rig(read_file(path), path, positions);
}

void parse_makehuman_weights(std::string_view json_text, const std::string& name, const MakeHumanRig& rig,
                             Mesh& mesh) {
  const json doc = parse_json(json_text, name);
  const json& groups = member(doc, "weights", json::value_t::object, name, "");
  const std::size_t n = mesh.positions.size();
  // Keep the four largest influences per vertex while streaming through the groups.
  std::vector<std::array<float, 4>> best_w(n, {0, 0, 0, 0});
  std::vector<std::array<std::uint16_t, 4>> best_j(n, {0, 0, 0, 0});
  for (const auto& [bone, list] : groups.items()) {
    const std::string field = "weights." + bone;
    const int joint = rig.find_bone(bone);
    if (joint < 0) field_error(name, field, "no bone of that name in the rig");
    if (!list.is_array()) field_error(name, field, "expected an array of [vertex, weight] pairs");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const json& pair = list[i];
      const std::string here = field + "[" + std::to_string(i) + "]";
      if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_unsigned() || !pair[1].is_number())
        field_error(name, here, "expected [vertex, weight]");
      const std::uint64_t v = pair[0].get<std::uint64_t>();
      const float w = pair[1].get<float>();
      if (v >= n) field_error(name, here, "vertex " + std::to_string(v) + " outside the mesh (" + std::to_string(n) + ")");
      if (!std::isfinite(w) || w < 0.0f) field_error(name, here, "weight must be finite and non-negative");
      auto& ws = best_w[v];
      auto& js = best_j[v];
      if (w <= ws[3]) continue;
      int k = 3;  // insertion into the sorted top four
      while (k > 0 && ws[static_cast<std::size_t>(k - 1)] < w) {
        ws[static_cast<std::size_t>(k)] = ws[static_cast<std::size_t>(k - 1)];
        js[static_cast<std::size_t>(k)] = js[static_cast<std::size_t>(k - 1)];
        --k;
      }
      ws[static_cast<std::size_t>(k)] = w;
      js[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(joint);
    }
  }
  mesh.joints.resize(n);
  mesh.weights.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto& ws = best_w[v];
    const float sum = ws[0] + ws[1] + ws[2] + ws[3];
    if (sum <= 0.0f) {  // unweighted: follow the root
      mesh.joints[v] = JointIndices(0);
      mesh.weights[v] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
      continue;
    }
    mesh.joints[v] = JointIndices(best_j[v][0], best_j[v][1], best_j[v][2], best_j[v][3]);
    mesh.weights[v] = vec4(ws[0], ws[1], ws[2], ws[3]) / sum;
  }
}

void read_makehuman_weights(const std::string& path, const MakeHumanRig& rig, Mesh& mesh) {
  parse_makehuman_weights(read_file(path), path, rig, mesh);
}

MakeHumanBody load_makehuman(const std::string& directory) {
  MakeHumanBody body;
  body.mesh = read_grouped_obj(directory + "/base.obj");
  body.rig = read_makehuman_rig(directory + "/rigs/default.mhskel", body.mesh.mesh.positions);
  read_makehuman_weights(directory + "/rigs/default_weights.mhw", body.rig, body.mesh.mesh);
  return body;
}

}  // namespace gestura
