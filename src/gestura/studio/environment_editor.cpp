#include "gestura/studio/environment_editor.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/world/color_palette.hpp"
#include "gestura/world/scene_json.hpp"

namespace gestura::studio {
namespace {

constexpr float kPlaceMarkerRadius = 0.25f;
constexpr int kMaxDepth = 32;  // groups and prototypes nest at most this deep (validate() refuses cycles)

Scene new_scene() {
  Scene s;
  s.name = "untitled";
  s.materials[kDefaultMaterial] = Material{};
  s.materials["floor"] = Material{vec3(0.61f, 0.52f, 0.40f), 0.15f};
  SceneObject floor;
  floor.name = "floor";
  floor.material = "floor";
  floor.shape.kind = ShapeKind::Plane;
  floor.shape.size = vec3(6.0f, 0.0f, 6.0f);
  s.objects.push_back(floor);
  return s;
}

std::string dump(const Scene& s) { return scene_to_json(s).dump(); }

// The object a path names, or null.
template <class SceneT>
auto object_at(SceneT& scene, const std::vector<int>& path) -> decltype(&scene.objects[0]) {
  if (path.empty() || path[0] < 0 || static_cast<std::size_t>(path[0]) >= scene.objects.size()) return nullptr;
  auto* o = &scene.objects[static_cast<std::size_t>(path[0])];
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (path[i] < 0 || static_cast<std::size_t>(path[i]) >= o->parts.size()) return nullptr;
    o = &o->parts[static_cast<std::size_t>(path[i])];
  }
  return o;
}

// Visits every primitive under `o` (its frame → world = `m`), prototypes expanded.
template <class Visit>
void visit_primitives(const Scene& scene, const SceneObject& o, const mat4& m, int depth, Visit&& visit) {
  if (depth > kMaxDepth) return;
  const mat4 here = m * o.transform.matrix();
  if (o.shape.kind != ShapeKind::None) visit(o.shape, here);
  for (const SceneObject& p : o.parts) visit_primitives(scene, p, here, depth + 1, visit);
  if (!o.instance.empty())
    if (const auto it = scene.prototypes.find(o.instance); it != scene.prototypes.end())
      visit_primitives(scene, it->second, here, depth + 1, visit);
}

}  // namespace

EnvironmentEditor::EnvironmentEditor() : scene_(new_scene()) {}

void EnvironmentEditor::open(const std::string& path) {
  Scene loaded = read_scene(path);  // throws, located; nothing here has changed yet
  if (editing_) end_edit();
  scene_ = std::move(loaded);
  file_ = path;
  selection_ = {};
  history_.clear(), done_ = 0;
  ++revision_, ++geometry_revision_;
  saved_revision_ = revision_;
  status_ = "opened " + path;
}

void EnvironmentEditor::save(const std::string& path) {
  const std::string target = path.empty() ? file_ : path;
  if (target.empty()) throw Error("the scene has no file yet: save it under a name");
  if (editing_) end_edit();
  validate(scene_);
  write_file_atomically(target, scene_to_json(scene_).dump(2) + "\n");
  file_ = target;
  saved_revision_ = revision_;
  status_ = "saved " + target;
}

// ---- selection ----

void EnvironmentEditor::select(const EnvSelection& selection) {
  selection_ = selection;
  if (selection_.kind == EnvItem::Object && !object_at(scene_, selection_.path)) selection_ = {};
  if (selection_.kind == EnvItem::Character &&
      (selection_.path.empty() || selection_.path[0] < 0 || static_cast<std::size_t>(selection_.path[0]) >= scene_.characters.size()))
    selection_ = {};
  if (selection_.kind == EnvItem::Place && !scene_.places.contains(selection_.place)) selection_ = {};
}

void EnvironmentEditor::select(const std::string& spec) {
  EnvSelection s;
  if (spec.rfind("place:", 0) == 0) {
    s.kind = EnvItem::Place, s.place = spec.substr(6);
    if (!scene_.places.contains(s.place)) throw Error("no place '" + s.place + "' in the scene");
  } else if (spec.rfind("character:", 0) == 0) {
    const std::string name = spec.substr(10);
    for (std::size_t i = 0; i < scene_.characters.size(); ++i)
      if (scene_.characters[i].name == name) s.kind = EnvItem::Character, s.path = {static_cast<int>(i)};
    if (s.empty()) throw Error("no character '" + name + "' in the scene");
  } else {
    const std::string top = spec.substr(0, spec.find('/'));
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      if (scene_.objects[i].name == top) s.kind = EnvItem::Object, s.path = {static_cast<int>(i)};
    if (s.empty()) throw Error("no object '" + top + "' in the scene");
    for (std::size_t at = spec.find('/'); at != std::string::npos; at = spec.find('/', at + 1)) {
      const std::string index = spec.substr(at + 1, spec.find('/', at + 1) - at - 1);
      if (index.empty() || index.size() > 6 || index.find_first_not_of("0123456789") != std::string::npos)
        throw Error("'" + spec + "': a part is named by its index (sofa/2)");
      s.path.push_back(std::stoi(index));
    }
    if (!object_at(scene_, s.path)) throw Error("'" + spec + "': no such part");
  }
  selection_ = s;
}

