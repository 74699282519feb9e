#include "environment_panel.hpp"

#include <GLFW/glfw3.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <future>
#include <optional>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/render/look.hpp"
#include "gestura/render/scene_cameras.hpp"
#include "gestura/render/scene_render_job.hpp"
#include "gestura/render/scene_renderer.hpp"
#include "gestura/studio/colour_editor.hpp"
#include "gestura/studio/environment_editor.hpp"
#include "gestura/studio/environment_pick.hpp"
#include "gestura/world/director.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/script.hpp"

namespace gestura::studio_ui {
namespace {

using namespace gestura::studio;

enum class Tool { Move, Rotate, Scale };
const char* const kToolNames[] = {"move", "rotate", "scale"};

// The four ALIAS views: two perspective (orbiting), the plan and the section.
const char* const kViewNames[] = {"perspective", "perspective2", "plan", "section"};
constexpr float kHandlePixels = 70.0f;  // a gizmo handle's length on screen
constexpr float kHandleGrab = 7.0f;     // how near (pixels) the mouse must be to grab it

struct ViewState {
  bool orthographic = false;
  // perspective: an orbit about `target`
  float yaw = 0.0f, pitch = 0.3f, distance = 6.0f, fov = 62.0f;
  vec3 target{0.0f};
  // orthographic: zoom about the framing's centre and a pan in the view plane (metres)
  float zoom = 1.0f;
  vec2 pan{0.0f};
};

struct Handle {
  vec3 axis{0.0f};      // world direction
  vec2 from{0.0f}, to{0.0f};  // on screen, view pixels
  float metres = 1.0f;  // the handle's length in the world
};

struct Drag {
  int view = 0;
  int axis = -1;  // -1: the body (moved in the view's plane, turned about the view's axis)
  vec2 start_pixel{0.0f};
  Ray start_ray;
  EnvTransform start;
  mat4 parent{1.0f}, world{1.0f};
  vec3 origin{0.0f};
  vec3 axis_world{0.0f};
  float handle_metres = 1.0f;
};

// The walk a character was asked for, performed beside the window and played in the views.
struct WalkPreview {
  Scene scene;
  SceneGeometry geometry;
  ScenePerformance performance;
  std::string title;
  std::unique_ptr<SceneAnimator> animator;
  std::unique_ptr<SceneRenderer> renderer;
  std::vector<vec3> path;  // the walker's root on the floor, every 0.1 s
  float time = 0.0f;
  bool playing = true;
};

std::uint32_t im_color(const vec3& c, int alpha = 255) {
  const auto b = [](float x) { return static_cast<int>(std::clamp(x, 0.0f, 1.0f) * 255.0f + 0.5f); };
  return IM_COL32(b(c.x), b(c.y), b(c.z), alpha);
}

Aabb environment_bounds(const SceneGeometry& g, const Scene& scene) {
  Aabb b;
  for (std::size_t o = 0; o < g.object_first.size(); ++o) {
    const mat4& m = g.object_transforms[o];
    for (std::uint32_t i = g.object_first[o]; i < g.object_first[o] + g.object_count[o]; ++i) b.grow(vec3(m * vec4(g.positions[g.indices[i]], 1.0f)));
  }
  for (const auto& [name, p] : scene.places) b.grow(p.position);
  for (const SceneCharacter& c : scene.characters) b.grow(c.position), b.grow(c.position + vec3(0, c.height, 0));
  return b;
}

}  // namespace

struct EnvironmentPanel::Impl {
  Impl(const Avatar& a, float scale) : avatar(a), render_scale(std::clamp(scale, 0.25f, 1.0f)) {
    for (const vec3& p : avatar.mesh.positions) avatar_height = std::max(avatar_height, p.y);
    avatar_height = std::max(avatar_height, 0.5f);
    for (int v = 0; v < 4; ++v) views[static_cast<std::size_t>(v)].orthographic = v >= 2;
    message = "environment editor: open a scene, click in a view to select, drag the handles (W move, E rotate, R scale)";
  }

  const Avatar& avatar;
  float render_scale = 1.0f;
  float avatar_height = 0.0f;
  EnvironmentEditor editor;
  ColourEditor colour;
  std::unique_ptr<SceneRenderer> renderer;
  SceneGeometry geometry;
  std::uint64_t geometry_seen = ~0ull, drawn_revision = ~0ull;
  int uploaded_characters = 0;
  std::vector<std::vector<mat4>> skinning;
  std::vector<float> morphs;
  Aabb frame;  // what the views frame (set on open and by "frame all", not on every edit: the views hold still under a drag)
  bool framed = false;
  std::array<ViewState, 4> views;
  std::array<mat4, 4> drawn_view{}, drawn_projection{};
  int width = 0, height = 0;  // the views' image, pixels
  int drawn_width = 0, drawn_height = 0;
  Tool tool = Tool::Move;
  float snap_metres = 0.0f, snap_degrees = 0.0f;
  std::optional<Drag> drag;
  int orbit_view = -1;
  std::vector<std::string> marked;  // objects ticked for grouping
  std::string message;               // overrides the editor's status until the next action
  std::string path_field, group_field;
  int walk_character = 0, walk_target = 0;
  std::future<std::unique_ptr<WalkPreview>> performing;
  std::unique_ptr<WalkPreview> preview;
  bool colour_active = false;
  std::optional<std::chrono::steady_clock::time_point> last_render;

  // ---- views ----
  Viewport viewport(int v) const {
    const int w2 = width / 2, h2 = height / 2;
    return Viewport{(v % 2) * w2, (v / 2) * h2, v % 2 ? width - w2 : w2, v / 2 ? height - h2 : h2};
  }
  int render_width() const { return std::max(16, static_cast<int>(std::lround(static_cast<float>(width) * render_scale))); }
  int render_height() const { return std::max(16, static_cast<int>(std::lround(static_cast<float>(height) * render_scale))); }
  vec2 view_size(int v) const {
    const Viewport p = viewport(v);
    return vec2(std::max(1, p.width), std::max(1, p.height));
  }
  int view_at(vec2 image_pixel) const {
    const int col = image_pixel.x >= static_cast<float>(width / 2) ? 1 : 0, row = image_pixel.y >= static_cast<float>(height / 2) ? 1 : 0;
    return row * 2 + col;
  }
  vec2 in_view(int v, vec2 image_pixel) const {
    const Viewport p = viewport(v);
    return image_pixel - vec2(p.x, p.y);
  }

  void frame_all() {
    try {
      if (geometry_seen != editor.geometry_revision()) rebuild_geometry();
      frame = environment_bounds(geometry, editor.scene());
    } catch (const Error&) {
      frame = Aabb{};
    }
    if (frame.empty()) frame.grow(vec3(-3, 0, -3)), frame.grow(vec3(3, 2, 3));
    for (int v = 0; v < 2; ++v) {
      // The perspective views start as the scene's built-in ones (high corners looking across it).
      const Camera base = scene_camera(kViewNames[v], editor.scene(), frame, {}, 1.5f);
      ViewState& s = views[static_cast<std::size_t>(v)];
      const vec3 d = base.eye - base.target;
      s.target = base.target, s.distance = glm::length(d);
      s.yaw = std::atan2(d.x, d.z), s.pitch = std::asin(std::clamp(d.y / std::max(1e-4f, s.distance), -1.0f, 1.0f));
    }
    for (int v = 2; v < 4; ++v) views[static_cast<std::size_t>(v)].zoom = 1.0f, views[static_cast<std::size_t>(v)].pan = vec2(0.0f);
    framed = true;
  }

