#include "gestura/world/scene_json.hpp"

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/world/json_locate.hpp"

namespace gestura {
namespace {

using nlohmann::json;

std::string escape_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out.push_back(c);
  }
  return out;
}

// Reads the scene from a parsed document, naming every failure by pointer (and place in the text).
class Reader {
 public:
  explicit Reader(const JsonLocator& locator) : at_(locator) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const { at_.fail(pointer, message); }

  void members(const json& object, const std::string& pointer, std::initializer_list<const char*> allowed) const {
    if (!object.is_object()) fail(pointer, "expected an object, got " + std::string(object.type_name()));
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      for (const char* a : allowed) known = known || key == a;
      if (!known) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        fail(pointer + "/" + escape_token(key), "unknown member '" + key + "' (known: " + list + ")");
      }
    }
  }

  float number(const json& v, const std::string& pointer) const {
    if (!v.is_number()) fail(pointer, "expected a number, got " + std::string(v.is_string() ? "the string " + v.dump() : v.type_name()));
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::abs(d) > 1e7) fail(pointer, "the number is not finite or beyond ±1e7");
    return static_cast<float>(d);
  }
  std::string string(const json& v, const std::string& pointer) const {
    if (!v.is_string()) fail(pointer, "expected a string, got " + std::string(v.type_name()));
    return v.get<std::string>();
  }
  bool boolean(const json& v, const std::string& pointer) const {
    if (!v.is_boolean()) fail(pointer, "expected true or false, got " + std::string(v.type_name()));
    return v.get<bool>();
  }
  vec3 vector3(const json& v, const std::string& pointer) const {
    if (!v.is_array() || v.size() != 3) fail(pointer, "expected [x, y, z]");
    return {number(v[0], pointer + "/0"), number(v[1], pointer + "/1"), number(v[2], pointer + "/2")};
  }
  // [x, z] on the ground or [x, y, z].
  vec3 ground_point(const json& v, const std::string& pointer, bool& has_y) const {
    if (v.is_array() && v.size() == 2) {
      has_y = false;
      return {number(v[0], pointer + "/0"), 0.0f, number(v[1], pointer + "/1")};
    }
    has_y = true;
    return vector3(v, pointer);
  }
  vec3 color(const json& v, const std::string& pointer) const {
    try {
      return parse_scene_color(v, "color");
    } catch (const Error& e) {
      fail(pointer, e.message());
    }
  }

  Shape shape(const json& o, const std::string& at) const {
    Shape s;
    const std::string kind = string(o["shape"], at + "/shape");
    if (kind == "box") s.kind = ShapeKind::Box;
    else if (kind == "plane") s.kind = ShapeKind::Plane;
    else if (kind == "cylinder") s.kind = ShapeKind::Cylinder;
    else if (kind == "sphere") s.kind = ShapeKind::Sphere;
    else if (kind == "mesh") s.kind = ShapeKind::Mesh;
    else fail(at + "/shape", "unknown shape '" + kind + "' (box, plane, cylinder, sphere, mesh)");
    if (o.contains("size")) {
      const json& v = o["size"];
      const std::string p = at + "/size";
      if (s.kind == ShapeKind::Box) {
        if (v.is_number()) s.size = vec3(number(v, p));
        else s.size = vector3(v, p);
      } else if (s.kind == ShapeKind::Plane) {
        if (!v.is_array() || v.size() != 2) fail(p, "a plane's size is [width, depth]");
        s.size = vec3(number(v[0], p + "/0"), 0.0f, number(v[1], p + "/1"));
      } else {
        fail(p, "a " + kind + " has no size (radius" + std::string(s.kind == ShapeKind::Cylinder ? ", height" : "") + ")");
      }
    }
    if (o.contains("radius")) s.radius = number(o["radius"], at + "/radius");
    if (o.contains("height")) s.height = number(o["height"], at + "/height");
    if (o.contains("segments")) {
      const float n = number(o["segments"], at + "/segments");
      if (n != std::floor(n)) fail(at + "/segments", "segments must be a whole number");
      s.segments = static_cast<int>(n);
    }
    if (o.contains("file")) s.file = string(o["file"], at + "/file");
    if (o.contains("unit")) s.file_scale = number(o["unit"], at + "/unit");
    auto only = [&](const char* key, bool allowed) {
      if (o.contains(key) && !allowed) fail(at + "/" + key, "a " + kind + " has no " + key);
    };
    only("radius", s.kind == ShapeKind::Cylinder || s.kind == ShapeKind::Sphere);
    only("height", s.kind == ShapeKind::Cylinder);
    only("segments", s.kind == ShapeKind::Cylinder || s.kind == ShapeKind::Sphere);
    only("file", s.kind == ShapeKind::Mesh);
    only("unit", s.kind == ShapeKind::Mesh);
    return s;
  }

  SceneObject object(const json& o, const std::string& at, int depth) const {
    if (depth > 64) fail(at, "parts nest more than 64 deep");
    members(o, at, {"name", "shape", "size", "radius", "height", "segments", "file", "unit", "position", "rotation",
                    "scale", "material", "parts", "instance", "door", "obstacle"});
    SceneObject out;
    out.pointer = at;
    if (o.contains("name")) out.name = string(o["name"], at + "/name");
    if (o.contains("shape")) out.shape = shape(o, at);
    else
      for (const char* key : {"size", "radius", "height", "segments", "file", "unit"})
        if (o.contains(key)) fail(at + "/" + key, std::string(key) + " without a shape");
    if (o.contains("position")) out.transform.position = vector3(o["position"], at + "/position");
    if (o.contains("rotation")) {
      const json& r = o["rotation"];
      out.transform.rotation = r.is_number() ? vec3(0.0f, number(r, at + "/rotation"), 0.0f) : vector3(r, at + "/rotation");
    }
    if (o.contains("scale")) {
      const json& s = o["scale"];
      out.transform.scale = s.is_number() ? vec3(number(s, at + "/scale")) : vector3(s, at + "/scale");
    }
    if (o.contains("material")) out.material = string(o["material"], at + "/material");
    if (o.contains("instance")) out.instance = string(o["instance"], at + "/instance");
    if (o.contains("obstacle")) out.obstacle = boolean(o["obstacle"], at + "/obstacle");
    if (o.contains("parts")) {
      const json& parts = o["parts"];
      if (!parts.is_array()) fail(at + "/parts", "expected an array of objects");
      if (parts.empty()) fail(at + "/parts", "an empty group");
      for (std::size_t i = 0; i < parts.size(); ++i)
        out.parts.push_back(object(parts[i], at + "/parts/" + std::to_string(i), depth + 1));
    }
    if (o.contains("door")) {
      const json& d = o["door"];
      const std::string p = at + "/door";
      members(d, p, {"handle", "open_angle", "angle"});
      DoorSpec door;
      if (!d.contains("handle")) fail(p, "a door needs its handle: [x, y, z] in the door's frame");
      door.handle = vector3(d["handle"], p + "/handle");
      if (d.contains("open_angle")) door.open_angle = number(d["open_angle"], p + "/open_angle");
      if (d.contains("angle")) door.angle = number(d["angle"], p + "/angle");
      out.door = door;
    }
    return out;
  }

  Scene scene(const json& doc, const std::string& name, const std::string& base_dir) const {
    members(doc, "", {"name", "seed", "background", "materials", "prototypes", "objects", "places", "characters",
                      "lights", "cameras", "script", "version"});
    Scene s;
    s.source = name;
    s.base_dir = base_dir;
    if (doc.contains("version")) {
      const float v = number(doc["version"], "/version");
      if (v != 1.0f) fail("/version", "this gestura reads scene version 1");
    }
    if (doc.contains("name")) s.name = string(doc["name"], "/name");
    if (doc.contains("seed")) {
      const json& v = doc["seed"];
      if (!v.is_number_unsigned()) fail("/seed", "expected a whole number >= 0");
      s.seed = v.get<std::uint64_t>();
    }
    if (doc.contains("background")) s.background = color(doc["background"], "/background");
    if (doc.contains("materials")) {
      const json& m = doc["materials"];
      if (!m.is_object()) fail("/materials", "expected an object of named materials");
      for (const auto& [key, value] : m.items()) {
        const std::string p = "/materials/" + escape_token(key);
        Material material;
        if (value.is_string() || value.is_array()) {
          material.color = color(value, p);
        } else {
          members(value, p, {"color", "specular"});
          if (value.contains("color")) material.color = color(value["color"], p + "/color");
          if (value.contains("specular")) material.specular = number(value["specular"], p + "/specular");
        }
        s.materials[key] = material;
      }
    }
    if (doc.contains("prototypes")) {
      const json& m = doc["prototypes"];
      if (!m.is_object()) fail("/prototypes", "expected an object of named prototypes");
      for (const auto& [key, value] : m.items()) {
        SceneObject p = object(value, "/prototypes/" + escape_token(key), 1);
        if (p.name.empty()) p.name = key;
        s.prototypes[key] = std::move(p);
      }
    }
    if (doc.contains("objects")) {
      const json& objects = doc["objects"];
      if (!objects.is_array()) fail("/objects", "expected an array of objects");
      if (objects.size() > 100000) fail("/objects", "more than 100000 objects");
      for (std::size_t i = 0; i < objects.size(); ++i) s.objects.push_back(object(objects[i], "/objects/" + std::to_string(i), 0));
    }
    if (doc.contains("places")) {
      const json& m = doc["places"];
      if (!m.is_object()) fail("/places", "expected an object of named places");
      for (const auto& [key, value] : m.items()) {
        const std::string p = "/places/" + escape_token(key);
        Place place;
        if (value.is_array()) {
          place.position = ground_point(value, p, place.on_ground);
          place.on_ground = true;
        } else {
          members(value, p, {"position", "facing"});
          if (!value.contains("position")) fail(p, "a place needs a position");
          bool has_y = false;
          place.position = ground_point(value["position"], p + "/position", has_y);
          place.on_ground = true;
          if (value.contains("facing")) place.facing = number(value["facing"], p + "/facing");
        }
        s.places[key] = place;
      }
    }
    if (doc.contains("characters")) {
      const json& list = doc["characters"];
      if (!list.is_array()) fail("/characters", "expected an array of characters");
      if (list.size() > 1000) fail("/characters", "more than 1000 characters");
      for (std::size_t i = 0; i < list.size(); ++i) s.characters.push_back(character(list[i], "/characters/" + std::to_string(i)));
    }
    if (doc.contains("lights")) {
      const json& list = doc["lights"];
      if (!list.is_array()) fail("/lights", "expected an array of lights");
      if (list.size() > 8) fail("/lights", "at most 8 lights");
      for (std::size_t i = 0; i < list.size(); ++i) s.lights.push_back(light(list[i], "/lights/" + std::to_string(i)));
    }
    if (doc.contains("cameras")) {
      const json& list = doc["cameras"];
      if (!list.is_array()) fail("/cameras", "expected an array of cameras");
      for (std::size_t i = 0; i < list.size(); ++i) s.cameras.push_back(camera(list[i], "/cameras/" + std::to_string(i)));
    }
    if (doc.contains("script")) {
      const json& v = doc["script"];
      if (v.is_string()) s.script = v.get<std::string>();
      else if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i) s.script += string(v[i], "/script/" + std::to_string(i)) + "\n";
      } else fail("/script", "expected the script as a string or an array of lines");
    }
    return s;
  }

  SceneCharacter character(const json& c, const std::string& at) const {
    members(c, at, {"name", "avatar", "height", "build", "sex", "position", "place", "facing", "colors", "radius", "speed"});
    SceneCharacter out;
    out.pointer = at;
    if (!c.contains("name")) fail(at, "a character needs a name");
    out.name = string(c["name"], at + "/name");
    if (c.contains("avatar")) out.avatar = string(c["avatar"], at + "/avatar");
    if (c.contains("height")) out.height = number(c["height"], at + "/height");
    if (c.contains("build")) out.build = number(c["build"], at + "/build");
    if (c.contains("sex")) out.sex = string(c["sex"], at + "/sex");
    if (c.contains("position")) {
      bool has_y = false;
      out.position = ground_point(c["position"], at + "/position", has_y);
    }
    if (c.contains("place")) out.place = string(c["place"], at + "/place");
    if (c.contains("facing")) out.facing = number(c["facing"], at + "/facing");
    if (c.contains("radius")) out.radius = number(c["radius"], at + "/radius");
    if (c.contains("speed")) out.speed = number(c["speed"], at + "/speed");
    if (c.contains("colors")) {
      const json& m = c["colors"];
      if (!m.is_object()) fail(at + "/colors", "expected {\"cloth\": \"#rrggbb\", …}");
      for (const auto& [key, value] : m.items()) out.colors[key] = color(value, at + "/colors/" + escape_token(key));
    }
    return out;
  }

  SceneLight light(const json& l, const std::string& at) const {
    members(l, at, {"type", "direction", "position", "color", "intensity", "shadows"});
    SceneLight out;
    const std::string type = l.contains("type") ? string(l["type"], at + "/type") : "directional";
    if (type == "directional") out.kind = LightKind::Directional;
    else if (type == "point") out.kind = LightKind::Point;
    else if (type == "ambient") out.kind = LightKind::Ambient;
    else fail(at + "/type", "unknown light type '" + type + "' (directional, point, ambient)");
    if (l.contains("direction")) out.direction = vector3(l["direction"], at + "/direction");
    if (l.contains("position")) out.position = vector3(l["position"], at + "/position");
    if (l.contains("color")) out.color = color(l["color"], at + "/color");
    if (l.contains("intensity")) out.intensity = number(l["intensity"], at + "/intensity");
    if (l.contains("shadows")) out.shadows = boolean(l["shadows"], at + "/shadows");
    if (out.kind == LightKind::Directional && glm::length(out.direction) > 0.0f) out.direction = glm::normalize(out.direction);
    return out;
  }

  SceneCamera camera(const json& c, const std::string& at) const {
    members(c, at, {"name", "position", "target", "look_at", "fov", "projection", "view_height"});
    SceneCamera out;
    if (!c.contains("name")) fail(at, "a camera needs a name");
    out.name = string(c["name"], at + "/name");
    if (c.contains("position")) out.position = vector3(c["position"], at + "/position");
    if (c.contains("target")) out.target = vector3(c["target"], at + "/target");
    if (c.contains("look_at")) out.look_at = string(c["look_at"], at + "/look_at");
    if (c.contains("fov")) out.fov = number(c["fov"], at + "/fov");
    if (c.contains("view_height")) out.view_height = number(c["view_height"], at + "/view_height");
    if (c.contains("projection")) {
      const std::string p = string(c["projection"], at + "/projection");
      if (p == "orthographic") out.orthographic = true;
      else if (p != "perspective") fail(at + "/projection", "unknown projection '" + p + "' (perspective, orthographic)");
    }
    return out;
  }

 private:
  const JsonLocator& at_;
};

