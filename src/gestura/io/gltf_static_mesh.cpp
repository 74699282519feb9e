#include "gestura/io/gltf_static_mesh.hpp"

#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/io/gltf_reader.hpp"

namespace gestura {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxTriangles = 4'000'000;

mat4 node_matrix(const GltfReader& r, const json& node, const std::string& where) {
  if (node.contains("matrix")) {
    const json& m = node["matrix"];
    if (!m.is_array() || m.size() != 16) r.fail(where, "matrix needs 16 numbers");
    mat4 out;
    for (int k = 0; k < 16; ++k) {
      const json& v = m[static_cast<std::size_t>(k)];
      if (!v.is_number() || !std::isfinite(v.get<double>())) r.fail(where, "matrix needs 16 finite numbers");
      out[k / 4][k % 4] = v.get<float>();
    }
    return out;
  }
  Transform t;
  t.translation = json_vec3(r, node, "translation", vec3(0.0f), where);
  t.scale = json_vec3(r, node, "scale", vec3(1.0f), where);
  if (node.contains("rotation")) {
    const json& a = node["rotation"];
    if (!a.is_array() || a.size() != 4) r.fail(where, "rotation needs 4 numbers");
    for (const json& v : a)
      if (!v.is_number()) r.fail(where, "rotation needs 4 numbers");
    const quat q(a[3].get<float>(), a[0].get<float>(), a[1].get<float>(), a[2].get<float>());
    if (!is_finite(q) || glm::length(q) < 1e-6f) r.fail(where, "rotation is not a usable quaternion");
    t.rotation = glm::normalize(q);
  }
  return t.matrix();
}

std::size_t checked_index(const GltfReader& r, const json& value, std::size_t size, const std::string& where, const char* what) {
  if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() >= static_cast<long long>(size))
    r.fail(where, std::string("refers to a missing ") + what + " " + value.dump());
  return value.get<std::size_t>();
}

vec3 material_color(const GltfReader& r, const json& prim, const std::string& where) {
  if (!prim.contains("material")) return vec3(1.0f);
  const json& materials = r.array("materials");
  const json& m = materials[checked_index(r, prim["material"], materials.size(), where, "material")];
  if (!m.is_object() || !m.contains("pbrMetallicRoughness")) return vec3(1.0f);
  const json& pbr = m["pbrMetallicRoughness"];
  if (!pbr.is_object() || !pbr.contains("baseColorFactor")) return vec3(1.0f);
  const json& f = pbr["baseColorFactor"];
  if (!f.is_array() || f.size() < 3) r.fail(where, "baseColorFactor needs 4 numbers");
  vec3 linear;
  for (int i = 0; i < 3; ++i) {
    const json& v = f[static_cast<std::size_t>(i)];
    if (!v.is_number()) r.fail(where, "baseColorFactor needs 4 numbers");
    linear[i] = std::clamp(v.get<float>(), 0.0f, 1.0f);
  }
  return glm::pow(linear, vec3(1.0f / 2.2f));  // glTF factors are linear; scenes speak sRGB
}

struct Walker {
  const GltfReader& r;
  std::vector<StaticMeshPart> parts;
  std::vector<int> on_path;
  std::size_t triangles = 0;
  std::size_t visits = 0;