  Camera camera(int v) const {
    const vec2 size = view_size(v);
    const float aspect = size.x / size.y;
    const ViewState& s = views[static_cast<std::size_t>(v)];
    if (!s.orthographic) {
      Camera c;
      c.target = s.target;
      c.eye = s.target + s.distance * vec3(std::cos(s.pitch) * std::sin(s.yaw), std::sin(s.pitch), std::cos(s.pitch) * std::cos(s.yaw));
      c.view = glm::lookAt(c.eye, c.target, vec3(0, 1, 0));
      c.projection = glm::perspective(deg(s.fov), aspect, 0.05f, std::max(50.0f, s.distance * 6.0f));
      return c;
    }
    Camera c = scene_camera(kViewNames[v], editor.scene(), frame, {}, aspect);
    c.projection = glm::scale(mat4(1.0f), vec3(s.zoom, s.zoom, 1.0f)) * c.projection;
    c.view = glm::translate(mat4(1.0f), vec3(-s.pan, 0.0f)) * c.view;
    return c;
  }

  // ---- drawing ----
  void rebuild_geometry() {
    geometry_seen = editor.geometry_revision();
    geometry = build_scene_geometry(editor.scene());
    if (renderer) {
      renderer->set_environment(geometry);
      renderer->set_lights(editor.scene().lights, editor.scene().background);
    }
  }

  vec3 character_position(const SceneCharacter& c) const {
    const auto it = editor.scene().places.find(c.place);
    return c.place.empty() || it == editor.scene().places.end() ? c.position : it->second.position;
  }

  void render(float dt) {
    if (width < 16 || height < 16) return;
    if (!framed) frame_all();
    if (!renderer) {
      renderer = std::make_unique<SceneRenderer>();
      geometry_seen = ~0ull;
    }
    if (performing.valid() && performing.wait_for(std::chrono::seconds(0)) == std::future_status::ready) finish_walk();
    // The views render at render_scale of the pixels they are shown at (the cameras are the same).
    const int rw = render_width(), rh = render_height();
    std::vector<View> list;
    for (int v = 0; v < 4; ++v) {
      const Viewport p = viewport(v);
      const auto at = [&](int x) { return static_cast<int>(std::lround(static_cast<float>(x) * render_scale)); };
      list.push_back(View{camera(v), Viewport{at(p.x), at(p.y), at(p.x + p.width) - at(p.x), at(p.y + p.height) - at(p.y)}});
    }
    if (preview) {
      if (preview->renderer->width() != rw || preview->renderer->height() != rh) preview->renderer->resize(rw, rh);
      const float duration = preview->performance.duration;
      if (preview->playing) preview->time += dt;
      if (preview->time > duration) preview->time = duration > 0.0f ? std::fmod(preview->time, duration) : 0.0f;
      preview->animator->pose_at(preview->time);
      preview->renderer->render(list, preview->animator->objects(), preview->animator->frames());
      drawn_revision = ~0ull;
      return;
    }
    try {
      if (geometry_seen != editor.geometry_revision()) rebuild_geometry();
    } catch (const Error& e) {
      message = std::string("cannot draw the scene: ") + e.what();
    }
    if (renderer->width() != rw || renderer->height() != rh) renderer->resize(rw, rh);
    bool same = drawn_revision == editor.revision() && drawn_width == width && drawn_height == height;
    for (int v = 0; v < 4 && same; ++v)
      same = drawn_view[static_cast<std::size_t>(v)] == list[static_cast<std::size_t>(v)].camera.view &&
             drawn_projection[static_cast<std::size_t>(v)] == list[static_cast<std::size_t>(v)].camera.projection;
    if (same) return;
    const Scene& scene = editor.scene();
    std::vector<mat4> objects;
    for (const SceneObject& o : scene.objects) objects.push_back(object_matrix(o, o.door ? o.door->angle : 0.0f));
    if (objects.size() != geometry.object_names.size()) objects.clear();  // geometry not rebuilt (an error): as uploaded
    // Characters stand in the avatar's rest pose at their place, scaled to their height.
    while (uploaded_characters < static_cast<int>(scene.characters.size())) {
      renderer->add_character(avatar.mesh, look_for(Look{}, avatar.mesh));
      ++uploaded_characters;
    }
    skinning.resize(static_cast<std::size_t>(uploaded_characters));
    morphs.assign(avatar.mesh.morphs.size(), 0.0f);
    std::vector<CharacterFrame> frames;
    for (int i = 0; i < uploaded_characters; ++i) {
      std::vector<mat4>& k = skinning[static_cast<std::size_t>(i)];
      if (i < static_cast<int>(scene.characters.size())) {
        const SceneCharacter& c = scene.characters[static_cast<std::size_t>(i)];
        const mat4 m = glm::translate(mat4(1.0f), character_position(c)) * glm::rotate(mat4(1.0f), deg(c.facing), vec3(0, 1, 0)) *
                       glm::scale(mat4(1.0f), vec3(c.height / avatar_height));
        k.assign(avatar.skeleton.size(), m);
        frames.push_back(CharacterFrame{k, morphs, true});
      } else {
        k.assign(avatar.skeleton.size(), mat4(1.0f));
        frames.push_back(CharacterFrame{k, morphs, false});
      }
    }
    renderer->render(list, objects, frames);
    drawn_revision = editor.revision(), drawn_width = width, drawn_height = height;
    for (int v = 0; v < 4; ++v)
      drawn_view[static_cast<std::size_t>(v)] = list[static_cast<std::size_t>(v)].camera.view,
      drawn_projection[static_cast<std::size_t>(v)] = list[static_cast<std::size_t>(v)].camera.projection;
  }

  // ---- the gizmo ----
  // The handles of the selected item in view v (none for an axis pointing at the viewer).
  std::vector<Handle> handles(int v) const {
    std::vector<Handle> out;
    const auto world = editor.world_matrix();
    if (!world || preview) return out;
    const vec3 origin = vec3((*world)[3]);
    const Camera c = camera(v);
    const vec2 size = view_size(v);
    const auto o = project_to_pixel(c, origin, size);
    if (!o) return out;
    const bool object = editor.selection().kind == EnvItem::Object;
    if (!object && tool == Tool::Scale) return out;
    for (int a = 0; a < 3; ++a) {
      if (!object && tool == Tool::Rotate && a != 1) continue;  // places and characters only turn about +Y
      vec3 e(0.0f);
      e[a] = 1.0f;
      const mat4& frame_of = tool == Tool::Scale ? *world : editor.parent_matrix();
      const vec3 axis = glm::normalize(vec3(frame_of * vec4(e, 0.0f)));
      const auto p1 = project_to_pixel(c, origin + axis, size);
      if (!p1) continue;
      const float len = glm::length(*p1 - *o);
      if (len < 4.0f) continue;
      out.push_back(Handle{axis, *o, *o + (*p1 - *o) / len * kHandlePixels, kHandlePixels / len});
    }
    return out;
  }