json vec_json(const vec3& v) { return json::array({v.x, v.y, v.z}); }

std::string hex(const vec3& c) {
  char text[8];
  auto byte = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.x), byte(c.y), byte(c.z));
  return text;
}

json object_json(const SceneObject& o) {
  json j = json::object();
  if (!o.name.empty()) j["name"] = o.name;
  switch (o.shape.kind) {
    case ShapeKind::Box: j["shape"] = "box", j["size"] = vec_json(o.shape.size); break;
    case ShapeKind::Plane: j["shape"] = "plane", j["size"] = json::array({o.shape.size.x, o.shape.size.z}); break;
    case ShapeKind::Cylinder: j["shape"] = "cylinder", j["radius"] = o.shape.radius, j["height"] = o.shape.height; break;
    case ShapeKind::Sphere: j["shape"] = "sphere", j["radius"] = o.shape.radius; break;
    case ShapeKind::Mesh: j["shape"] = "mesh", j["file"] = o.shape.file, j["unit"] = o.shape.file_scale; break;
    case ShapeKind::None: break;
  }
  if (o.shape.segments) j["segments"] = o.shape.segments;
  if (o.transform.position != vec3(0.0f)) j["position"] = vec_json(o.transform.position);
  if (o.transform.rotation != vec3(0.0f)) j["rotation"] = vec_json(o.transform.rotation);
  if (o.transform.scale != vec3(1.0f)) j["scale"] = vec_json(o.transform.scale);
  if (!o.material.empty()) j["material"] = o.material;
  if (!o.instance.empty()) j["instance"] = o.instance;
  if (!o.obstacle) j["obstacle"] = false;
  if (o.door) j["door"] = {{"handle", vec_json(o.door->handle)}, {"open_angle", o.door->open_angle}, {"angle", o.door->angle}};
  for (const SceneObject& p : o.parts) j["parts"].push_back(object_json(p));
  return j;
}

}  // namespace