std::string EnvironmentEditor::selection_name() const {
  switch (selection_.kind) {
    case EnvItem::Place: return "place:" + selection_.place;
    case EnvItem::Character: return "character:" + scene_.characters[static_cast<std::size_t>(selection_.path[0])].name;
    case EnvItem::Object: {
      std::string name = scene_.objects[static_cast<std::size_t>(selection_.path[0])].name;
      for (std::size_t i = 1; i < selection_.path.size(); ++i) name += "/" + std::to_string(selection_.path[i]);
      return name;
    }
    default: return "";
  }
}

EnvSelection EnvironmentEditor::pick(const Ray& ray, const SceneGeometry* geometry, float* distance) const {
  EnvSelection best;
  float nearest = std::numeric_limits<float>::infinity();
  const auto consider = [&](std::optional<float> t, const EnvSelection& s) {
    if (t && *t < nearest) nearest = *t, best = s;
  };
  // Objects: the deepest part hit (a chair's leg inside the chair), picked as the part; an instance
  // is picked whole.
  std::vector<int> path;
  const auto walk = [&](auto&& self, const SceneObject& o, const mat4& parent, int depth) -> void {
    if (depth > kMaxDepth) return;
    const mat4 here = parent * o.transform.matrix();
    const EnvSelection s{EnvItem::Object, path, {}};
    if (o.shape.kind == ShapeKind::Mesh) {
      if (geometry && depth == 0) {
        const int index = path[0];
        if (static_cast<std::size_t>(index) < geometry->object_first.size()) {
          const auto first = geometry->object_first[static_cast<std::size_t>(index)], count = geometry->object_count[static_cast<std::size_t>(index)];
          consider(ray_triangles(ray, geometry->positions, std::span(geometry->indices).subspan(first, count), here), s);
        }
      }
    } else if (o.shape.kind != ShapeKind::None) {
      consider(ray_placed_shape(ray, o.shape, here), s);
    }
    if (!o.instance.empty())
      if (const auto it = scene_.prototypes.find(o.instance); it != scene_.prototypes.end())
        visit_primitives(scene_, it->second, here, depth + 1, [&](const Shape& shape, const mat4& m) {
          if (shape.kind != ShapeKind::Mesh) consider(ray_placed_shape(ray, shape, m), s);
        });
    for (std::size_t i = 0; i < o.parts.size(); ++i) {
      path.push_back(static_cast<int>(i));
      self(self, o.parts[i], here, depth + 1);
      path.pop_back();
    }
  };
  for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
    path = {static_cast<int>(i)};
    walk(walk, scene_.objects[i], mat4(1.0f), 0);
  }
  for (const auto& [name, place] : scene_.places) {
    // A flat disc on the floor, and a post above it so it can be picked from the side too.
    consider(ray_upright_cylinder(ray, place.position, kPlaceMarkerRadius, 0.05f), EnvSelection{EnvItem::Place, {}, name});
  }
  for (std::size_t i = 0; i < scene_.characters.size(); ++i) {
    const SceneCharacter& c = scene_.characters[i];
    const vec3 at = c.place.empty() || !scene_.places.contains(c.place) ? c.position : scene_.places.at(c.place).position;
    consider(ray_upright_cylinder(ray, at, c.radius, c.height), EnvSelection{EnvItem::Character, {static_cast<int>(i)}, {}});
  }
  if (distance) *distance = nearest;
  return best;
}

// ---- the selected item's frame ----

SceneObject* EnvironmentEditor::selected_object() {
  return selection_.kind == EnvItem::Object ? object_at(scene_, selection_.path) : nullptr;
}
const SceneObject* EnvironmentEditor::selected_object() const {
  return selection_.kind == EnvItem::Object ? object_at(scene_, selection_.path) : nullptr;
}