  // `whole`: a click on a part of a group selects the group (Shift+click).
  void press(int v, vec2 p, int force_axis = -1, bool whole = false) {
    if (preview) return;
    const Ray ray = pixel_ray(camera(v), p, view_size(v));
    message.clear();
    int axis = force_axis;
    std::vector<Handle> hs = handles(v);
    if (axis < 0)
      for (std::size_t i = 0; i < hs.size(); ++i) {
        const vec2 d = glm::normalize(hs[i].to - hs[i].from);
        if (distance_to_segment(p, hs[i].from + d * 12.0f, hs[i].to) < kHandleGrab) axis = static_cast<int>(i);
      }
    if (axis < 0) {
      EnvSelection picked = editor.pick(ray, &geometry);
      if (whole && picked.kind == EnvItem::Object) picked.path.resize(1);
      editor.select(picked);
      colour.follow(editor);
      if (editor.selection().empty()) return;
      hs = handles(v);
    }
    if (force_axis >= 0) {
      // A script names the axis: x, y or z of the tool's frame.
      const auto it = std::find_if(hs.begin(), hs.end(), [&](const Handle& h) {
        vec3 e(0.0f);
        e[force_axis] = 1.0f;
        const mat4 f = tool == Tool::Scale ? *editor.world_matrix() : editor.parent_matrix();
        return glm::dot(h.axis, glm::normalize(vec3(f * vec4(e, 0.0f)))) > 0.999f;
      });
      if (it == hs.end()) throw Error(std::string("the ") + "xyz"[force_axis] + " handle is not shown in the " + kViewNames[v] + " view");
      axis = static_cast<int>(it - hs.begin());
    }
    Drag d;
    d.view = v, d.start_pixel = p, d.start_ray = ray;
    d.start = *editor.transform(), d.parent = editor.parent_matrix(), d.world = *editor.world_matrix();
    d.origin = vec3(d.world[3]);
    if (axis >= 0) d.axis = axis, d.axis_world = hs[static_cast<std::size_t>(axis)].axis, d.handle_metres = hs[static_cast<std::size_t>(axis)].metres;
    editor.begin_edit(std::string(kToolNames[static_cast<int>(tool)]) + " " + editor.selection_name());
    drag = d;
  }

  void move_to(vec2 p) {
    if (!drag) return;
    const Drag& d = *drag;
    const Ray ray = pixel_ray(camera(d.view), p, view_size(d.view));
    EnvTransform t = d.start;
    const mat3 to_parent = glm::inverse(mat3(d.parent));
    // The view's own axis: turning and moving the body happen in the plane the view looks at.
    const vec3 view_axis = kViewNames[d.view] == std::string("section") ? vec3(0, 0, 1) : vec3(0, 1, 0);
    if (tool == Tool::Move) {
      vec3 delta(0.0f);
      if (d.axis >= 0) {
        const auto along = drag_along_axis(d.start_ray, ray, d.origin, d.axis_world);
        if (!along) return;
        delta = d.axis_world * snap(*along, snap_metres);
      } else {
        const auto moved = drag_in_plane(d.start_ray, ray, d.origin, view_axis);
        if (!moved) return;
        delta = vec3(snap(moved->x, snap_metres), snap(moved->y, snap_metres), snap(moved->z, snap_metres));
      }
      t.position = d.start.position + to_parent * delta;
    } else if (tool == Tool::Rotate) {
      const vec3 axis = d.axis >= 0 ? d.axis_world : view_axis;
      float angle = 0.0f;
      if (const auto a = drag_angle(d.start_ray, ray, d.origin, axis)) angle = *a;
      else angle = (p.x - d.start_pixel.x) * 0.01f;  // the plane seen edge-on: sideways turns
      angle = deg(snap(to_degrees(angle), snap_degrees));
      if (editor.selection().kind == EnvItem::Object) t.rotation = rotate_euler(d.start.rotation, glm::normalize(to_parent * axis), angle);
      else t.rotation.y = d.start.rotation.y + to_degrees(angle) * (axis.y >= 0.0f ? 1.0f : -1.0f);
    } else if (editor.selection().kind == EnvItem::Object) {
      if (d.axis >= 0) {
        const auto along = drag_along_axis(d.start_ray, ray, d.origin, d.axis_world);
        if (!along) return;
        const float factor = std::max(0.01f, 1.0f + *along / d.handle_metres);
        t.scale[d.axis] = std::max(0.001f, snap(d.start.scale[d.axis] * factor, snap_metres));
      } else {
        t.scale = d.start.scale * std::exp(-(p.y - d.start_pixel.y) / 150.0f);  // drag up to grow
      }
    }
    editor.set_transform(t);
  }

  void release() {
    if (!drag) return;
    drag.reset();
    editor.end_edit();
  }

  // ---- the walk preview ----
  void start_walk(const std::string& who, const std::string& target) {
    if (performing.valid()) throw Error("a walk is being performed already");
    const std::string text = who + " walks to " + target;
    Scene scene = editor.scene();
    Script script = gestura::parse_script(text, "preview");
    check_script(script, scene);  // unknown names: said now, not after seconds
    preview.reset();
    message = "performing: " + text + " ...";
    performing = std::async(std::launch::async, [scene = std::move(scene), script = std::move(script), text]() mutable {
      auto p = std::make_unique<WalkPreview>();
      p->scene = std::move(scene);
      p->geometry = build_scene_geometry(p->scene);
      p->performance = perform_scene(p->scene, p->geometry, script);
      p->title = text;
      return p;
    });
  }

  void finish_walk() {
    try {
      std::unique_ptr<WalkPreview> p = performing.get();
      p->animator = std::make_unique<SceneAnimator>(p->scene, p->geometry, p->performance);
      p->renderer = std::make_unique<SceneRenderer>();
      p->renderer->resize(render_width(), render_height());
      p->animator->upload(*p->renderer);
      std::string warnings;
      for (const LogEntry& e : p->performance.log)
        if (e.warning) warnings += (warnings.empty() ? "" : "; ") + e.text;
      message = warnings.empty() ? p->title + " (" + std::to_string(p->performance.duration).substr(0, 4) + " s)" : warnings;
      preview = std::move(p);
      // The walker's path: the first character is who walks (SceneAnimator keeps the scene's order).
      const std::string walker = preview->title.substr(0, preview->title.find(' '));
      preview->path.clear();
      for (std::size_t i = 0; i < preview->performance.characters.size(); ++i)
        if (preview->performance.characters[i].name == walker)
          for (float t = 0.0f; t <= preview->performance.duration + 1e-3f; t += 0.1f) {
            preview->animator->pose_at(t);
            preview->path.push_back(preview->animator->views()[i].position);
          }
    } catch (const Error& e) {
      message = std::string("the walk cannot be shown: ") + e.what();
    } catch (const std::exception& e) {
      message = std::string("the walk cannot be shown: ") + e.what();
    }
  }

