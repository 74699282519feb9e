#include "gestura/render/scene_cameras.hpp"

#include <algorithm>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

// `near` > 0.05 cuts away what lies between the eye and the subject (a wall in front of a room seen
// from outside).
Camera look(const vec3& eye, const vec3& target, float fov_degrees, float aspect, float near = 0.05f) {
  Camera c;
  c.eye = eye;
  c.target = target;
  const vec3 up = std::abs(glm::normalize(target - eye).y) > 0.99f ? vec3(0, 0, -1) : vec3(0, 1, 0);
  c.view = glm::lookAt(eye, target, up);
  const float far = std::max(50.0f, glm::length(target - eye) * 4.0f);
  c.projection = glm::perspective(deg(fov_degrees), aspect, near, far);
  return c;
}

// The vertical field of view (degrees, with a margin) a camera at `eye` looking at `target` needs to
// show every point; huge when a point lies behind the eye or nearer than 0.3 m in depth.
float framing_fov(const vec3& eye, const vec3& target, std::span<const vec3> points, float aspect) {
  const vec3 f = glm::normalize(target - eye);
  const vec3 up = std::abs(f.y) > 0.99f ? vec3(0, 0, -1) : vec3(0, 1, 0);
  const vec3 r = glm::normalize(glm::cross(f, up));
  const vec3 u = glm::cross(r, f);
  float tan_half = 0.0f;
  for (const vec3& p : points) {
    const vec3 d = p - eye;
    const float z = glm::dot(d, f);
    if (z < 0.3f) return 1e6f;
    tan_half = std::max({tan_half, std::abs(glm::dot(d, u)) / z, std::abs(glm::dot(d, r)) / (z * aspect)});
  }
  return 2.0f * to_degrees(std::atan(tan_half * 1.06f));
}

Camera ortho(const vec3& eye, const vec3& target, const vec3& up, float half_height, float aspect, float depth, float near = 0.01f) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.orthographic = true;
  c.view = glm::lookAt(eye, target, up);
  c.projection = glm::ortho(-half_height * aspect, half_height * aspect, -half_height, half_height, near, depth);
  return c;
}

Aabb usable(const Aabb& bounds, std::span<const CharacterView> characters) {
  Aabb b = bounds;
  for (const CharacterView& c : characters) b.grow(c.position), b.grow(c.head + vec3(0, 0.2f, 0));
  if (b.empty()) b.grow(vec3(-2, 0, -2)), b.grow(vec3(2, 2, 2));
  // Rooms are mostly floor: a camera framing the whole floor slab (walls included) sees them well.
  return b;
}

}  // namespace

std::vector<std::string> expand_scene_cameras(const std::vector<std::string>& names, const Scene& scene) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    if (n == "alias") {
      out.insert(out.end(), {"perspective", "perspective2", "plan", "section"});
      continue;
    }
    const bool built_in = std::find(std::begin(kBuiltInSceneCameras), std::end(kBuiltInSceneCameras), n) != std::end(kBuiltInSceneCameras);
    if (!built_in && !scene.find_camera(n) && !scene.find_character(n)) {
      std::string known;
      for (const SceneCamera& c : scene.cameras) known += " " + c.name;
      for (const char* b : kBuiltInSceneCameras) known += std::string(" ") + b;
      for (const SceneCharacter& c : scene.characters) known += " " + c.name;
      throw Error("unknown camera '" + n + "' (this scene has:" + known + ")");
    }
    out.push_back(n);
  }
  if (out.empty()) throw Error("no camera");
  if (out.size() > 9) throw Error("at most 9 cameras in a split view");
  return out;
}