std::optional<EnvTransform> EnvironmentEditor::transform() const {
  if (const SceneObject* o = selected_object()) return EnvTransform{o->transform.position, o->transform.rotation, o->transform.scale};
  if (selection_.kind == EnvItem::Place) {
    const Place& p = scene_.places.at(selection_.place);
    return EnvTransform{p.position, vec3(0.0f, p.facing.value_or(0.0f), 0.0f), vec3(1.0f)};
  }
  if (selection_.kind == EnvItem::Character) {
    const SceneCharacter& c = scene_.characters[static_cast<std::size_t>(selection_.path[0])];
    const vec3 at = c.place.empty() || !scene_.places.contains(c.place) ? c.position : scene_.places.at(c.place).position;
    return EnvTransform{at, vec3(0.0f, c.facing, 0.0f), vec3(1.0f)};
  }
  return std::nullopt;
}

mat4 EnvironmentEditor::parent_matrix() const {
  mat4 m(1.0f);
  if (selection_.kind != EnvItem::Object) return m;
  for (std::size_t n = 1; n < selection_.path.size(); ++n) {
    const std::vector<int> prefix(selection_.path.begin(), selection_.path.begin() + static_cast<std::ptrdiff_t>(n));
    if (const SceneObject* o = object_at(scene_, prefix)) m = m * o->transform.matrix();
  }
  return m;
}

std::optional<mat4> EnvironmentEditor::world_matrix() const {
  const auto t = transform();
  if (!t) return std::nullopt;
  ObjectTransform ot{t->position, t->rotation, t->scale};
  return parent_matrix() * ot.matrix();
}

// ---- edits ----

void EnvironmentEditor::changed(bool geometry) {
  ++revision_;
  if (geometry) ++geometry_revision_;
}

void EnvironmentEditor::begin_edit(const std::string& label) {
  if (editing_) end_edit();
  editing_ = Step{label, scene_, {}, selection_, {}, false};
}

void EnvironmentEditor::set_transform(const EnvTransform& t) {
  if (!is_finite(t.position) || !is_finite(t.rotation) || !is_finite(t.scale)) {
    status_ = "refused: a transform must be finite numbers";
    return;
  }
  const bool own_step = !editing_;
  if (own_step) begin_edit("transform " + selection_name());
  if (SceneObject* o = selected_object()) {
    o->transform.position = t.position;
    o->transform.rotation = t.rotation;
    // A scale of zero or below would turn the object inside out (validate() refuses it): stop at 1 mm.
    o->transform.scale = glm::max(t.scale, vec3(0.001f));
    // A part changes its group's triangles; a top-level object only its own transform.
    if (selection_.path.size() > 1) editing_->geometry = true;
    changed(selection_.path.size() > 1);
  } else if (selection_.kind == EnvItem::Place) {
    Place& p = scene_.places.at(selection_.place);
    if (p.position != t.position || p.facing.value_or(0.0f) != t.rotation.y) {
      p.position = t.position;
      if (p.facing || t.rotation.y != 0.0f) p.facing = t.rotation.y;
    }
    changed(false);
  } else if (selection_.kind == EnvItem::Character) {
    SceneCharacter& c = scene_.characters[static_cast<std::size_t>(selection_.path[0])];
    c.place.clear();  // moved by hand: it stands where it was put
    c.position = t.position, c.facing = t.rotation.y;
    changed(false);
  }
  if (own_step) end_edit();
}

void EnvironmentEditor::end_edit() {
  if (!editing_) return;
  Step s = std::move(*editing_);
  editing_.reset();
  if (dump(s.before) == dump(scene_)) return;  // a click without a drag changes nothing
  try {
    validate(scene_);
  } catch (const Error& e) {
    scene_ = s.before;
    selection_ = s.selection_before;
    changed(true);
    status_ = "refused " + s.label + ": " + e.message();
    return;
  }
  s.after = scene_;
  s.selection_after = selection_;
  history_.resize(done_);
  history_.push_back(std::move(s));
  if (history_.size() > kMaxHistory) history_.erase(history_.begin());
  done_ = history_.size();
  status_ = history_.back().label;
}

template <class Change>
void EnvironmentEditor::step(const std::string& label, bool geometry, Change&& change) {
  begin_edit(label);
  editing_->geometry = geometry;
  change();
  changed(geometry);
  end_edit();
}

std::string EnvironmentEditor::unique_name(const std::string& stem) const {
  for (int n = 1;; ++n) {
    const std::string name = stem + std::to_string(n);
    if (!scene_.find_object(name) && !scene_.places.contains(name) && !scene_.find_character(name)) return name;
  }
}