  void stop_walk() {
    preview.reset();
    drawn_revision = ~0ull;
  }

  // ---- the panels ----
  void draw_scene_list(const ImVec2& pos, const ImVec2& size);
  void draw_views(const ImVec2& pos, const ImVec2& size);
  void draw_properties(const ImVec2& pos, const ImVec2& size);
  void draw_colour(const ImVec2& pos, const ImVec2& size);
  void draw_object_node(const SceneObject& o, std::vector<int>& path);
  void open(const std::string& path);
  void save(const std::string& path);
  const std::string& status() const { return message.empty() ? editor.status() : message; }
};

namespace {

bool begin_window(const char* name, const ImVec2& pos, const ImVec2& size) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  return ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

}  // namespace

void EnvironmentPanel::Impl::open(const std::string& path) {
  try {
    if (drag) release();
    editor.open(path);
    message.clear();
    path_field = path;
    stop_walk();
    frame_all();  // the views frame the new scene (now: a script's next step may click in them)
    colour.follow(editor);
  } catch (const Error& e) {
    // Nothing changed: the scene being edited, its file and its history are as they were.
    message = std::string("not opened: ") + e.what();
  }
}

void EnvironmentPanel::Impl::save(const std::string& path) {
  try {
    editor.save(path);
    message.clear();
    path_field = editor.file();
  } catch (const Error& e) {
    message = std::string("not saved: ") + e.what();
  }
}

void EnvironmentPanel::Impl::draw_object_node(const SceneObject& o, std::vector<int>& path) {
  const EnvSelection here{EnvItem::Object, path, {}};
  const bool selected = editor.selection() == here;
  std::string label = o.name.empty() ? (o.shape.kind != ShapeKind::None ? shape_name(o.shape.kind) : "group") : o.name;
  if (o.name.empty() || path.size() > 1) label = std::to_string(path.back()) + ": " + label;
  if (!o.instance.empty()) label += " (" + o.instance + ")";
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (selected) flags |= ImGuiTreeNodeFlags_Selected;
  if (o.parts.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  if (path.size() == 1 && std::find(marked.begin(), marked.end(), o.name) != marked.end()) label = "[x] " + label;
  ImGui::PushID(static_cast<int>(path.back()));
  const bool open = ImGui::TreeNodeEx("node", flags, "%s", label.c_str());
  if (ImGui::IsItemClicked()) {
    if (ImGui::GetIO().KeyCtrl && path.size() == 1 && !o.name.empty()) {
      // Ctrl+click ticks top-level objects for "Group".
      const auto it = std::find(marked.begin(), marked.end(), o.name);
      if (it == marked.end()) marked.push_back(o.name);
      else marked.erase(it);
    } else {
      editor.select(here);
      colour.follow(editor);
    }
  }
  if (open && !o.parts.empty()) {
    for (std::size_t i = 0; i < o.parts.size(); ++i) {
      path.push_back(static_cast<int>(i));
      draw_object_node(o.parts[i], path);
      path.pop_back();
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
}

void EnvironmentPanel::Impl::draw_scene_list(const ImVec2& pos, const ImVec2& size) {
  if (begin_window("Scene", pos, size)) {
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##path", "scene.json", &path_field);
    if (ImGui::Button("Open")) open(path_field);
    ImGui::SameLine();
    if (ImGui::Button("Save")) save(path_field == editor.file() ? "" : path_field);
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s", editor.file().empty() ? "(new scene)" : "", editor.dirty() ? " unsaved" : " saved");
    ImGui::Separator();
    ImGui::TextUnformatted("Add at the plan's centre:");
    const vec3 at(frame.empty() ? 0.0f : frame.centre().x, 0.0f, frame.empty() ? 0.0f : frame.centre().z);
    for (auto [label, kind] : {std::pair{"Box", ShapeKind::Box}, std::pair{"Plane", ShapeKind::Plane}, std::pair{"Cylinder", ShapeKind::Cylinder},
                               std::pair{"Sphere", ShapeKind::Sphere}}) {
      if (ImGui::SmallButton(label)) message.clear(), editor.add_primitive(kind, at);
      ImGui::SameLine();
    }
    ImGui::NewLine();
    if (ImGui::SmallButton("Place")) message.clear(), editor.add_place("", at);
    ImGui::SameLine();
    if (ImGui::SmallButton("Character")) message.clear(), editor.add_character("", at);
    ImGui::SameLine();
    if (ImGui::SmallButton("Duplicate")) message.clear(), editor.duplicate_selected();
    ImGui::SameLine();
    if (ImGui::SmallButton("Delete")) message.clear(), editor.remove_selected();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::InputTextWithHint("##group", "group name", &group_field);
    ImGui::SameLine();
    ImGui::BeginDisabled(marked.empty());
    if (ImGui::SmallButton("Group ticked")) {
      message.clear();
      editor.group(marked, group_field);
      marked.clear();
    }
    ImGui::EndDisabled();
    ImGui::TextDisabled("Ctrl+click objects to tick them");
    ImGui::Separator();
    ImGui::BeginChild("tree", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 4.5f));
    const Scene& scene = editor.scene();
    if (ImGui::TreeNodeEx("Objects", ImGuiTreeNodeFlags_DefaultOpen)) {
      std::vector<int> path;
      for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        path = {static_cast<int>(i)};
        draw_object_node(scene.objects[i], path);
      }
      ImGui::TreePop();
    }
    if (ImGui::TreeNodeEx("Places", ImGuiTreeNodeFlags_DefaultOpen)) {
      for (const auto& [name, place] : scene.places) {
        const EnvSelection here{EnvItem::Place, {}, name};
        if (ImGui::Selectable(name.c_str(), editor.selection() == here)) editor.select(here), colour.follow(editor);
      }
      ImGui::TreePop();
    }
    if (ImGui::TreeNodeEx("Characters", ImGuiTreeNodeFlags_DefaultOpen)) {
      for (std::size_t i = 0; i < scene.characters.size(); ++i) {
        const EnvSelection here{EnvItem::Character, {static_cast<int>(i)}, {}};
        if (ImGui::Selectable(scene.characters[i].name.c_str(), editor.selection() == here)) editor.select(here), colour.follow(editor);
      }
      ImGui::TreePop();
    }
    ImGui::EndChild();
    // Walk a character to a place or an object: performed (path planning, the walking skill) and played.
    ImGui::Separator();
    std::vector<std::string> targets;
    for (const auto& [name, place] : scene.places) targets.push_back(name);
    for (const SceneObject& o : scene.objects)
      if (!o.name.empty()) targets.push_back(o.name);
    if (!scene.characters.empty() && !targets.empty()) {
      walk_character = std::clamp(walk_character, 0, static_cast<int>(scene.characters.size()) - 1);
      walk_target = std::clamp(walk_target, 0, static_cast<int>(targets.size()) - 1);
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
      if (ImGui::BeginCombo("##who", scene.characters[static_cast<std::size_t>(walk_character)].name.c_str())) {
        for (std::size_t i = 0; i < scene.characters.size(); ++i)
          if (ImGui::Selectable(scene.characters[i].name.c_str(), static_cast<int>(i) == walk_character)) walk_character = static_cast<int>(i);
        ImGui::EndCombo();
      }
      ImGui::SameLine();
      ImGui::TextUnformatted("to");
      ImGui::SameLine();
      ImGui::SetNextItemWidth(-1);
      if (ImGui::BeginCombo("##where", targets[static_cast<std::size_t>(walk_target)].c_str())) {
        for (std::size_t i = 0; i < targets.size(); ++i)
          if (ImGui::Selectable(targets[i].c_str(), static_cast<int>(i) == walk_target)) walk_target = static_cast<int>(i);
        ImGui::EndCombo();
      }
      ImGui::BeginDisabled(performing.valid());
      if (ImGui::Button("Walk")) {
        try {
          start_walk(scene.characters[static_cast<std::size_t>(walk_character)].name, targets[static_cast<std::size_t>(walk_target)]);
        } catch (const Error& e) {
          message = e.what();
        }
      }
      ImGui::EndDisabled();
      if (preview) {
        ImGui::SameLine();
        if (ImGui::Button(preview->playing ? "Pause" : "Play")) preview->playing = !preview->playing;
        ImGui::SameLine();
        if (ImGui::Button("Back to editing")) stop_walk();
      }
    } else {
      ImGui::TextDisabled("add a character and a place to walk");
    }
  }
  ImGui::End();
}

void EnvironmentPanel::Impl::draw_views(const ImVec2& pos, const ImVec2& size) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
  if (begin_window("Views", pos, size)) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    width = std::max(16, static_cast<int>(avail.x)), height = std::max(16, static_cast<int>(avail.y));
    SceneRenderer* shown = preview ? preview->renderer.get() : renderer.get();
    const ImVec2 image_size(static_cast<float>(width), static_cast<float>(height));
    if (shown && shown->width() == render_width() && shown->height() == render_height())
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(shown->resolved_texture())), image_size, ImVec2(0, 1), ImVec2(1, 0));
    else
      ImGui::Dummy(image_size);
    const ImVec2 origin = ImGui::GetItemRectMin();
    const bool hovered = ImGui::IsItemHovered();
    const ImGuiIO& io = ImGui::GetIO();
    const vec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
    const int under = view_at(mouse);
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) press(under, in_view(under, mouse), -1, io.KeyShift);
    if (drag && ImGui::IsMouseDown(ImGuiMouseButton_Left) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) move_to(in_view(drag->view, mouse));
    if (drag && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) release();
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) orbit_view = under;
    if (orbit_view >= 0 && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
      ViewState& s = views[static_cast<std::size_t>(orbit_view)];
      if (!s.orthographic) {
        s.yaw -= io.MouseDelta.x * 0.01f;
        s.pitch = std::clamp(s.pitch + io.MouseDelta.y * 0.01f, deg(-85.0f), deg(85.0f));
      } else {
        const Camera c = camera(orbit_view);
        const float metres_per_pixel = 2.0f / (c.projection[1][1] * view_size(orbit_view).y);
        s.pan += vec2(-io.MouseDelta.x, io.MouseDelta.y) * metres_per_pixel;
      }
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) orbit_view = -1;
    if (hovered && io.MouseWheel != 0.0f) {
      ViewState& s = views[static_cast<std::size_t>(under)];
      const float f = std::pow(1.15f, io.MouseWheel);
      if (s.orthographic) s.zoom = std::clamp(s.zoom * f, 0.05f, 50.0f);
      else s.distance = std::clamp(s.distance / f, 0.3f, 500.0f);
    }

    // Overlays: the view's name, places, characters' names, the walk's path and the gizmo.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + image_size.x, origin.y + image_size.y), true);
    for (int v = 0; v < 4; ++v) {
      const Viewport vp = viewport(v);
      const ImVec2 o(origin.x + static_cast<float>(vp.x), origin.y + static_cast<float>(vp.y));
      const auto at = [&](vec2 p) { return ImVec2(o.x + p.x, o.y + p.y); };
      dl->PushClipRect(o, ImVec2(o.x + static_cast<float>(vp.width), o.y + static_cast<float>(vp.height)), true);
      const Camera c = camera(v);
      const vec2 vs = view_size(v);
      for (const auto& [name, place] : editor.scene().places) {
        const bool sel = editor.selection().kind == EnvItem::Place && editor.selection().place == name;
        if (const auto p = project_to_pixel(c, place.position, vs)) {
          dl->AddCircle(at(*p), 6.0f, sel ? IM_COL32(255, 220, 60, 255) : IM_COL32(250, 250, 250, 220), 16, 2.0f);
          dl->AddText(at(*p + vec2(8, -7)), IM_COL32(250, 250, 250, 230), name.c_str());
        }
      }
      if (!preview)
        for (std::size_t i = 0; i < editor.scene().characters.size(); ++i) {
          const SceneCharacter& ch = editor.scene().characters[i];
          if (const auto p = project_to_pixel(c, character_position(ch) + vec3(0, ch.height + 0.1f, 0), vs))
            dl->AddText(at(*p + vec2(-12, -14)), IM_COL32(255, 255, 255, 240), ch.name.c_str());
        }
      if (preview && preview->path.size() > 1) {
        for (std::size_t i = 1; i < preview->path.size(); ++i) {
          const auto a = project_to_pixel(c, preview->path[i - 1] + vec3(0, 0.02f, 0), vs), b = project_to_pixel(c, preview->path[i] + vec3(0, 0.02f, 0), vs);
          if (a && b) dl->AddLine(at(*a), at(*b), IM_COL32(255, 200, 40, 230), 2.5f);
        }
      }
      if (const auto world = editor.world_matrix(); world && !preview) {
        if (const auto p = project_to_pixel(c, vec3((*world)[3]), vs)) dl->AddCircleFilled(at(*p), 4.0f, IM_COL32(255, 220, 60, 255));
        const vec3 colours[] = {vec3(0.95f, 0.3f, 0.3f), vec3(0.3f, 0.9f, 0.35f), vec3(0.35f, 0.55f, 1.0f)};
        for (const Handle& h : handles(v)) {
          int a = 0;
          for (int k = 1; k < 3; ++k)
            if (std::abs(h.axis[k]) > std::abs(h.axis[a])) a = k;
          const std::uint32_t col = im_color(colours[a]);
          dl->AddLine(at(h.from), at(h.to), col, 3.0f);
          if (tool == Tool::Move) dl->AddTriangleFilled(at(h.to + glm::normalize(h.to - h.from) * 10.0f),
                                                       at(h.to + vec2(-(h.to - h.from).y, (h.to - h.from).x) / kHandlePixels * 5.0f),
                                                       at(h.to - vec2(-(h.to - h.from).y, (h.to - h.from).x) / kHandlePixels * 5.0f), col);
          else if (tool == Tool::Rotate) dl->AddCircle(at(h.to), 6.0f, col, 16, 2.5f);
          else dl->AddRectFilled(at(h.to - vec2(5)), at(h.to + vec2(5)), col);
        }
      }
      dl->AddRectFilled(ImVec2(o.x + 4, o.y + 4), ImVec2(o.x + 12 + ImGui::CalcTextSize(kViewNames[v]).x, o.y + 22), IM_COL32(0, 0, 0, 140));
      dl->AddText(ImVec2(o.x + 8, o.y + 5), IM_COL32(255, 255, 255, 255), kViewNames[v]);
      dl->PopClipRect();
      dl->AddRect(o, ImVec2(o.x + static_cast<float>(vp.width), o.y + static_cast<float>(vp.height)), IM_COL32(20, 20, 24, 255));
    }
    if (preview) {
      const std::string line = preview->title + "  " + std::to_string(preview->time).substr(0, 4) + " s";
      dl->AddText(ImVec2(origin.x + 8, origin.y + image_size.y - 22), IM_COL32(255, 220, 60, 255), line.c_str());
    }
    dl->PopClipRect();
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void EnvironmentPanel::Impl::draw_properties(const ImVec2& pos, const ImVec2& size) {
  if (begin_window("Properties", pos, size)) {
    for (int t = 0; t < 3; ++t) {
      if (ImGui::RadioButton(kToolNames[t], static_cast<int>(tool) == t)) tool = static_cast<Tool>(t);
      ImGui::SameLine();
    }
    ImGui::TextDisabled("(W E R)");
    ImGui::SetNextItemWidth(80);
    ImGui::InputFloat("snap m", &snap_metres, 0.0f, 0.0f, "%.2f");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60);
    ImGui::InputFloat("snap deg", &snap_degrees, 0.0f, 0.0f, "%.0f");
    snap_metres = std::clamp(snap_metres, 0.0f, 10.0f), snap_degrees = std::clamp(snap_degrees, 0.0f, 90.0f);
    if (ImGui::SmallButton("Frame all (F)")) frame_all();
    ImGui::Separator();
    const std::string name = editor.selection_name();
    ImGui::Text("Selected: %s", name.empty() ? "(nothing: click in a view)" : name.c_str());
    if (auto t = editor.transform()) {
      const bool object = editor.selection().kind == EnvItem::Object;
      bool changed = false, activated = false, deactivated = false;
      const auto field = [&](const char* label, float* v, int n) {
        ImGui::SetNextItemWidth(-60);
        changed |= n == 3 ? ImGui::DragFloat3(label, v, 0.01f, 0.0f, 0.0f, "%.3f") : ImGui::DragFloat(label, v, 0.5f, 0.0f, 0.0f, "%.1f");
        activated |= ImGui::IsItemActivated();
        deactivated |= ImGui::IsItemDeactivated();
      };
      field("position", &t->position.x, 3);
      if (object) field("rotation", &t->rotation.x, 3), field("scale", &t->scale.x, 3);
      else field("facing", &t->rotation.y, 1);
      if (activated && !drag) editor.begin_edit("edit " + name);
      if (changed) editor.set_transform(*t);
      if (deactivated && !drag) editor.end_edit();
      if (object) {
        const SceneObject* o = nullptr;
        const std::vector<int>& path = editor.selection().path;
        o = &editor.scene().objects[static_cast<std::size_t>(path[0])];
        for (std::size_t i = 1; i < path.size(); ++i) o = &o->parts[static_cast<std::size_t>(path[i])];
        ImGui::TextDisabled("%s%s  material: %s", o->shape.kind != ShapeKind::None ? shape_name(o->shape.kind) : (o->instance.empty() ? "group" : "instance"),
                            o->parts.empty() ? "" : (" of " + std::to_string(o->parts.size()) + " parts").c_str(), o->material.empty() ? "(inherited)" : o->material.c_str());
      }
    }
  }
  ImGui::End();
}

