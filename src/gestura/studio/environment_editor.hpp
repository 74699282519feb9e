#pragma once
// The Environment Editor (alias-movement-through-environments.txt ch. 7) as plain data: the scene
// being edited, what is selected, and every change as an undoable step. The studio's window draws it
// in four views and turns the mouse into the calls below; scripts and tests call them directly.
//
// What can be selected: an object (a top-level one or a part of a group, by its path of indices), a
// named place, or a character. Each has a transform the gizmo moves: an object its own (relative to
// its group), a place and a character their position and facing (rotation.y).
//
// Undo keeps whole scenes (a room is a few kilobytes): an edit is the scene before and after. A drag
// is one edit: begin_edit() when the mouse goes down, set_transform() as it moves (the views follow
// live), end_edit() when it comes up.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/studio/environment_pick.hpp"
#include "gestura/world/scene.hpp"
#include "gestura/world/scene_geometry.hpp"

namespace gestura::studio {

enum class EnvItem : std::uint8_t { None, Object, Place, Character };

struct EnvSelection {
  EnvItem kind = EnvItem::None;
  std::vector<int> path;  // Object: index into scene.objects, then into parts; Character: {index}
  std::string place;      // Place: its name

  bool empty() const { return kind == EnvItem::None; }
  bool operator==(const EnvSelection&) const = default;
};

// The transform the gizmo edits, in the frame of the item's parent (the world for anything at the
// top level).
struct EnvTransform {
  vec3 position{0.0f};
  vec3 rotation{0.0f};  // degrees (objects: yaw, pitch, roll as ObjectTransform; places, characters: facing in .y)
  vec3 scale{1.0f};     // objects only
};

class EnvironmentEditor {
 public:
  EnvironmentEditor();  // a new scene: a 6 m × 6 m floor

  // ---- files ----
  // Reads `path` (docs/scene.md). Throws gestura::Error located at file:line:column; the scene being
  // edited, its file name and its history are then left exactly as they were.
  void open(const std::string& path);
  // Writes the scene as JSON (the same format), staged and renamed: the old file stays whole if
  // anything fails. `path` "" = the file it came from. Throws gestura::Error.
  void save(const std::string& path = "");
  const std::string& file() const { return file_; }
  bool dirty() const { return revision_ != saved_revision_; }

  const Scene& scene() const { return scene_; }
  // Counts every change (the views draw again); geometry_revision() only those that change the
  // triangles (a top-level object moved, scaled or turned does not: its transform is drawn).
  std::uint64_t revision() const { return revision_; }
  std::uint64_t geometry_revision() const { return geometry_revision_; }
  // The message of the last step that did something or was refused ("moved table", "no object chiar").
  const std::string& status() const { return status_; }

  // ---- selection ----
  const EnvSelection& selection() const { return selection_; }
  void select(const EnvSelection& selection);
  // "table", "sofa/2" (a part), "place:door", "character:anna". Throws gestura::Error when absent.
  void select(const std::string& spec);
  std::string selection_name() const;  // the same spelling ("" when nothing)
  // The nearest object, place marker or character under the ray (none for empty space). Places are
  // picked by a 0.25 m disc marker, characters by an upright cylinder of their radius and height.
  // `geometry` supplies the triangles of meshes (built from this scene; may be null).
  EnvSelection pick(const Ray& ray, const SceneGeometry* geometry = nullptr, float* distance = nullptr) const;

  // ---- the selected item's frame ----
  std::optional<EnvTransform> transform() const;
  mat4 parent_matrix() const;      // the parent's frame → world (identity at the top level)
  std::optional<mat4> world_matrix() const;  // the item's frame → world (places, characters: position + facing)

  // ---- edits (each one undoable) ----
  void begin_edit(const std::string& label);
  void set_transform(const EnvTransform& t);  // live, inside begin_edit/end_edit or as one step
  void end_edit();     // records the step when the scene changed
  bool editing() const { return editing_.has_value(); }

  void add_primitive(ShapeKind kind, const vec3& at);   // box, plane, cylinder or sphere, selected
  void add_place(const std::string& name, const vec3& at);
  void add_character(const std::string& name, const vec3& at);
  void remove_selected();
  void duplicate_selected();  // a copy 0.5 m along +X, selected
  // Gathers top-level objects into a new group object `name` (its origin at their centre on the
  // floor); their transforms become relative to it, so nothing moves on screen.
  void group(const std::vector<std::string>& objects, const std::string& name);
  // Gives the selected item's top-level object the colour (world/color_palette.hpp apply_color).
  void set_color(const vec3& color);
  // The colour the selected item is drawn in (its material's, inherited through its groups).
  std::optional<vec3> selected_color() const;

  bool undo();
  bool redo();
  std::string undo_label() const { return done_ > 0 ? history_[done_ - 1].label : std::string(); }
  std::string redo_label() const { return done_ < history_.size() ? history_[done_].label : std::string(); }

  static constexpr std::size_t kMaxHistory = 200;

 private:
  struct Step {
    std::string label;
    Scene before, after;
    EnvSelection selection_before, selection_after;
    bool geometry = true;
  };
  SceneObject* selected_object();
  const SceneObject* selected_object() const;
  // Applies a one-step change: checks the result (validate); a refused change leaves the scene as it
  // was and says why in status().
  template <class Change>
  void step(const std::string& label, bool geometry, Change&& change);
  void changed(bool geometry);
  std::string unique_name(const std::string& stem) const;

  Scene scene_;
  std::string file_;
  EnvSelection selection_;
  std::vector<Step> history_;
  std::size_t done_ = 0;
  std::optional<Step> editing_;
  std::uint64_t revision_ = 0, geometry_revision_ = 0, saved_revision_ = 0;
  std::string status_;
};

}  // namespace gestura::studio
