#include "gestura/world/scene.hpp"

#include <set>

#include "gestura/core/error.hpp"
#include "gestura/world/json_locate.hpp"

namespace gestura {

const char* shape_name(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::None: return "none";
    case ShapeKind::Box: return "box";
    case ShapeKind::Plane: return "plane";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Mesh: return "mesh";
  }
  return "?";
}

quat ObjectTransform::orientation() const {
  const quat yaw = glm::angleAxis(deg(rotation.y), vec3(0, 1, 0));
  const quat pitch = glm::angleAxis(deg(rotation.x), vec3(1, 0, 0));
  const quat roll = glm::angleAxis(deg(rotation.z), vec3(0, 0, 1));
  return yaw * pitch * roll;
}

mat4 ObjectTransform::matrix() const {
  Transform t;
  t.translation = position;
  t.rotation = orientation();
  t.scale = scale;
  return t.matrix();
}

const SceneObject* Scene::find_object(const std::string& object_name) const {
  for (const SceneObject& o : objects)
    if (o.name == object_name) return &o;
  return nullptr;
}

SceneObject* Scene::find_object(const std::string& object_name) {
  for (SceneObject& o : objects)
    if (o.name == object_name) return &o;
  return nullptr;
}

const SceneCharacter* Scene::find_character(const std::string& character_name) const {
  for (const SceneCharacter& c : characters)
    if (c.name == character_name) return &c;
  return nullptr;
}

const SceneCamera* Scene::find_camera(const std::string& camera_name) const {
  for (const SceneCamera& c : cameras)
    if (c.name == camera_name) return &c;
  return nullptr;
}

std::vector<SceneLight> default_lights() {
  SceneLight key;
  key.kind = LightKind::Directional;
  key.direction = glm::normalize(vec3(-0.45f, -1.0f, -0.55f));
  key.color = vec3(1.0f, 0.96f, 0.9f);
  key.intensity = 1.1f;
  key.shadows = true;
  SceneLight fill;
  fill.kind = LightKind::Directional;
  fill.direction = glm::normalize(vec3(0.6f, -0.5f, 0.4f));
  fill.color = vec3(0.75f, 0.82f, 1.0f);
  fill.intensity = 0.35f;
  SceneLight sky;
  sky.kind = LightKind::Ambient;
  sky.color = vec3(0.85f, 0.9f, 1.0f);
  sky.intensity = 0.35f;
  return {key, fill, sky};
}

namespace {

class Checker {
 public:
  Checker(const Scene& scene, const JsonLocator* locator) : scene_(scene), locator_(locator) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    if (locator_) locator_->fail(pointer, message);
    const std::string where = pointer.empty() ? std::string("/") : pointer;
    throw Error(SourceLocation{scene_.source, 0, 0}, where + ": " + message);
  }

  void finite(const vec3& v, const std::string& pointer, const char* what) const {
    if (!is_finite(v)) fail(pointer, std::string(what) + " is not a finite number");
  }
  void finite(float v, const std::string& pointer, const char* what) const {
    if (!std::isfinite(v)) fail(pointer, std::string(what) + " is not a finite number");
  }
  void positive(float v, const std::string& pointer, const char* what) const {
    finite(v, pointer, what);
    if (!(v > 0.0f)) fail(pointer, std::string(what) + " must be positive, got " + std::to_string(v));
  }

  void shape(const Shape& s, const std::string& at) const {
    switch (s.kind) {
      case ShapeKind::Box:
        finite(s.size, at + "/size", "size");
        for (int i = 0; i < 3; ++i) positive(s.size[i], at + "/size", "every box side");
        break;
      case ShapeKind::Plane:
        positive(s.size.x, at + "/size", "plane width");
        positive(s.size.z, at + "/size", "plane depth");
        break;
      case ShapeKind::Cylinder:
        positive(s.radius, at + "/radius", "radius");
        positive(s.height, at + "/height", "height");
        break;
      case ShapeKind::Sphere: positive(s.radius, at + "/radius", "radius"); break;
      case ShapeKind::Mesh:
        if (s.file.empty()) fail(at + "/file", "a mesh needs a file (.obj, .gltf or .glb)");
        positive(s.file_scale, at + "/unit", "unit");
        break;
      case ShapeKind::None: break;
    }
    if (s.segments != 0 && (s.segments < 3 || s.segments > 256))
      fail(at + "/segments", "segments must be 3..256, got " + std::to_string(s.segments));
  }

  void object(const SceneObject& o, const std::string& at, int depth) const {
    if (depth > 64) fail(at, "parts nest more than 64 deep");
    const ObjectTransform& t = o.transform;
    finite(t.position, at + "/position", "position");
    finite(t.rotation, at + "/rotation", "rotation");
    finite(t.scale, at + "/scale", "scale");
    for (int i = 0; i < 3; ++i) positive(t.scale[i], at + "/scale", "scale");
    if (!o.material.empty() && o.material != kDefaultMaterial && !scene_.materials.count(o.material))
      fail(at + "/material", "unknown material '" + o.material + "'" + known_materials());
    const int kinds = (o.shape.kind != ShapeKind::None) + !o.parts.empty() + !o.instance.empty();
    if (kinds == 0) fail(at, "an object needs a shape, parts or an instance");
    if (kinds > 1) fail(at, "an object has one of: a shape, parts, an instance");
    shape(o.shape, at);
    if (!o.instance.empty() && !scene_.prototypes.count(o.instance))
      fail(at + "/instance", "unknown prototype '" + o.instance + "'");
    if (o.door) {
      if (depth > 0) fail(at + "/door", "only a top-level object can be a door");
      finite(o.door->handle, at + "/door/handle", "handle");
      finite(o.door->open_angle, at + "/door/open_angle", "open_angle");
      if (std::abs(o.door->open_angle) > 180.0f) fail(at + "/door/open_angle", "open_angle must be within ±180 degrees");
    }
    for (std::size_t i = 0; i < o.parts.size(); ++i) object(o.parts[i], at + "/parts/" + std::to_string(i), depth + 1);
  }