void EnvironmentPanel::Impl::draw_colour(const ImVec2& pos, const ImVec2& size) {
  if (begin_window("Colour", pos, size)) {
    colour.follow(editor);
    const bool can = editor.selection().kind == EnvItem::Object;
    const vec3 c = colour.palette().color();
    ImGui::ColorButton("##current", ImVec4(c.x, c.y, c.z, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(48, 48));
    ImGui::SameLine();
    ImGui::BeginGroup();
    float rgb[3] = {c.x, c.y, c.z};
    bool changed = false, activated = false, deactivated = false;
    ImGui::SetNextItemWidth(-30);
    changed |= ImGui::ColorEdit3("RGB", rgb, ImGuiColorEditFlags_DisplayRGB | ImGuiColorEditFlags_NoPicker | ImGuiColorEditFlags_Float);
    activated |= ImGui::IsItemActivated(), deactivated |= ImGui::IsItemDeactivated();
    ImGui::SetNextItemWidth(-30);
    changed |= ImGui::ColorEdit3("HSV", rgb, ImGuiColorEditFlags_DisplayHSV | ImGuiColorEditFlags_NoPicker | ImGuiColorEditFlags_Float);
    activated |= ImGui::IsItemActivated(), deactivated |= ImGui::IsItemDeactivated();
    ImGui::Text("%s", color_hex(c).c_str());
    ImGui::EndGroup();
    if (can && activated && !colour_active) editor.begin_edit("colour " + editor.selection_name()), colour_active = true;
    if (changed) {
      if (can) colour.choose(editor, vec3(rgb[0], rgb[1], rgb[2]));
      else message = "select an object to colour";
    }
    if (colour_active && deactivated) editor.end_edit(), colour_active = false;
    // The six ramps of nearby colours: click toward the colour in mind.
    const char* const ramp_names[] = {"+red", "+green", "+blue", "-red", "-green", "-blue"};
    for (std::size_t r = 0; r < 6; ++r) {
      ImGui::TextUnformatted(ramp_names[r]);
      ImGui::SameLine(60);
      const auto& ramp = colour.palette().ramps()[r].colors;
      for (std::size_t i = 0; i < ramp.size(); ++i) {
        ImGui::PushID(static_cast<int>(r * 100 + i));
        if (ImGui::ColorButton("##ramp", ImVec4(ramp[i].x, ramp[i].y, ramp[i].z, 1.0f), 0, ImVec2(20, 20)) && can) colour.choose_ramp(editor, r, i);
        ImGui::PopID();
        ImGui::SameLine();
      }
      ImGui::NewLine();
    }
    ImGui::TextUnformatted("kept");
    ImGui::SameLine(60);
    for (std::size_t s = 0; s < ColorPalette::kSlots; ++s) {
      ImGui::PushID(static_cast<int>(1000 + s));
      const auto& slot = colour.palette().slots()[s];
      const vec3 k = slot.value_or(vec3(0.15f));
      if (ImGui::ColorButton("##slot", ImVec4(k.x, k.y, k.z, 1.0f), slot ? 0 : ImGuiColorEditFlags_NoTooltip, ImVec2(20, 20))) {
        if (slot && can) colour.choose_slot(editor, s);
        else if (!slot) colour.store(s);
      }
      if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) colour.store(s);
      ImGui::PopID();
      ImGui::SameLine();
    }
    ImGui::NewLine();
    ImGui::TextDisabled("click an empty slot (or right-click any) to keep the colour");
    if (!can) ImGui::TextDisabled("select an object to colour it");
  }
  ImGui::End();
}