  void mesh(std::size_t mi, const mat4& transform) {
    const json& meshes = r.array("meshes");
    const json& gmesh = meshes[mi];
    const std::string mwhere = "meshes[" + std::to_string(mi) + "]";
    if (!gmesh.is_object() || !gmesh.contains("primitives") || !gmesh["primitives"].is_array()) r.fail(mwhere, "needs primitives");
    const mat3 normal_matrix = glm::transpose(glm::inverse(mat3(transform)));
    const bool mirrored = glm::determinant(mat3(transform)) < 0.0f;
    for (std::size_t pi = 0; pi < gmesh["primitives"].size(); ++pi) {
      const json& prim = gmesh["primitives"][pi];
      const std::string where = mwhere + ".primitives[" + std::to_string(pi) + "]";
      if (!prim.is_object() || !prim.contains("attributes") || !prim["attributes"].is_object()) r.fail(where, "needs attributes");
      if (prim.contains("mode") && !(prim["mode"].is_number_integer() && prim["mode"].get<int>() == 4)) continue;
      const json& attr = prim["attributes"];
      if (!attr.contains("POSITION")) r.fail(where, "has no POSITION");
      int width = 0;
      const std::vector<float> pos = r.accessor(attr["POSITION"], where, &width);
      if (width != 3) r.fail(where, "POSITION is not VEC3");
      const std::size_t count = pos.size() / 3;
      std::vector<float> nrm;
      if (attr.contains("NORMAL")) {
        nrm = r.accessor(attr["NORMAL"], where, &width);
        if (width != 3 || nrm.size() != pos.size()) r.fail(where, "NORMAL does not match POSITION");
      }
      StaticMeshPart part;
      part.name = gmesh.contains("name") && gmesh["name"].is_string() ? gmesh["name"].get<std::string>() : "mesh " + std::to_string(mi);
      part.color = material_color(r, prim, where);
      for (std::size_t v = 0; v < count; ++v) {
        const vec3 p(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
        if (!is_finite(p)) r.fail(where, "POSITION " + std::to_string(v) + " is not finite");
        part.positions.push_back(vec3(transform * vec4(p, 1.0f)));
      }
      std::vector<std::uint32_t> idx;
      if (prim.contains("indices")) {
        const std::vector<float> raw = r.accessor(prim["indices"], where, &width);
        if (width != 1 || raw.size() % 3) r.fail(where, "indices are not whole triangles");
        for (float i : raw) {
          if (!(i >= 0.0f && i < static_cast<float>(count))) r.fail(where, "index " + std::to_string(i) + " past its " + std::to_string(count) + " vertices");
          idx.push_back(static_cast<std::uint32_t>(i));
        }
      } else {
        if (count % 3) r.fail(where, "vertex count is not whole triangles");
        for (std::size_t i = 0; i < count; ++i) idx.push_back(static_cast<std::uint32_t>(i));
      }
      triangles += idx.size() / 3;
      if (triangles > kMaxTriangles) r.fail(where, "more than 4 million triangles in the file");
      for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
        part.indices.push_back(idx[t]);
        part.indices.push_back(idx[t + (mirrored ? 2 : 1)]);
        part.indices.push_back(idx[t + (mirrored ? 1 : 2)]);
      }
      part.normals.assign(count, vec3(0.0f));
      if (!nrm.empty()) {
        for (std::size_t v = 0; v < count; ++v) {
          const vec3 n = normal_matrix * vec3(nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]);
          part.normals[v] = glm::length(n) > 1e-12f ? glm::normalize(n) : vec3(0, 1, 0);
        }
      } else {
        for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
          const vec3 a = part.positions[part.indices[t]], b = part.positions[part.indices[t + 1]], c = part.positions[part.indices[t + 2]];
          const vec3 n = glm::cross(b - a, c - a);
          for (int k = 0; k < 3; ++k) part.normals[part.indices[t + static_cast<std::size_t>(k)]] += n;
        }
        for (vec3& n : part.normals) n = glm::length(n) > 1e-20f ? glm::normalize(n) : vec3(0, 1, 0);
      }
      if (!part.indices.empty()) parts.push_back(std::move(part));
    }
  }

  void node(std::size_t ni, const mat4& parent) {
    const json& nodes = r.array("nodes");
    const std::string where = "nodes[" + std::to_string(ni) + "]";
    for (int n : on_path)
      if (static_cast<std::size_t>(n) == ni) r.fail(where, "the node tree has a cycle");
    if (on_path.size() > 256) r.fail(where, "the node tree is deeper than 256");
    if (++visits > 100000) r.fail(where, "more than 100000 node visits (nodes shared by many parents)");
    const json& n = nodes[ni];
    if (!n.is_object()) r.fail(where, "not an object");
    const mat4 transform = parent * node_matrix(r, n, where);
    on_path.push_back(static_cast<int>(ni));
    if (n.contains("mesh")) mesh(checked_index(r, n["mesh"], r.array("meshes").size(), where, "mesh"), transform);
    if (n.contains("children")) {
      if (!n["children"].is_array()) r.fail(where, "children is not an array");
      for (const json& c : n["children"]) node(checked_index(r, c, nodes.size(), where, "child node"), transform);
    }
    on_path.pop_back();
  }
};

}  // namespace

std::vector<StaticMeshPart> read_gltf_static_mesh(const std::string& bytes, const std::string& source) {
  const GltfReader r(bytes, source);
  Walker w{r, {}, {}, 0, 0};
  const json& doc = r.doc();
  const json& nodes = r.array("nodes");
  std::vector<std::size_t> roots;
  if (doc.contains("scenes") && doc["scenes"].is_array() && !doc["scenes"].empty()) {
    std::size_t scene = 0;
    if (doc.contains("scene")) scene = checked_index(r, doc["scene"], doc["scenes"].size(), "scene", "scene");
    const json& s = doc["scenes"][scene];
    if (s.is_object() && s.contains("nodes")) {
      if (!s["nodes"].is_array()) r.fail("scenes[" + std::to_string(scene) + "]", "nodes is not an array");
      for (const json& n : s["nodes"]) roots.push_back(checked_index(r, n, nodes.size(), "scenes[" + std::to_string(scene) + "]", "node"));
    }
  } else {
    // No scene: every node no other node lists as a child is a root.
    std::vector<bool> child(nodes.size(), false);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].is_object() && nodes[i].contains("children") && nodes[i]["children"].is_array())
        for (const json& c : nodes[i]["children"]) child[checked_index(r, c, nodes.size(), "nodes[" + std::to_string(i) + "]", "child node")] = true;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (!child[i]) roots.push_back(i);
  }
  for (std::size_t root : roots) w.node(root, mat4(1.0f));
  if (w.parts.empty()) throw Error(source + ": no triangle geometry in the glTF file");
  return std::move(w.parts);
}

}  // namespace gestura
