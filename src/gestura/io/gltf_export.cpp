#include "gestura/io/gltf_export.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura {
namespace {

using json = nlohmann::json;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

constexpr std::array<MaterialLook, kMaterialCount> kLooks{{
    {"skin", {0.80f, 0.60f, 0.50f, 1.0f}, 0.6f},
    {"cloth", {0.10f, 0.11f, 0.16f, 1.0f}, 0.9f},
    {"hair", {0.16f, 0.10f, 0.06f, 1.0f}, 0.8f},
    {"eye_white", {0.92f, 0.92f, 0.90f, 1.0f}, 0.3f},
    {"iris", {0.25f, 0.35f, 0.45f, 1.0f}, 0.3f},
    {"lips", {0.70f, 0.38f, 0.38f, 1.0f}, 0.5f},
    {"teeth", {0.95f, 0.94f, 0.88f, 1.0f}, 0.4f},
    {"tongue", {0.75f, 0.35f, 0.38f, 1.0f}, 0.5f},
    {"brow", {0.18f, 0.11f, 0.07f, 1.0f}, 0.9f},
    {"pupil", {0.02f, 0.02f, 0.02f, 1.0f}, 0.2f},
    {"mouth", {0.20f, 0.06f, 0.06f, 1.0f}, 0.6f},
    {"nail", {0.88f, 0.70f, 0.64f, 1.0f}, 0.35f},
    {"trousers", {0.12f, 0.12f, 0.14f, 1.0f}, 0.9f},
}};

// Binary chunk under construction: each view starts 4-byte aligned.
struct BinaryBuilder {
  std::vector<std::uint8_t> bytes;
  json views = json::array();

  int add_view(const void* data, std::size_t size, int target) {
    while (bytes.size() % 4) bytes.push_back(0);
    json view{{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}};
    if (target) view["target"] = target;
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes.insert(bytes.end(), p, p + size);
    views.push_back(view);
    return static_cast<int>(views.size() - 1);
  }
};

json vec3_bounds(const std::vector<vec3>& values, bool max) {
  vec3 b(max ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity());
  for (const vec3& v : values) b = max ? glm::max(b, v) : glm::min(b, v);
  return json::array({b.x, b.y, b.z});
}

void check_mesh(const Skeleton& skeleton, const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  if (n == 0 || mesh.indices.empty()) throw Error("glTF export: the mesh is empty");
  if (mesh.normals.size() != n || mesh.joints.size() != n || mesh.weights.size() != n ||
      (!mesh.materials.empty() && mesh.materials.size() != n))
    throw Error("glTF export: per-vertex arrays disagree in length with the " + std::to_string(n) + " positions");
  if (mesh.indices.size() % 3) throw Error("glTF export: index count is not a multiple of 3");
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= n) throw Error("glTF export: index " + std::to_string(i) + " points past the vertices");
  for (std::size_t v = 0; v < n; ++v) {
    if (!is_finite(mesh.positions[v]) || !is_finite(mesh.normals[v]))
      throw Error("glTF export: vertex " + std::to_string(v) + " is not finite");
    for (int k = 0; k < 4; ++k)
      if (mesh.joints[v][k] >= skeleton.size())
        throw Error("glTF export: vertex " + std::to_string(v) + " references joint " + std::to_string(mesh.joints[v][k]) +
                    " of a " + std::to_string(skeleton.size()) + "-joint skeleton");
    if (!mesh.materials.empty() && mesh.materials[v] >= kMaterialCount)
      throw Error("glTF export: vertex " + std::to_string(v) + " has an unknown material");
  }
  for (const MorphTarget& m : mesh.morphs) {
    if (m.vertices.size() != m.position_deltas.size() ||
        (!m.normal_deltas.empty() && m.normal_deltas.size() != m.vertices.size()))
      throw Error("glTF export: morph '" + m.name + "' has mismatched arrays");
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      if (m.vertices[i] >= n || (i > 0 && m.vertices[i] <= m.vertices[i - 1]))
        throw Error("glTF export: morph '" + m.name + "' vertex list must be increasing and inside the mesh");
  }
}