// ---------------------------------------------------------------------------------------------

EnvironmentPanel::EnvironmentPanel(const Avatar& avatar, float render_scale) : impl_(std::make_unique<Impl>(avatar, render_scale)) {}
EnvironmentPanel::~EnvironmentPanel() {
  if (impl_->performing.valid()) impl_->performing.wait();
}

void EnvironmentPanel::render() {
  // The walk preview plays in real time.
  const auto now = std::chrono::steady_clock::now();
  const float dt = impl_->last_render ? std::min(0.1f, std::chrono::duration<float>(now - *impl_->last_render).count()) : 0.0f;
  impl_->last_render = now;
  impl_->render(dt);
}

void EnvironmentPanel::draw(const ImVec2& pos, const ImVec2& size) {
  Impl& m = *impl_;
  const float left = std::round(size.x * 0.2f), right = std::round(size.x * 0.26f), centre = size.x - left - right;
  const float props = std::round(size.y * 0.34f);
  m.draw_scene_list(pos, ImVec2(left, size.y));
  m.draw_views(ImVec2(pos.x + left, pos.y), ImVec2(centre, size.y));
  m.draw_properties(ImVec2(pos.x + left + centre, pos.y), ImVec2(right, props));
  m.draw_colour(ImVec2(pos.x + left + centre, pos.y + props), ImVec2(right, size.y - props));
}