Camera scene_camera(const std::string& name, const Scene& scene, const Aabb& bounds, std::span<const CharacterView> characters,
                    float aspect) {
  if (const SceneCamera* c = scene.find_camera(name)) {
    vec3 target = c->target;
    if (!c->look_at.empty())
      for (const CharacterView& v : characters)
        if (v.name == c->look_at) target = v.head - vec3(0, 0.25f, 0);
    if (c->orthographic) {
      const vec3 d = glm::normalize(target - c->position);
      const vec3 up = std::abs(d.y) > 0.99f ? vec3(0, 0, -1) : vec3(0, 1, 0);
      return ortho(c->position, target, up, c->view_height * 0.5f, aspect, glm::length(target - c->position) * 3.0f + 50.0f);
    }
    return look(c->position, target, c->fov, aspect);
  }
  for (const CharacterView& v : characters)
    if (v.name == name) {
      const vec3 forward(std::sin(v.facing), 0.0f, std::cos(v.facing));
      const vec3 right(-forward.z, 0.0f, forward.x);
      const vec3 eye = v.head - forward * 1.6f + right * 0.45f + vec3(0, 0.25f, 0);
      return look(eye, v.head + forward * 2.0f - vec3(0, 0.35f, 0), 50.0f, aspect);
    }
  const Aabb b = usable(bounds, characters);
  const vec3 centre = b.centre(), size = b.max - b.min;
  if (name == "plan") {
    const float half = std::max(size.z * 0.5f, size.x * 0.5f / aspect) * 1.05f;
    return ortho(vec3(centre.x, b.max.y + 5.0f, centre.z), centre, vec3(0, 0, -1), half, aspect, size.y + 20.0f);
  }
  if (name == "section") {
    // A cut through the middle of the scene (what lies in front of it is not drawn), seen from +Z.
    const float half = std::max(size.y * 0.5f, size.x * 0.5f / aspect) * 1.08f;
    return ortho(vec3(centre.x, centre.y, b.max.z + 5.0f), centre, vec3(0, 1, 0), half, aspect, size.z + 20.0f,
                 5.0f + (b.max.z - centre.z));
  }
  // The perspective views stand in high corners of the scene's box looking down across it, so a
  // walled room is seen from inside (its walls would hide it from outside).
  if (name == "perspective" || name == "perspective2") {
    const vec3 corner = name == "perspective" ? vec3(0.05f, 0.9f, 0.95f) : vec3(0.95f, 0.9f, 0.05f);
    const vec3 eye = b.min + (b.max - b.min) * corner;
    const vec3 target = vec3(centre.x, b.min.y + std::min(0.8f, size.y * 0.3f), centre.z);
    return look(eye, target, 62.0f, aspect);
  }
  // "characters": frame every character's body, from the south-east and a little above — or, when a
  // room's walls keep the camera too close for that (a character by the wall it would stand behind),
  // from the nearest direction round them that fits everyone.
  std::vector<vec3> points;
  Aabb people;
  for (const CharacterView& v : characters)
    for (int k = 0; k < 8; ++k) {
      const vec3 p((k & 1) ? v.position.x + 0.35f : v.position.x - 0.35f, (k & 2) ? v.head.y + 0.2f : v.position.y,
                   (k & 4) ? v.position.z + 0.35f : v.position.z - 0.35f);
      points.push_back(p);
      people.grow(p);
    }
  if (people.empty()) {
    people = b;
    for (int k = 0; k < 8; ++k)
      points.push_back(vec3((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z));
  }
  const vec3 centre_people = people.centre();
  const float radius = glm::length(people.max - people.min) * 0.5f;
  const float fit = std::min(deg(20.0f), std::atan(std::tan(deg(20.0f)) * aspect));
  const vec3 inner_min = b.min + vec3(0.35f), inner_max = b.max - vec3(0.35f);
  const bool walled = inner_min.x < inner_max.x && inner_min.z < inner_max.z;
  const vec3 south_east = glm::normalize(vec3(0.35f, 0.3f, 1.0f));
  float best_fov = 1e9f;
  Camera best;
  for (int i = 0; i < 12; ++i) {
    const float yaw = deg(30.0f) * static_cast<float>((i + 1) / 2) * (i % 2 ? 1.0f : -1.0f);  // 0, 30, -30, 60, -60, …
    const vec3 from(south_east.x * std::cos(yaw) + south_east.z * std::sin(yaw), south_east.y,
                    -south_east.x * std::sin(yaw) + south_east.z * std::cos(yaw));
    // At the distance that fits them — but inside the scene's box (a room's walls would hide them
    // from outside).
    vec3 eye = centre_people + from * (radius / std::sin(fit) * 0.92f);
    if (walled) {
      const vec3 d = eye - centre_people;
      float t = 1.0f;
      for (int axis : {0, 2}) {
        if (d[axis] > 1e-4f) t = std::min(t, (inner_max[axis] - centre_people[axis]) / d[axis]);
        if (d[axis] < -1e-4f) t = std::min(t, (inner_min[axis] - centre_people[axis]) / d[axis]);
      }
      eye = centre_people + d * std::max(t, 0.15f);
    }
    const float fov = framing_fov(eye, centre_people, points, aspect);
    if (fov < best_fov) best_fov = fov, best = look(eye, centre_people, std::clamp(fov, 30.0f, 100.0f), aspect);
    if (fov <= 75.0f) break;  // the first direction (nearest the south-east) that fits everyone
  }
  return best;
}

std::vector<View> scene_views(const std::vector<std::string>& names, const Scene& scene, const Aabb& bounds,
                              std::span<const CharacterView> characters, int width, int height) {
  const std::vector<std::string> expanded = expand_scene_cameras(names, scene);
  const std::vector<Viewport> panes = split_viewports(static_cast<int>(expanded.size()), width, height);
  std::vector<View> views;
  for (std::size_t i = 0; i < panes.size(); ++i) {
    const float aspect = static_cast<float>(panes[i].width) / static_cast<float>(std::max(1, panes[i].height));
    views.push_back({scene_camera(expanded[i], scene, bounds, characters, aspect), panes[i]});
  }
  return views;
}

}  // namespace gestura