// A sparse morph accessor: zeros everywhere but the listed vertices.
int sparse_accessor(BinaryBuilder& bin, json& accessors, std::size_t count, const std::vector<std::uint32_t>& vertices,
                    const std::vector<vec3>& deltas) {
  std::vector<vec3> all(deltas);
  all.push_back(vec3(0.0f));  // untouched vertices are zero: part of min/max
  json acc{{"componentType", kFloat}, {"count", count}, {"type", "VEC3"},
           {"min", vec3_bounds(all, false)}, {"max", vec3_bounds(all, true)}};
  if (!vertices.empty()) {
    const int iv = bin.add_view(vertices.data(), vertices.size() * sizeof(std::uint32_t), 0);
    const int vv = bin.add_view(deltas.data(), deltas.size() * sizeof(vec3), 0);
    acc["sparse"] = {{"count", vertices.size()},
                     {"indices", {{"bufferView", iv}, {"componentType", kUnsignedInt}}},
                     {"values", {{"bufferView", vv}}}};
  }
  accessors.push_back(acc);
  return static_cast<int>(accessors.size() - 1);
}

}  // namespace

const MaterialLook& material_look(MaterialId id) { return kLooks[static_cast<std::size_t>(id)]; }

std::vector<std::uint8_t> encode_glb(const Skeleton& skeleton, const Mesh& mesh, const std::string& name) {
  skeleton.validate();
  check_mesh(skeleton, mesh);
  const std::size_t n = mesh.vertex_count(), nj = skeleton.size();
  BinaryBuilder bin;
  json accessors = json::array();
  auto accessor = [&](int view, int component, std::size_t count, const char* type) {
    accessors.push_back({{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
    return static_cast<int>(accessors.size() - 1);
  };

  // Vertex attributes. Normals are renormalised (the validator requires unit length).
  std::vector<vec3> normals(mesh.normals);
  for (vec3& v : normals) v = glm::length(v) > 0.0f ? glm::normalize(v) : vec3(0, 1, 0);
  std::vector<vec4> weights(mesh.weights);
  for (vec4& w : weights) {
    const float s = w.x + w.y + w.z + w.w;
    w = s > 0.0f ? w / s : vec4(1, 0, 0, 0);
  }
  const int position = accessor(bin.add_view(mesh.positions.data(), n * sizeof(vec3), kArrayBuffer), kFloat, n, "VEC3");
  accessors[position]["min"] = vec3_bounds(mesh.positions, false);
  accessors[position]["max"] = vec3_bounds(mesh.positions, true);
  const int normal = accessor(bin.add_view(normals.data(), n * sizeof(vec3), kArrayBuffer), kFloat, n, "VEC3");
  const int joints =
      accessor(bin.add_view(mesh.joints.data(), n * sizeof(JointIndices), kArrayBuffer), kUnsignedShort, n, "VEC4");
  const int weight = accessor(bin.add_view(weights.data(), n * sizeof(vec4), kArrayBuffer), kFloat, n, "VEC4");

  // Morph targets, shared by every primitive.
  json targets = json::array(), target_names = json::array(), default_weights = json::array();
  for (const MorphTarget& m : mesh.morphs) {
    json t{{"POSITION", sparse_accessor(bin, accessors, n, m.vertices, m.position_deltas)}};
    if (!m.normal_deltas.empty()) t["NORMAL"] = sparse_accessor(bin, accessors, n, m.vertices, m.normal_deltas);
    targets.push_back(t);
    target_names.push_back(m.name);
    default_weights.push_back(0.0);
  }

  // One primitive per material in use.
  std::array<std::vector<std::uint32_t>, kMaterialCount> by_material;
  for (std::size_t f = 0; f < mesh.indices.size(); f += 3) {
    // A triangle takes the material most of its corners have (the first corner's on a tie).
    std::uint8_t m[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) m[k] = mesh.materials.empty() ? 0 : mesh.materials[mesh.indices[f + k]];
    const std::uint8_t chosen = (m[1] == m[2] && m[1] != m[0]) ? m[1] : m[0];
    by_material[chosen].insert(by_material[chosen].end(), {mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]});
  }
  json primitives = json::array(), materials = json::array();
  for (int m = 0; m < kMaterialCount; ++m) {
    if (by_material[m].empty()) continue;
    const MaterialLook& look = kLooks[static_cast<std::size_t>(m)];
    // The mesh's own colours (sRGB) are given to glTF as it wants them, linear.
    vec4 base = look.base_colour;
    if (mesh.material_colors.size() == static_cast<std::size_t>(kMaterialCount))
      base = vec4(glm::pow(mesh.material_colors[static_cast<std::size_t>(m)], vec3(2.2f)), 1.0f);
    materials.push_back({{"name", look.name},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor", {base.x, base.y, base.z, base.w}},
                           {"metallicFactor", 0.0},
                           {"roughnessFactor", look.roughness}}}});
    const auto& idx = by_material[m];
    const int ia = accessor(bin.add_view(idx.data(), idx.size() * sizeof(std::uint32_t), kElementArrayBuffer),
                            kUnsignedInt, idx.size(), "SCALAR");
    json prim{{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"JOINTS_0", joints}, {"WEIGHTS_0", weight}}},
              {"indices", ia},
              {"material", materials.size() - 1},
              {"mode", 4}};
    if (!targets.empty()) prim["targets"] = targets;
    primitives.push_back(prim);
  }

  // Joints as nodes; inverse bind matrices of the rest pose.
  std::vector<mat4> model(nj);
  local_to_model(skeleton, rest_pose(skeleton), model);
  std::vector<mat4> inverse_bind(nj);
  for (std::size_t j = 0; j < nj; ++j) inverse_bind[j] = glm::inverse(model[j]);
  const int ibm = accessor(bin.add_view(inverse_bind.data(), nj * sizeof(mat4), 0), kFloat, nj, "MAT4");
  json nodes = json::array(), scene_nodes = json::array(), skin_joints = json::array();
  std::vector<json> children(nj, json::array());
  for (std::size_t j = 0; j < nj; ++j)
    if (skeleton.parents[j] >= 0) children[static_cast<std::size_t>(skeleton.parents[j])].push_back(j);
  for (std::size_t j = 0; j < nj; ++j) {
    const vec3 t = skeleton.rest_translations[j], s = skeleton.rest_scales[j];
    const quat q = glm::normalize(skeleton.rest_rotations[j]);
    json node{{"name", skeleton.names[j]}, {"translation", {t.x, t.y, t.z}}};
    if (q != quat(1, 0, 0, 0)) node["rotation"] = {q.x, q.y, q.z, q.w};
    if (s != vec3(1.0f)) node["scale"] = {s.x, s.y, s.z};
    if (!children[j].empty()) node["children"] = children[j];
    nodes.push_back(node);
    skin_joints.push_back(j);
    if (skeleton.parents[j] < 0) scene_nodes.push_back(j);
  }
  json mesh_json{{"name", name}, {"primitives", primitives}};
  if (!targets.empty()) {
    mesh_json["weights"] = default_weights;
    mesh_json["extras"] = {{"targetNames", target_names}};
  }
  nodes.push_back({{"name", name}, {"mesh", 0}, {"skin", 0}});
  scene_nodes.push_back(nj);

  while (bin.bytes.size() % 4) bin.bytes.push_back(0);
  json gltf{{"asset", {{"version", "2.0"}, {"generator", "gestura"}}},
            {"scene", 0},
            {"scenes", {{{"name", name}, {"nodes", scene_nodes}}}},
            {"nodes", nodes},
            {"meshes", {mesh_json}},
            {"materials", materials},
            {"skins", {{{"joints", skin_joints}, {"inverseBindMatrices", ibm}, {"skeleton", 0}}}},
            {"accessors", accessors},
            {"bufferViews", bin.views},
            {"buffers", {{{"byteLength", bin.bytes.size()}}}}};
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');

  std::vector<std::uint8_t> out;
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xff));
  };
  const std::size_t total = 12 + 8 + text.size() + 8 + bin.bytes.size();
  if (total > std::numeric_limits<std::uint32_t>::max()) throw Error("glTF export: result exceeds 4 GiB");
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(static_cast<std::uint32_t>(total));
  u32(static_cast<std::uint32_t>(text.size()));
  u32(0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  u32(static_cast<std::uint32_t>(bin.bytes.size()));
  u32(0x004E4942);  // "BIN\0"
  out.insert(out.end(), bin.bytes.begin(), bin.bytes.end());
  return out;
}

void write_glb(const std::string& path, const Skeleton& skeleton, const Mesh& mesh, const std::string& name) {
  const std::vector<std::uint8_t> bytes = encode_glb(skeleton, mesh, name);
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace gestura