void EnvironmentPanel::shortcuts() {
  Impl& m = *impl_;
  const ImGuiIO& io = ImGui::GetIO();
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) m.message.clear(), m.editor.undo();
    if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) m.message.clear(), m.editor.redo();
    if (pressed(GLFW_KEY_S)) m.save("");
    if (pressed(GLFW_KEY_D)) m.message.clear(), m.editor.duplicate_selected();
    return;
  }
  if (io.WantTextInput) return;
  if (pressed(GLFW_KEY_W)) m.tool = Tool::Move;
  if (pressed(GLFW_KEY_E)) m.tool = Tool::Rotate;
  if (pressed(GLFW_KEY_R)) m.tool = Tool::Scale;
  if (pressed(GLFW_KEY_F)) m.frame_all();
  if (pressed(GLFW_KEY_DELETE)) m.message.clear(), m.editor.remove_selected();
}

bool EnvironmentPanel::busy() const { return impl_->performing.valid(); }
void EnvironmentPanel::undo() { impl_->message.clear(), impl_->editor.undo(); }
void EnvironmentPanel::redo() { impl_->message.clear(), impl_->editor.redo(); }
std::string EnvironmentPanel::undo_label() const { return impl_->editor.undo_label(); }
std::string EnvironmentPanel::redo_label() const { return impl_->editor.redo_label(); }
const std::string& EnvironmentPanel::status() const { return impl_->status(); }

