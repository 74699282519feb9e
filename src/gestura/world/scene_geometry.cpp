#include "gestura/world/scene_geometry.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/io/gltf_static_mesh.hpp"
#include "gestura/io/makehuman.hpp"

namespace gestura {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_bytes(const std::string& path, const std::string& pointer) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error(pointer + ": cannot read mesh file '" + path + "'");
  if (std::filesystem::file_size(path, ec) > (std::size_t{512} << 20)) throw Error(pointer + ": mesh file '" + path + "' is larger than 512 MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

struct LoadedMesh {
  TriangleMesh mesh;
  std::vector<vec3> colors;  // per vertex; empty = the object's material
};

std::size_t primitive_triangles(const Shape& s) {
  const auto n = static_cast<std::size_t>(s.segments > 0 ? s.segments : kDefaultSegments);
  switch (s.kind) {
    case ShapeKind::Box: return 12;
    case ShapeKind::Plane: return 2;
    case ShapeKind::Cylinder: return 4 * n;
    case ShapeKind::Sphere: return n * std::max<std::size_t>(6, n);
    default: return 0;
  }
}

// Triangles an object expands to (meshes not counted), prototypes memoised, saturating: checked
// before anything is built, so an instance bomb costs nothing.
std::size_t expanded_triangles(const Scene& scene, const SceneObject& o, std::map<std::string, std::size_t>& memo) {
  std::size_t n = primitive_triangles(o.shape);
  for (const SceneObject& p : o.parts) n = std::min(kMaxSceneTriangles * 2, n + expanded_triangles(scene, p, memo));
  if (!o.instance.empty()) {
    auto it = memo.find(o.instance);
    if (it == memo.end()) {
      memo[o.instance] = kMaxSceneTriangles * 2;  // guards a cycle (validate() reports it properly)
      const std::size_t count = expanded_triangles(scene, scene.prototypes.at(o.instance), memo);
      it = memo.insert_or_assign(o.instance, count).first;
    }
    n = std::min(kMaxSceneTriangles * 2, n + it->second);
  }
  return n;
}

class Builder {
 public:
  Builder(const Scene& scene, SceneGeometry& out) : scene_(scene), out_(out) {}

  void object(const SceneObject& o, const mat4& to_object, const std::string& inherited_material, int top,
              const std::string& pointer, int depth) {
    const std::string material = o.material.empty() ? inherited_material : o.material;
    const mat4 here = depth == 0 ? mat4(1.0f) : to_object * o.transform.matrix();
    if (o.shape.kind == ShapeKind::Mesh) {
      const LoadedMesh& m = mesh(o.shape, pointer);
      const mat4 scaled = here * glm::scale(mat4(1.0f), vec3(o.shape.file_scale));
      add(m.mesh, scaled, material, m.colors, pointer);
    } else if (o.shape.kind != ShapeKind::None) {
      add(tessellate(o.shape), here, material, {}, pointer);
      out_.primitives.push_back({top, o.shape, here});
    }
    for (std::size_t i = 0; i < o.parts.size(); ++i)
      object(o.parts[i], here, material, top, pointer + "/parts/" + std::to_string(i), depth + 1);
    if (!o.instance.empty()) {
      if (depth > 64) throw Error(pointer + ": prototypes nest more than 64 deep");
      const SceneObject& proto = scene_.prototypes.at(o.instance);
      // The prototype is placed by the instance's transform, then its own.
      const mat4 base = here * proto.transform.matrix();
      SceneObject inner = proto;
      inner.transform = ObjectTransform{};
      object(inner, base, material, top, pointer, depth + 1);
    }
  }

 private:
  void add(const TriangleMesh& m, const mat4& transform, const std::string& material, const std::vector<vec3>& colors,
           const std::string& pointer) {
    if (out_.indices.size() / 3 + m.triangle_count() > kMaxSceneTriangles)
      throw Error(pointer + ": the scene expands to more than " + std::to_string(kMaxSceneTriangles) + " triangles");
    TriangleMesh placed;
    placed.append(m, transform);
    const auto base = static_cast<std::uint32_t>(out_.positions.size());
    const auto it = scene_.materials.find(material);
    const Material mat = it != scene_.materials.end() ? it->second : Material{};
    for (std::size_t i = 0; i < placed.positions.size(); ++i) {
      out_.positions.push_back(placed.positions[i]);
      out_.normals.push_back(placed.normals[i]);
      out_.colors.push_back(colors.empty() || !material.empty() ? mat.color : colors[i]);
      out_.specular.push_back(mat.specular);
    }
    for (std::uint32_t i : placed.indices) out_.indices.push_back(base + i);
  }

  const LoadedMesh& mesh(const Shape& s, const std::string& pointer) {
    const std::filesystem::path path = std::filesystem::path(scene_.base_dir) / s.file;
    const std::string key = path.lexically_normal().string();
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    LoadedMesh loaded;
    const std::string ext = lower_extension(key);
    try {
      if (ext == ".obj") {
        const GroupedMesh g = parse_grouped_obj(read_bytes(key, pointer), key, 1.0f);
        loaded.mesh.positions = g.mesh.positions;
        loaded.mesh.normals = g.mesh.normals;
        loaded.mesh.indices = g.mesh.indices;
      } else if (ext == ".gltf" || ext == ".glb") {
        for (const StaticMeshPart& part : read_gltf_static_mesh(read_bytes(key, pointer), key)) {
          TriangleMesh tm{part.positions, part.normals, part.indices};
          loaded.mesh.append(tm, mat4(1.0f));
          loaded.colors.insert(loaded.colors.end(), part.positions.size(), part.color);
        }
      } else {
        throw Error("unknown mesh format '" + ext + "' (.obj, .gltf, .glb)");
      }
    } catch (const Error& e) {
      throw Error(pointer + "/file: " + e.what());
    }
    if (loaded.mesh.indices.empty()) throw Error(pointer + "/file: '" + key + "' has no triangles");
    return cache_.emplace(key, std::move(loaded)).first->second;
  }

  const Scene& scene_;
  SceneGeometry& out_;
  std::map<std::string, LoadedMesh> cache_;
};

}  // namespace

int SceneGeometry::find_object(const std::string& name) const {
  for (std::size_t i = 0; i < object_names.size(); ++i)
    if (object_names[i] == name) return static_cast<int>(i);
  return -1;
}

mat4 object_matrix(const SceneObject& object, float door_angle) {
  const ObjectTransform& t = object.transform;
  const quat r = t.orientation() * glm::angleAxis(deg(door_angle), vec3(0, 1, 0));
  Transform tr;
  tr.translation = t.position;
  tr.rotation = r;
  tr.scale = t.scale;
  return tr.matrix();
}

SceneGeometry build_scene_geometry(const Scene& scene) {
  SceneGeometry out;
  std::map<std::string, std::size_t> memo;
  std::size_t total = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    total = std::min(kMaxSceneTriangles * 2, total + expanded_triangles(scene, scene.objects[i], memo));
    if (total > kMaxSceneTriangles)
      throw Error((scene.objects[i].pointer.empty() ? "/objects/" + std::to_string(i) : scene.objects[i].pointer) +
                  ": the scene expands to more than " + std::to_string(kMaxSceneTriangles) + " triangles");
  }
  Builder builder(scene, out);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const std::string pointer = o.pointer.empty() ? "/objects/" + std::to_string(i) : o.pointer;
    out.object_names.push_back(o.name);
    out.object_transforms.push_back(object_matrix(o, o.door ? o.door->angle : 0.0f));
    out.object_obstacle.push_back(o.obstacle ? 1 : 0);
    out.object_door.push_back(o.door ? 1 : 0);
    out.object_first.push_back(static_cast<std::uint32_t>(out.indices.size()));
    builder.object(o, mat4(1.0f), o.material, static_cast<int>(i), pointer, 0);
    out.object_count.push_back(static_cast<std::uint32_t>(out.indices.size()) - out.object_first.back());
  }
  return out;
}

}  // namespace gestura