void EnvironmentEditor::add_primitive(ShapeKind kind, const vec3& at) {
  if (kind != ShapeKind::Box && kind != ShapeKind::Plane && kind != ShapeKind::Cylinder && kind != ShapeKind::Sphere) {
    status_ = "refused: the primitives are box, plane, cylinder and sphere";
    return;
  }
  const std::string name = unique_name(shape_name(kind));
  step("add " + name, true, [&] {
    SceneObject o;
    o.name = name;
    o.shape.kind = kind;
    // Sized like a piece of furniture and standing on the floor.
    o.shape.size = kind == ShapeKind::Plane ? vec3(1.0f, 0.0f, 1.0f) : vec3(0.5f);
    o.shape.radius = 0.25f, o.shape.height = 0.5f;
    o.transform.position = at + vec3(0.0f, kind == ShapeKind::Plane ? 0.0f : 0.25f, 0.0f);
    scene_.objects.push_back(o);
    selection_ = EnvSelection{EnvItem::Object, {static_cast<int>(scene_.objects.size() - 1)}, {}};
  });
}

void EnvironmentEditor::add_place(const std::string& wanted, const vec3& at) {
  const std::string name = wanted.empty() ? unique_name("place") : wanted;
  if (scene_.places.contains(name)) {
    status_ = "refused: there is a place '" + name + "' already";
    return;
  }
  step("add place " + name, false, [&] {
    scene_.places[name] = Place{at, std::nullopt, true};
    selection_ = EnvSelection{EnvItem::Place, {}, name};
  });
}

void EnvironmentEditor::add_character(const std::string& wanted, const vec3& at) {
  const std::string name = wanted.empty() ? unique_name("person") : wanted;
  if (scene_.find_character(name)) {
    status_ = "refused: there is a character '" + name + "' already";
    return;
  }
  step("add character " + name, false, [&] {
    SceneCharacter c;
    c.name = name;
    c.position = at;
    scene_.characters.push_back(c);
    selection_ = EnvSelection{EnvItem::Character, {static_cast<int>(scene_.characters.size() - 1)}, {}};
  });
}

void EnvironmentEditor::remove_selected() {
  if (selection_.empty()) {
    status_ = "nothing selected to delete";
    return;
  }
  step("delete " + selection_name(), selection_.kind == EnvItem::Object, [&] {
    if (selection_.kind == EnvItem::Place) {
      scene_.places.erase(selection_.place);
      for (SceneCharacter& c : scene_.characters)  // who started there stays where the place was
        if (c.place == selection_.place) c.position = transform()->position, c.place.clear();
    } else if (selection_.kind == EnvItem::Character) {
      scene_.characters.erase(scene_.characters.begin() + selection_.path[0]);
    } else if (selection_.path.size() == 1) {
      scene_.objects.erase(scene_.objects.begin() + selection_.path[0]);
    } else {
      std::vector<int> parent(selection_.path.begin(), selection_.path.end() - 1);
      SceneObject* p = object_at(scene_, parent);
      p->parts.erase(p->parts.begin() + selection_.path.back());
    }
    selection_ = {};
  });
}

void EnvironmentEditor::duplicate_selected() {
  if (selection_.empty()) {
    status_ = "nothing selected to duplicate";
    return;
  }
  const vec3 offset(0.5f, 0.0f, 0.0f);
  step("duplicate " + selection_name(), selection_.kind == EnvItem::Object, [&] {
    if (selection_.kind == EnvItem::Place) {
      const std::string name = unique_name(selection_.place + "-");
      Place copy = scene_.places.at(selection_.place);
      copy.position += offset;
      scene_.places[name] = copy;
      selection_ = EnvSelection{EnvItem::Place, {}, name};
    } else if (selection_.kind == EnvItem::Character) {
      SceneCharacter copy = scene_.characters[static_cast<std::size_t>(selection_.path[0])];
      copy.position = transform()->position + offset, copy.place.clear();
      copy.name = unique_name(copy.name + "-");
      scene_.characters.push_back(copy);
      selection_.path = {static_cast<int>(scene_.characters.size() - 1)};
    } else if (selection_.path.size() == 1) {
      SceneObject copy = scene_.objects[static_cast<std::size_t>(selection_.path[0])];
      copy.name = unique_name((copy.name.empty() ? std::string("object") : copy.name) + "-");
      copy.transform.position += offset;
      copy.pointer.clear();
      scene_.objects.push_back(copy);
      selection_.path = {static_cast<int>(scene_.objects.size() - 1)};
    } else {
      std::vector<int> parent(selection_.path.begin(), selection_.path.end() - 1);
      SceneObject* p = object_at(scene_, parent);
      SceneObject copy = p->parts[static_cast<std::size_t>(selection_.path.back())];
      // The offset is along the world's +X, carried into the group's frame.
      copy.transform.position += vec3(glm::inverse(parent_matrix()) * vec4(offset, 0.0f));
      copy.pointer.clear();
      p->parts.push_back(copy);
      selection_.path.back() = static_cast<int>(p->parts.size() - 1);
    }
  });
}