vec3 parse_scene_color(const nlohmann::json& value, const std::string& what) {
  if (value.is_string()) {
    std::string text = value.get<std::string>();
    if (!text.empty() && text[0] == '#') text.erase(0, 1);
    bool ok = text.size() == 6;
    for (char c : text) ok = ok && std::isxdigit(static_cast<unsigned char>(c));
    if (!ok) throw Error(what + ": expected \"#rrggbb\", got \"" + value.get<std::string>() + "\"");
    const unsigned long v = std::stoul(text, nullptr, 16);
    return vec3(static_cast<float>((v >> 16) & 0xFF), static_cast<float>((v >> 8) & 0xFF), static_cast<float>(v & 0xFF)) / 255.0f;
  }
  if (value.is_array() && value.size() == 3) {
    vec3 c;
    for (int i = 0; i < 3; ++i) {
      if (!value[static_cast<std::size_t>(i)].is_number()) throw Error(what + ": expected [r, g, b] numbers in 0..1");
      c[i] = value[static_cast<std::size_t>(i)].get<float>();
      if (!(c[i] >= 0.0f && c[i] <= 1.0f)) throw Error(what + ": [r, g, b] components must be in 0..1");
    }
    return c;
  }
  throw Error(what + ": expected \"#rrggbb\" or [r, g, b]");
}