bool EnvironmentPanel::execute(const studio::ScriptStep& step) {
  Impl& m = *impl_;
  const std::string& a = step.action;
  const auto arg = [&](std::size_t i) { return i < step.args.size() ? step.args[i] : std::string(); };
  const auto number = [&](std::size_t i) {
    try {
      std::size_t used = 0;
      const float v = std::stof(arg(i), &used);
      if (used != arg(i).size() || !std::isfinite(v)) throw std::invalid_argument("");
      return v;
    } catch (const std::exception&) {
      throw Error("'" + arg(i) + "' is not a number");
    }
  };
  const auto view_named = [&](const std::string& name) {
    for (int v = 0; v < 4; ++v)
      if (name == kViewNames[v]) return v;
    throw Error("no view '" + name + "' (perspective, perspective2, plan, section)");
  };
  const auto axis_named = [&](const std::string& name) {
    if (name.empty()) return -1;
    if (name == "x" || name == "y" || name == "z") return name[0] - 'x';
    throw Error("no axis '" + name + "' (x, y, z)");
  };
  if (a == "undo") {
    m.message.clear(), m.editor.undo();
  } else if (a == "redo") {
    m.message.clear(), m.editor.redo();
  } else if (a.rfind("env-", 0) != 0) {
    return false;
  } else if (a == "env-open") {
    m.open(arg(0));
  } else if (a == "env-save") {
    m.save(arg(0));
  } else if (a == "env-select") {
    m.message.clear();
    if (arg(0) == "-") m.editor.select(EnvSelection{});
    else m.editor.select(arg(0));
    m.colour.follow(m.editor);
  } else if (a == "env-tool") {
    const std::string t = arg(0);
    if (t == "move") m.tool = Tool::Move;
    else if (t == "rotate") m.tool = Tool::Rotate;
    else if (t == "scale") m.tool = Tool::Scale;
    else throw Error("no tool '" + t + "' (move, rotate, scale)");
  } else if (a == "env-snap") {
    m.snap_metres = std::clamp(number(0), 0.0f, 10.0f);
    if (step.args.size() > 1) m.snap_degrees = std::clamp(number(1), 0.0f, 90.0f);
  } else if (a == "env-click") {
    const int v = view_named(arg(0));
    m.press(v, vec2(number(1), number(2)));
    m.release();
  } else if (a == "env-drag" || a == "env-drag-from") {
    // env-drag VIEW X0 Y0 X1 Y1 [AXIS]: pixels in the view. env-drag-from VIEW ITEM DX DY [AXIS]: from
    // where the item's origin is drawn, by DX DY pixels.
    const int v = view_named(arg(0));
    if (m.width < 16) throw Error("the views are not drawn yet");
    vec2 from, to;
    std::size_t next = 5;
    if (a == "env-drag") {
      from = vec2(number(1), number(2)), to = vec2(number(3), number(4));
    } else {
      m.editor.select(arg(1));
      const auto p = project_to_pixel(m.camera(v), vec3((*m.editor.world_matrix())[3]), m.view_size(v));
      if (!p) throw Error("'" + arg(1) + "' is not in the " + arg(0) + " view");
      from = *p, to = *p + vec2(number(2), number(3));
      next = 4;
    }
    m.press(v, from, axis_named(arg(next)));
    if (!m.drag) throw Error("nothing to drag at " + std::to_string(static_cast<int>(from.x)) + "," + std::to_string(static_cast<int>(from.y)) + " in the " + arg(0) + " view");
    for (int k = 1; k <= 4; ++k) m.move_to(from + (to - from) * (static_cast<float>(k) / 4.0f));
    m.release();
  } else if (a == "env-set") {
    auto t = m.editor.transform();
    if (!t) throw Error("nothing selected");
    const vec3 v(number(1), step.args.size() > 2 ? number(2) : 0.0f, step.args.size() > 3 ? number(3) : 0.0f);
    if (arg(0) == "position") t->position = v;
    else if (arg(0) == "rotation") t->rotation = v;
    else if (arg(0) == "scale") t->scale = v;
    else if (arg(0) == "facing") t->rotation.y = v.x;
    else throw Error("no field '" + arg(0) + "' (position, rotation, scale, facing)");
    m.message.clear();
    m.editor.set_transform(*t);
  } else if (a == "env-add") {
    const vec3 at(m.frame.empty() ? 0.0f : m.frame.centre().x, 0.0f, m.frame.empty() ? 0.0f : m.frame.centre().z);
    const std::string kind = arg(0);
    m.message.clear();
    if (kind == "place") m.editor.add_place(arg(1), at);
    else if (kind == "character") m.editor.add_character(arg(1), at);
    else if (kind == "box") m.editor.add_primitive(ShapeKind::Box, at);
    else if (kind == "plane") m.editor.add_primitive(ShapeKind::Plane, at);
    else if (kind == "cylinder") m.editor.add_primitive(ShapeKind::Cylinder, at);
    else if (kind == "sphere") m.editor.add_primitive(ShapeKind::Sphere, at);
    else throw Error("cannot add '" + kind + "' (box, plane, cylinder, sphere, place, character)");
  } else if (a == "env-delete") {
    m.message.clear(), m.editor.remove_selected();
  } else if (a == "env-duplicate") {
    m.message.clear(), m.editor.duplicate_selected();
  } else if (a == "env-group") {
    std::vector<std::string> names;
    std::istringstream words(arg(1));
    for (std::string w; words >> w;) names.push_back(w);
    m.message.clear(), m.editor.group(names, arg(0));
  } else if (a == "env-colour") {
    m.message.clear();
    if (m.editor.selection().kind != EnvItem::Object) throw Error("select an object to colour");
    std::istringstream words(arg(0));
    std::vector<std::string> parts;
    for (std::string w; words >> w;) parts.push_back(w);
    // '#' starts a comment in a script: the hex colour may come without it.
    if (parts.size() == 1 && parts[0].size() == 6 && parts[0].find_first_not_of("0123456789abcdefABCDEF") == std::string::npos) parts[0] = "#" + parts[0];
    if (parts.size() == 1) m.colour.choose(m.editor, parse_scene_color(parts[0], "colour"));
    else if (parts.size() == 4 && parts[0] == "hsv") m.colour.choose_hsv(m.editor, vec3(std::stof(parts[1]), std::stof(parts[2]), std::stof(parts[3])));
    else if (parts.size() == 3) m.colour.choose(m.editor, vec3(std::stof(parts[0]), std::stof(parts[1]), std::stof(parts[2])));
    else throw Error("a colour is rrggbb, R G B (0..1) or hsv H S V (0..1)");
  } else if (a == "env-ramp") {
    if (m.editor.selection().kind != EnvItem::Object) throw Error("select an object to colour");
    m.message.clear(), m.colour.choose_ramp(m.editor, static_cast<std::size_t>(number(0)), static_cast<std::size_t>(number(1)));
  } else if (a == "env-keep") {
    m.colour.store(static_cast<std::size_t>(number(0)));
  } else if (a == "env-slot") {
    if (m.editor.selection().kind != EnvItem::Object) throw Error("select an object to colour");
    m.message.clear(), m.colour.choose_slot(m.editor, static_cast<std::size_t>(number(0)));
  } else if (a == "env-orbit") {
    ViewState& s = m.views[static_cast<std::size_t>(view_named(arg(0)))];
    if (s.orthographic) throw Error("the plan and the section do not orbit (they pan and zoom)");
    s.yaw += deg(number(1)), s.pitch = std::clamp(s.pitch + deg(number(2)), deg(-85.0f), deg(85.0f));
  } else if (a == "env-zoom") {
    ViewState& s = m.views[static_cast<std::size_t>(view_named(arg(0)))];
    const float f = std::clamp(number(1), 0.05f, 50.0f);
    if (s.orthographic) s.zoom = f;
    else s.distance /= f;
  } else if (a == "env-frame") {
    m.frame_all();
  } else if (a == "env-walk") {
    m.start_walk(arg(0), arg(1));
  } else if (a == "env-walk-time") {
    if (!m.preview) throw Error("no walk is shown");
    m.preview->time = std::clamp(number(0), 0.0f, m.preview->performance.duration), m.preview->playing = false;
  } else if (a == "env-stop") {
    m.stop_walk();
  } else {
    return false;
  }
  return true;
}

nlohmann::json EnvironmentPanel::dump() const {
  const Impl& m = *impl_;
  nlohmann::json j;
  j["file"] = m.editor.file();
  j["dirty"] = m.editor.dirty();
  j["status"] = m.status();
  j["selection"] = m.editor.selection_name();
  j["undo"] = m.editor.undo_label();
  j["redo"] = m.editor.redo_label();
  j["tool"] = kToolNames[static_cast<int>(m.tool)];
  j["scene"] = scene_to_json(m.editor.scene());
  if (const auto t = m.editor.transform())
    j["transform"] = {{"position", {t->position.x, t->position.y, t->position.z}},
                      {"rotation", {t->rotation.x, t->rotation.y, t->rotation.z}},
                      {"scale", {t->scale.x, t->scale.y, t->scale.z}}};
  j["views"] = nlohmann::json::array();
  for (int v = 0; v < 4; ++v) {
    const Viewport vp = m.viewport(v);
    j["views"].push_back({{"name", kViewNames[v]}, {"x", vp.x}, {"y", vp.y}, {"width", vp.width}, {"height", vp.height},
                          {"orthographic", m.views[static_cast<std::size_t>(v)].orthographic}});
  }
  j["frame"] = {{"min", {m.frame.min.x, m.frame.min.y, m.frame.min.z}}, {"max", {m.frame.max.x, m.frame.max.y, m.frame.max.z}}};
  const vec3 c = m.colour.palette().color();
  j["palette"]["color"] = color_hex(c);
  for (const ColorRamp& r : m.colour.palette().ramps()) {
    nlohmann::json ramp = nlohmann::json::array();
    for (const vec3& k : r.colors) ramp.push_back(color_hex(k));
    j["palette"]["ramps"].push_back(ramp);
  }
  j["preview"]["performing"] = m.performing.valid();
  j["preview"]["shown"] = m.preview != nullptr;
  if (m.preview) {
    j["preview"]["title"] = m.preview->title;
    j["preview"]["duration"] = m.preview->performance.duration;
    nlohmann::json path = nlohmann::json::array();
    for (const vec3& p : m.preview->path) path.push_back({p.x, p.y, p.z});
    j["preview"]["path"] = path;
    nlohmann::json log = nlohmann::json::array();
    for (const LogEntry& e : m.preview->performance.log) log.push_back({{"time", e.time}, {"text", e.text}, {"warning", e.warning}});
    j["preview"]["log"] = log;
  }
  return j;
}

}  // namespace gestura::studio_ui
