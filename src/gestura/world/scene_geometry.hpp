#pragma once
// The scene's objects flattened into triangles: prototypes expanded, groups resolved, meshes read,
// materials looked up. Geometry stays in each top-level object's own frame, so an object moved by an
// editor or a door swinging open only changes that object's transform, not its triangles.
#include <cstdint>
#include <string>
#include <vector>

#include "gestura/world/scene.hpp"
#include "gestura/world/shapes.hpp"

namespace gestura {

// One primitive after flattening, kept for exact distance queries (meshes have none).
struct PlacedPrimitive {
  int object = -1;          // top-level object index
  Shape shape;              // kind Box/Plane/Cylinder/Sphere
  mat4 to_object{1.0f};     // the primitive's frame → its object's frame
};

struct SceneGeometry {
  // Per top-level object.
  std::vector<std::string> object_names;
  std::vector<mat4> object_transforms;        // object frame → world, as the scene has it now
  std::vector<std::uint8_t> object_obstacle;  // 1 = takes part in collision and path planning
  std::vector<std::uint8_t> object_door;      // 1 = a door (moves about its hinge)
  std::vector<std::uint32_t> object_first;    // first index (into indices) of the object's triangles
  std::vector<std::uint32_t> object_count;    // its index count

  // Triangles in object frames, grouped by object.
  std::vector<vec3> positions;
  std::vector<vec3> normals;
  std::vector<vec3> colors;                   // sRGB per vertex (the material's colour)
  std::vector<float> specular;                // per vertex
  std::vector<std::uint32_t> indices;

  std::vector<PlacedPrimitive> primitives;

  std::size_t object_count_total() const { return object_names.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
  int find_object(const std::string& name) const;  // -1 when absent
};

inline constexpr std::size_t kMaxSceneTriangles = 4'000'000;

// Contract: a validated scene. Reads mesh files (OBJ, glTF/GLB) relative to scene.base_dir; throws
// gestura::Error naming the object's JSON pointer and the file's own error for unreadable or
// malformed meshes, and for scenes whose expanded prototypes exceed kMaxSceneTriangles.
SceneGeometry build_scene_geometry(const Scene& scene);

// The transform of a top-level object (its scene transform, a door turned by `door_angle` degrees
// about its hinge).
mat4 object_matrix(const SceneObject& object, float door_angle);

}  // namespace gestura