Scene parse_scene(std::string_view text, const std::string& name, const std::string& base_dir) {
  if (text.size() > kMaxSceneBytes) throw Error(name + ": a scene larger than 16 MiB");
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    if (const auto colon = what.find("syntax error"); colon != std::string::npos) what = what.substr(colon);
    throw_json_syntax_error(text, name, e.byte, what);
  } catch (const json::exception& e) {
    // A number too large for a double ("number overflow parsing '1e999'"): point at the literal.
    std::string what = e.what();
    std::size_t at = std::string_view::npos;
    if (const auto q = what.find('\''); q != std::string::npos)
      if (const auto r = what.find('\'', q + 1); r != std::string::npos) at = text.find(what.substr(q + 1, r - q - 1));
    if (const auto close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
    throw_json_syntax_error(text, name, at == std::string_view::npos ? 0 : at + 1, what);
  }
  const JsonLocator locator(std::string(text), name);
  Scene scene = Reader(locator).scene(doc, name, base_dir);
  validate(scene, &locator);
  return scene;
}

Scene read_scene(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error("cannot read scene '" + path + "': no such file");
  if (std::filesystem::file_size(path, ec) > kMaxSceneBytes) throw Error(path + ": a scene larger than 16 MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read scene '" + path + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return parse_scene(buffer.str(), path, dir.empty() ? "." : dir);
}

nlohmann::json scene_to_json(const Scene& scene) {
  json j = json::object();
  j["version"] = 1;
  if (!scene.name.empty()) j["name"] = scene.name;
  j["seed"] = scene.seed;
  j["background"] = hex(scene.background);
  for (const auto& [name, m] : scene.materials) j["materials"][name] = {{"color", hex(m.color)}, {"specular", m.specular}};
  for (const auto& [name, p] : scene.prototypes) j["prototypes"][name] = object_json(p);
  j["objects"] = json::array();
  for (const SceneObject& o : scene.objects) j["objects"].push_back(object_json(o));
  for (const auto& [name, p] : scene.places) {
    json place = {{"position", vec_json(p.position)}};
    if (p.facing) place["facing"] = *p.facing;
    j["places"][name] = place;
  }
  for (const SceneCharacter& c : scene.characters) {
    json cj = {{"name", c.name}, {"avatar", c.avatar}, {"height", c.height}, {"build", c.build}, {"sex", c.sex},
               {"position", vec_json(c.position)}, {"facing", c.facing}, {"radius", c.radius}, {"speed", c.speed}};
    if (!c.place.empty()) cj["place"] = c.place;
    for (const auto& [material, color] : c.colors) cj["colors"][material] = hex(color);
    j["characters"].push_back(cj);
  }
  for (const SceneLight& l : scene.lights) {
    const char* type = l.kind == LightKind::Directional ? "directional" : l.kind == LightKind::Point ? "point" : "ambient";
    json lj = {{"type", type}, {"color", hex(l.color)}, {"intensity", l.intensity}};
    if (l.kind == LightKind::Directional) lj["direction"] = vec_json(l.direction), lj["shadows"] = l.shadows;
    if (l.kind == LightKind::Point) lj["position"] = vec_json(l.position);
    j["lights"].push_back(lj);
  }
  for (const SceneCamera& c : scene.cameras) {
    json cj = {{"name", c.name}, {"position", vec_json(c.position)}, {"target", vec_json(c.target)}, {"fov", c.fov}};
    if (!c.look_at.empty()) cj["look_at"] = c.look_at;
    if (c.orthographic) cj["projection"] = "orthographic", cj["view_height"] = c.view_height;
    j["cameras"].push_back(cj);
  }
  if (!scene.script.empty()) j["script"] = scene.script;
  return j;
}

}  // namespace gestura
