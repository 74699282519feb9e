#pragma once
// The figure editor's panels (ALIAS Tree Editor, ch. 3), drawn with Dear ImGui over a
// studio::FigureEditor: the skeleton as a tree, and the selected joint's name, rest offset, degrees
// of freedom, rotation order, limits and Denavit–Hartenberg description, with the tree edits (add a
// child, remove, copy or mirror a branch) and the skeleton file (save, load).
#include <string>

#include "gestura/studio/figure_model.hpp"

namespace gestura::studio_ui {

struct FigureView {
  int joint = -1;
  std::string rename;       // the name field of the selected joint
  int rename_for = -2;      // the joint the name field was filled for
  std::string new_joint = "new_joint";
  std::string path = "figure.bvh";
  bool show_body = true;    // the skinned body in the view
  bool show_sticks = true;  // the stick figure over it
  std::string message;      // what the last file action did
};

void draw_figure_tree(studio::FigureEditor& figure, FigureView& view);
void draw_figure_joint(studio::FigureEditor& figure, FigureView& view);

}  // namespace gestura::studio_ui