  // Depth-first over instance references; a prototype met again on the current path is a cycle.
  void instances(const SceneObject& o, const std::string& at, std::vector<std::string>& path) const {
    if (!o.instance.empty()) {
      for (const std::string& p : path)
        if (p == o.instance) {
          std::string cycle;
          for (const std::string& q : path) cycle += q + " → ";
          fail(at + "/instance", "prototypes form a cycle: " + cycle + o.instance);
        }
      const auto it = scene_.prototypes.find(o.instance);
      if (it == scene_.prototypes.end() || done_.count(o.instance)) return;
      path.push_back(o.instance);
      const std::string proto_at = it->second.pointer.empty() ? "/prototypes/" + o.instance : it->second.pointer;
      instances(it->second, proto_at, path);
      path.pop_back();
      done_.insert(o.instance);  // explored without a cycle: later references need no second walk
    }
    for (std::size_t i = 0; i < o.parts.size(); ++i) instances(o.parts[i], at + "/parts/" + std::to_string(i), path);
  }

  std::string known_materials() const {
    std::string out = " (known:";
    for (const auto& [name, m] : scene_.materials) out += " " + name;
    return out + ")";
  }

  void run() const {
    for (const auto& [name, m] : scene_.materials) {
      finite(m.color, "/materials/" + name + "/color", "color");
      if (m.specular < 0.0f || m.specular > 1.0f || !std::isfinite(m.specular))
        fail("/materials/" + name + "/specular", "specular must be 0..1");
    }
    for (const auto& [name, p] : scene_.prototypes) {
      const std::string at = p.pointer.empty() ? "/prototypes/" + name : p.pointer;
      object(p, at, 1);
      std::vector<std::string> path{name};
      instances(p, at, path);
    }
    std::set<std::string> names;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& o = scene_.objects[i];
      const std::string at = o.pointer.empty() ? "/objects/" + std::to_string(i) : o.pointer;
      if (!o.name.empty() && !names.insert(o.name).second) fail(at + "/name", "a second object named '" + o.name + "'");
      object(o, at, 0);
      std::vector<std::string> path;
      instances(o, at, path);
    }
    for (const auto& [name, p] : scene_.places) {
      finite(p.position, "/places/" + name + "/position", "position");
      if (p.facing) finite(*p.facing, "/places/" + name + "/facing", "facing");
    }
    std::set<std::string> characters;
    for (std::size_t i = 0; i < scene_.characters.size(); ++i) {
      const SceneCharacter& c = scene_.characters[i];
      const std::string at = c.pointer.empty() ? "/characters/" + std::to_string(i) : c.pointer;
      if (c.name.empty()) fail(at + "/name", "a character needs a name");
      if (!characters.insert(c.name).second) fail(at + "/name", "a second character named '" + c.name + "'");
      if (names.count(c.name)) fail(at + "/name", "'" + c.name + "' names an object too");
      finite(c.position, at + "/position", "position");
      finite(c.facing, at + "/facing", "facing");
      if (!c.place.empty() && !scene_.places.count(c.place) && !scene_.find_object(c.place))
        fail(at + "/place", "unknown place '" + c.place + "'");
      if (!(c.radius >= 0.1f && c.radius <= 1.0f)) fail(at + "/radius", "radius must be 0.1..1 m");
      if (!(c.speed >= 0.2f && c.speed <= 3.0f)) fail(at + "/speed", "speed must be 0.2..3 m/s");
      for (const auto& [material, color] : c.colors) finite(color, at + "/colors/" + material, "color");
    }
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const SceneLight& l = scene_.lights[i];
      const std::string at = "/lights/" + std::to_string(i);
      finite(l.direction, at + "/direction", "direction");
      finite(l.position, at + "/position", "position");
      finite(l.color, at + "/color", "color");
      if (!(l.intensity >= 0.0f && l.intensity < 100.0f)) fail(at + "/intensity", "intensity must be 0..100");
      if (l.kind == LightKind::Directional && glm::length(l.direction) < 1e-6f) fail(at + "/direction", "direction is zero");
    }
    std::set<std::string> cameras;
    for (std::size_t i = 0; i < scene_.cameras.size(); ++i) {
      const SceneCamera& c = scene_.cameras[i];
      const std::string at = "/cameras/" + std::to_string(i);
      if (c.name.empty()) fail(at + "/name", "a camera needs a name");
      if (!cameras.insert(c.name).second) fail(at + "/name", "a second camera named '" + c.name + "'");
      finite(c.position, at + "/position", "position");
      finite(c.target, at + "/target", "target");
      if (!(c.fov > 1.0f && c.fov < 170.0f)) fail(at + "/fov", "fov must be 1..170 degrees");
      positive(c.view_height, at + "/view_height", "view_height");
      if (c.look_at.empty() && glm::length(c.target - c.position) < 1e-4f)
        fail(at + "/target", "the camera sits on its target");
      if (!c.look_at.empty() && !scene_.find_character(c.look_at))
        fail(at + "/look_at", "unknown character '" + c.look_at + "'");
    }
    finite(scene_.background, "/background", "background");
  }

 private:
  const Scene& scene_;
  const JsonLocator* locator_;
  mutable std::set<std::string> done_;
};

}  // namespace

void validate(const Scene& scene, const JsonLocator* locator) { Checker(scene, locator).run(); }

}  // namespace gestura
