#pragma once
// The studio's Environment Editor and Colour Editor (alias-movement-through-environments.txt ch. 7,
// §7.1): the scene in the four ALIAS views at once — two perspective views that orbit, the plan (top,
// orthographic) and the section (front, orthographic) — drawn by the scene renderer; objects, parts,
// places and characters picked by clicking in any view and moved, turned and scaled by dragging the
// gizmo's handles; the palette of nearby colours applied live. The editing itself is plain data
// (gestura/studio/environment_editor.hpp, colour_editor.hpp); this file turns the mouse and the
// script into its calls and draws it. Needs the studio's OpenGL context current.
#include <memory>
#include <string>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "gestura/body/avatar.hpp"
#include "gestura/studio/script.hpp"

namespace gestura::studio_ui {

class EnvironmentPanel {
 public:
  // `render_scale`: the views render at this fraction of their pixels (--preview-scale; faster on a CPU).
  explicit EnvironmentPanel(const Avatar& avatar, float render_scale = 1.0f);
  ~EnvironmentPanel();
  EnvironmentPanel(const EnvironmentPanel&) = delete;
  EnvironmentPanel& operator=(const EnvironmentPanel&) = delete;

  // Draws the four views into their texture when something changed (call before the UI frame).
  void render();
  // The mode's panels inside the rectangle: scene tree (left), views (centre), properties and colour
  // editor (right).
  void draw(const ImVec2& pos, const ImVec2& size);
  // Keys of the mode (outside text fields): Ctrl+Z/Y, Del, Ctrl+D, W/E/R tools, F frame all.
  void shortcuts();
  // A script step of this mode (env-*, and undo/redo); false when it is not one. Throws
  // gestura::Error for bad arguments (the studio reports it with the line).
  bool execute(const studio::ScriptStep& step);
  bool busy() const;  // a walk being performed for the preview
  // The Edit menu's undo and redo in this mode, and what they would undo / redo ("" when nothing).
  void undo();
  void redo();
  std::string undo_label() const;
  std::string redo_label() const;
  nlohmann::json dump() const;
  const std::string& status() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gestura::studio_ui
