#include "figure_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <vector>

#include "gestura/core/error.hpp"

namespace gestura::studio_ui {
namespace {

void node(studio::FigureEditor& figure, FigureView& view, int joint, const std::vector<std::vector<int>>& children) {
  const Skeleton& s = figure.skeleton();
  const auto& kids = children[static_cast<std::size_t>(joint)];
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (kids.empty()) flags |= ImGuiTreeNodeFlags_Leaf;
  if (joint == view.joint) flags |= ImGuiTreeNodeFlags_Selected;
  const JointDofs& d = s.dofs[static_cast<std::size_t>(joint)];
  const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(static_cast<std::intptr_t>(joint)), flags, "%s%s",
                                      s.names[static_cast<std::size_t>(joint)].c_str(), d.count() ? "" : "  (fixed)");
  if (ImGui::IsItemClicked()) view.joint = joint;
  if (open) {
    for (const int c : kids) node(figure, view, c, children);
    ImGui::TreePop();
  }
}

}  // namespace

void draw_figure_tree(studio::FigureEditor& figure, FigureView& view) {
  const Skeleton& s = figure.skeleton();
  ImGui::TextDisabled("%zu joints, %d degrees of freedom", s.size(), s.total_dofs());
  ImGui::Checkbox("skinned body", &view.show_body);
  ImGui::SameLine();
  ImGui::Checkbox("stick figure", &view.show_sticks);
  ImGui::Separator();
  std::vector<std::vector<int>> children(s.size());
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.parents[j] >= 0) children[static_cast<std::size_t>(s.parents[j])].push_back(static_cast<int>(j));
  ImGui::BeginChild("tree");
  ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 7.0f);
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.parents[j] < 0) node(figure, view, static_cast<int>(j), children);
  ImGui::PopStyleVar();
  ImGui::EndChild();
}