void EnvironmentEditor::group(const std::vector<std::string>& names, const std::string& wanted) {
  std::vector<std::size_t> members;
  for (const std::string& n : names) {
    std::size_t index = scene_.objects.size();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      if (scene_.objects[i].name == n) index = i;
    if (index == scene_.objects.size()) {
      status_ = "refused: no object '" + n + "' to group";
      return;
    }
    if (std::find(members.begin(), members.end(), index) == members.end()) members.push_back(index);
  }
  if (members.empty()) {
    status_ = "refused: name the objects to group";
    return;
  }
  const std::string name = wanted.empty() ? unique_name("group") : wanted;
  if (scene_.find_object(name) && std::none_of(names.begin(), names.end(), [&](const std::string& n) { return n == name; })) {
    status_ = "refused: there is an object '" + name + "' already";
    return;
  }
  step("group " + name, true, [&] {
    vec3 centre(0.0f);
    for (std::size_t i : members) centre += scene_.objects[i].transform.position;
    centre /= static_cast<float>(members.size());
    centre.y = 0.0f;
    SceneObject g;
    g.name = name;
    g.transform.position = centre;
    std::sort(members.begin(), members.end());
    for (std::size_t i : members) {
      SceneObject part = scene_.objects[i];
      part.transform.position -= centre;
      // A part with no material of its own would take the group's: keep what it was drawn in.
      if (part.material.empty()) part.material = kDefaultMaterial;
      part.pointer.clear();
      g.parts.push_back(std::move(part));
    }
    for (auto it = members.rbegin(); it != members.rend(); ++it) scene_.objects.erase(scene_.objects.begin() + static_cast<std::ptrdiff_t>(*it));
    scene_.objects.push_back(std::move(g));
    if (!scene_.materials.contains(kDefaultMaterial)) scene_.materials[kDefaultMaterial] = Material{};
    selection_ = EnvSelection{EnvItem::Object, {static_cast<int>(scene_.objects.size() - 1)}, {}};
  });
}

void EnvironmentEditor::set_color(const vec3& color) {
  if (selection_.kind != EnvItem::Object) {
    status_ = "select an object to colour";
    return;
  }
  const auto apply = [&] { apply_color(scene_, static_cast<std::size_t>(selection_.path[0]), color); };
  if (editing_) {  // a colour dragged in the picker: one step when it is let go
    apply();
    editing_->geometry = true;
    changed(true);
    return;
  }
  step("colour " + scene_.objects[static_cast<std::size_t>(selection_.path[0])].name, true, apply);
}

std::optional<vec3> EnvironmentEditor::selected_color() const {
  if (selection_.kind != EnvItem::Object) return std::nullopt;
  std::string material;
  for (std::size_t n = 1; n <= selection_.path.size(); ++n) {
    const std::vector<int> prefix(selection_.path.begin(), selection_.path.begin() + static_cast<std::ptrdiff_t>(n));
    if (const SceneObject* o = object_at(scene_, prefix)) {
      if (!o->material.empty()) material = o->material;
      // An instance without a material of its own is drawn in its prototype's.
      else if (const auto p = scene_.prototypes.find(o->instance); !o->instance.empty() && p != scene_.prototypes.end() && !p->second.material.empty())
        material = p->second.material;
    }
  }
  if (material.empty()) material = kDefaultMaterial;
  const auto it = scene_.materials.find(material);
  return it == scene_.materials.end() ? Material{}.color : it->second.color;
}

bool EnvironmentEditor::undo() {
  if (editing_) end_edit();
  if (done_ == 0) {
    status_ = "nothing to undo";
    return false;
  }
  const Step& s = history_[--done_];
  scene_ = s.before;
  selection_ = s.selection_before;
  changed(true);
  status_ = "undid " + s.label;
  return true;
}

bool EnvironmentEditor::redo() {
  if (editing_) end_edit();
  if (done_ >= history_.size()) {
    status_ = "nothing to redo";
    return false;
  }
  const Step& s = history_[done_++];
  scene_ = s.after;
  selection_ = s.selection_after;
  changed(true);
  status_ = "redid " + s.label;
  return true;
}

}  // namespace gestura::studio
