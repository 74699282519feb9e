#pragma once
// A scene: the environment the characters live in (alias-movement-through-environments.txt ch. 7),
// as plain data an editor can change and a renderer, the collision and the path planner can read.
//
// The environment is a list of objects. An object is a transform (scale, then rotation, then
// translation: ALIAS's "scaling then translating", with rotation between) and either one shape
// (box, plane, cylinder, sphere, or a mesh read from OBJ/glTF), a list of parts (a sofa "composed of
// several rectangular solids"), or an instance of a prototype (a chair defined once, placed many
// times). Parts are objects too, so groups nest. Objects carry a material (a colour); a part without
// one takes its parent's.
//
// Conventions: metres, +Y up; a character facing 0° looks along +Z, angles turn counter-clockwise
// seen from above (toward +X). Primitives are centred on their origin (the plane lies in y = 0 facing
// +Y; the cylinder's axis is +Y).
//
// scene_json.hpp reads and writes the documented JSON form (docs/scene.md); validate() checks what
// an editor might have produced.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gestura/core/math.hpp"

namespace gestura {

class JsonLocator;

enum class ShapeKind : std::uint8_t { None, Box, Plane, Cylinder, Sphere, Mesh };

const char* shape_name(ShapeKind kind);

struct Shape {
  ShapeKind kind = ShapeKind::None;
  vec3 size{1.0f};        // box: width, height, depth; plane: width, 0, depth
  float radius = 0.5f;    // cylinder, sphere
  float height = 1.0f;    // cylinder
  int segments = 0;       // cylinder/sphere tessellation (0 = default: 32 around)
  std::string file;       // mesh: OBJ or glTF path, relative to the scene file's folder
  float file_scale = 1.0f;  // mesh: units of the file in metres (0.01 for centimetres)
};

struct ObjectTransform {
  vec3 position{0.0f};
  vec3 rotation{0.0f};  // degrees: yaw about +Y outermost, then pitch about X, then roll about Z
  vec3 scale{1.0f};

  mat4 matrix() const;  // T · R · S
  quat orientation() const;
};

// A door swings about its object's local +Y axis through the object's origin (the hinge).
struct DoorSpec {
  vec3 handle{0.0f};           // the grip point, object-local (door closed)
  float open_angle = 90.0f;    // degrees the door turns when opened (+ = counter-clockwise from above)
  float angle = 0.0f;          // current opening in degrees (0 = closed)
};

struct SceneObject {
  std::string name;            // unique among top-level objects; parts may be unnamed
  ObjectTransform transform;
  std::string material;        // "" = inherit (top level: the default material)
  Shape shape;                 // kind None when the object is a group or an instance
  std::vector<SceneObject> parts;
  std::string instance;        // name of a prototype, or ""
  std::optional<DoorSpec> door;
  bool obstacle = true;        // false: drawn but ignored by collision and path planning
  std::string pointer;         // JSON pointer of its definition, for error messages ("" when built in code)
};

struct Material {
  vec3 color{0.7f, 0.7f, 0.7f};  // sRGB 0..1
  float specular = 0.1f;         // 0..1
};

// A named place: "the chair", "the door". `facing` is where a character standing there looks.
struct Place {
  vec3 position{0.0f};
  std::optional<float> facing;   // degrees; none = keep the arrival direction
  bool on_ground = true;         // position.y is found by dropping onto the ground
};

struct SceneCharacter {
  std::string name;
  std::string avatar = "default";     // as gestura avatar: default or makehuman:DIR
  float height = 1.70f;
  float build = 1.0f;
  std::string sex = "neutral";
  vec3 position{0.0f};
  std::string place;                  // start at a named place instead of `position`
  float facing = 0.0f;                // degrees
  std::map<std::string, vec3> colors; // material name (skin, cloth, hair, …) → sRGB
  float radius = 0.3f;                // collision radius for path planning and avoidance
  float speed = 1.3f;                 // preferred walking speed m/s
  std::string pointer;
};

enum class LightKind : std::uint8_t { Directional, Point, Ambient };

struct SceneLight {
  LightKind kind = LightKind::Directional;
  vec3 direction{-0.4f, -1.0f, -0.3f};  // directional: the way the light travels
  vec3 position{0.0f, 3.0f, 0.0f};      // point
  vec3 color{1.0f};
  float intensity = 1.0f;
  bool shadows = false;
};

struct SceneCamera {
  std::string name;
  vec3 position{0.0f, 1.6f, 4.0f};
  vec3 target{0.0f, 1.0f, 0.0f};
  std::string look_at;           // a character's name: aim at it every frame (overrides target)
  float fov = 45.0f;             // vertical, degrees (perspective)
  bool orthographic = false;
  float view_height = 10.0f;     // orthographic: metres the image's height covers
};

struct Scene {
  std::string name;
  std::uint64_t seed = 1;
  std::map<std::string, Material> materials;
  std::map<std::string, SceneObject> prototypes;
  std::vector<SceneObject> objects;
  std::map<std::string, Place> places;
  std::vector<SceneCharacter> characters;
  std::vector<SceneLight> lights;
  std::vector<SceneCamera> cameras;
  vec3 background{0.62f, 0.66f, 0.70f};
  std::string base_dir;          // folder mesh files are relative to
  std::string source;            // file name for error messages
  std::string script;            // optional script text carried by the scene ("" = none)

  const SceneObject* find_object(const std::string& name) const;  // top level only
  SceneObject* find_object(const std::string& name);
  const SceneCharacter* find_character(const std::string& name) const;
  const SceneCamera* find_camera(const std::string& name) const;
};

// The material the renderer uses when an object names none.
inline constexpr const char* kDefaultMaterial = "default";

// Checks what the JSON reader checks, for scenes built or edited in code: unique names, known
// materials and prototypes, no cycle of instances, finite numbers, positive sizes. Throws
// gestura::Error naming the object by its JSON pointer (and, given the `locator` of the text it was
// read from, its file:line:column).
void validate(const Scene& scene, const JsonLocator* locator = nullptr);

// The lights used when a scene has none: a warm key from above front-left with shadows, a cool
// fill, and ambient sky light.
std::vector<SceneLight> default_lights();

}  // namespace gestura