void draw_figure_joint(studio::FigureEditor& figure, FigureView& view) {
  const Skeleton& s = figure.skeleton();
  // The skeleton file.
  ImGui::InputText("file", &view.path);
  if (ImGui::Button("Save skeleton")) {
    try {
      figure.save(view.path);
      view.message = "saved " + view.path + " (BVH) and " + studio::figure_sidecar_path(view.path);
    } catch (const Error& e) {
      view.message = std::string("not saved: ") + e.what();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Load skeleton")) view.message = figure.load(view.path) ? "loaded " + view.path : "not loaded: " + figure.error();
  ImGui::SameLine();
  if (ImGui::Button("Undo")) figure.undo();
  ImGui::SameLine();
  if (ImGui::Button("Redo")) figure.redo();
  if (!view.message.empty()) ImGui::TextWrapped("%s", view.message.c_str());
  ImGui::Separator();
  if (view.joint < 0 || view.joint >= static_cast<int>(s.size())) {
    ImGui::TextDisabled("select a joint in the tree");
    return;
  }
  const std::size_t j = static_cast<std::size_t>(view.joint);
  if (view.rename_for != view.joint) view.rename = s.names[j], view.rename_for = view.joint;
  ImGui::InputText("name", &view.rename);
  ImGui::SameLine();
  if (ImGui::Button("Rename") && !figure.rename(view.joint, view.rename)) view.message = figure.error();
  ImGui::Text("parent: %s", s.parents[j] < 0 ? "(root)" : s.names[static_cast<std::size_t>(s.parents[j])].c_str());
  const std::string key = std::to_string(view.joint);
  vec3 offset = s.rest_translations[j];
  if (ImGui::DragFloat3("rest offset (m)", &offset.x, 0.001f, -2.0f, 2.0f, "%.3f")) figure.set_rest_offset(view.joint, offset, "offset:" + key);
  if (ImGui::IsItemDeactivatedAfterEdit()) figure.seal();

  if (ImGui::CollapsingHeader("Degrees of freedom and limits", ImGuiTreeNodeFlags_DefaultOpen)) {
    JointDofs d = s.dofs[j];
    bool changed = false;
    int order = static_cast<int>(d.order);
    const char* orders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
    changed |= ImGui::Combo("rotation order", &order, orders, 6);
    d.order = static_cast<RotationOrder>(order);
    for (int a = 0; a < 3; ++a) {
      ImGui::PushID(a);
      bool free = d.free(a);
      char label[24];
      std::snprintf(label, sizeof label, "%c free", "xyz"[a]);
      if (ImGui::Checkbox(label, &free)) {
        d.axes = static_cast<std::uint8_t>(free ? d.axes | (1u << a) : d.axes & ~(1u << a));
        changed = true;
      }
      if (free) {
        ImGui::SameLine();
        float range[2] = {glm::degrees(d.min_angle[a]), glm::degrees(d.max_angle[a])};
        ImGui::SetNextItemWidth(-1);
        if (ImGui::DragFloat2("##limits", range, 0.5f, -180.0f, 180.0f, "%.1f deg")) {
          d.min_angle[a] = glm::radians(std::min(range[0], range[1]));
          d.max_angle[a] = glm::radians(std::max(range[0], range[1]));
          changed = true;
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) figure.seal();
      }
      ImGui::PopID();
    }
    if (changed && !figure.set_dofs(view.joint, d, "dofs:" + key)) view.message = figure.error();
  }

  if (ImGui::CollapsingHeader("Denavit-Hartenberg (ch. 4.1)", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::optional<DenavitHartenberg> dh = j < s.dh.size() ? s.dh[j] : std::nullopt;
    if (!dh) {
      ImGui::TextDisabled("no DH description");
      if (ImGui::Button("Describe from the rest offset")) figure.set_dh(view.joint, figure.dh_from_rest(view.joint));
    } else {
      DenavitHartenberg h = *dh;
      float a[4] = {h.a, glm::degrees(h.alpha), h.d, glm::degrees(h.theta)};
      bool changed = ImGui::DragFloat("a (m)", &a[0], 0.001f, -2.0f, 2.0f, "%.4f");
      changed |= ImGui::DragFloat("alpha (deg)", &a[1], 0.5f, -180.0f, 180.0f, "%.2f");
      changed |= ImGui::DragFloat("d (m)", &a[2], 0.001f, -2.0f, 2.0f, "%.4f");
      changed |= ImGui::DragFloat("theta (deg)", &a[3], 0.5f, -180.0f, 180.0f, "%.2f");
      if (changed) figure.set_dh(view.joint, DenavitHartenberg{a[0], glm::radians(a[1]), a[2], glm::radians(a[3])}, "dh:" + key);
      if (ImGui::IsItemDeactivatedAfterEdit()) figure.seal();
      const vec3 t(h.matrix(0.0f)[3]);
      const vec3 r = s.rest_translations[j];
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("Rz(theta) Tz(d) Tx(a) Rx(alpha) puts the joint at (%.3f, %.3f, %.3f); the rest offset is (%.3f, %.3f, %.3f)", t.x, t.y,
                         t.z, r.x, r.y, r.z);
      ImGui::PopStyleColor();
      if (ImGui::Button("Remove DH")) figure.set_dh(view.joint, std::nullopt);
    }
  }

  if (ImGui::CollapsingHeader("Tree", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::InputText("new joint", &view.new_joint);
    if (ImGui::Button("Add child")) {
      const int added = figure.add_joint(view.joint, view.new_joint, vec3(0.0f, 0.05f, 0.0f));
      if (added >= 0) view.joint = added;
      else view.message = figure.error();
    }
    ImGui::SameLine();
    if (ImGui::Button("Remove joint")) {
      const int parent = s.parents[j];
      if (figure.remove_joint(view.joint)) view.joint = parent;
      else view.message = figure.error();
    }
    if (ImGui::Button("Copy branch")) {
      const int copy = figure.copy_branch(view.joint);
      if (copy >= 0) view.joint = copy;
      else view.message = figure.error();
    }
    ImGui::SameLine();
    if (ImGui::Button("Mirror branch to the other side")) {
      const int n = figure.mirror_branch(view.joint);
      view.message = n >= 0 ? "mirrored " + std::to_string(n) + " joints" : figure.error();
    }
  }
}

}  // namespace gestura::studio_ui
