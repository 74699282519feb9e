#include "gestura/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <sstream>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

constexpr float kPerspectiveFov = deg(30.0f);
constexpr float kMargin = 1.08f;  // breathing room around the framed region

struct Region {
  vec3 min, max;
};

// The camera that looks along `direction` and fits `region` into the image: projects the region's
// corners onto the camera axes, centres them and backs off until the front face fits.
Camera fit(const Region& region, vec3 direction, vec3 up, float aspect, bool orthographic) {
  direction = glm::normalize(direction);
  const vec3 right = glm::normalize(glm::cross(direction, up));
  const vec3 true_up = glm::cross(right, direction);
  vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 p{(corner & 1) ? region.max.x : region.min.x, (corner & 2) ? region.max.y : region.min.y,
                 (corner & 4) ? region.max.z : region.min.z};
    const vec3 q{glm::dot(p, right), glm::dot(p, true_up), glm::dot(p, direction)};
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const vec3 mid = (lo + hi) * 0.5f;
  const vec3 centre = right * mid.x + true_up * mid.y + direction * mid.z;
  float half_w = (hi.x - lo.x) * 0.5f * kMargin, half_h = (hi.y - lo.y) * 0.5f * kMargin;
  const float half_depth = (hi.z - lo.z) * 0.5f;
  if (half_w < half_h * aspect) half_w = half_h * aspect; else half_h = half_w / aspect;

  Camera camera;
  camera.orthographic = orthographic;
  camera.target = centre;
  if (orthographic) {
    const float back = half_depth + 1.0f;
    camera.eye = centre - direction * back;
    camera.projection = glm::ortho(-half_w, half_w, -half_h, half_h, 0.01f, back + half_depth + 1.0f);
  } else {
    const float t = std::tan(kPerspectiveFov * 0.5f);
    const float distance = half_h / t + half_depth;
    camera.eye = centre - direction * distance;
    camera.projection = glm::perspective(kPerspectiveFov, aspect, std::max(0.02f, distance - half_depth * 3.0f - 0.5f),
                                         distance + half_depth * 3.0f + 1.0f);
  }
  camera.view = glm::lookAt(camera.eye, camera.target, true_up);
  return camera;
}

// The signing space above the hips: body width widened to the hands' reach, and room in front.
Region signing_space(const FramingBox& box) {
  const float cx = (box.min.x + box.max.x) * 0.5f, reach = box.reach();
  return {{cx - reach, box.hips_y, box.min.z}, {cx + reach, box.max.y + 0.03f * box.height(), box.max.z + 0.6f * reach}};
}

}  // namespace

float FramingBox::reach() const { return std::max((max.x - min.x) * 0.5f, 0.3f * height()); }

FramingBox framing_box(const Mesh& mesh, const Skeleton& skeleton) {
  if (mesh.positions.empty()) throw Error("framing: the mesh has no vertices");
  FramingBox box{mesh.positions[0], mesh.positions[0], 0.0f};
  for (const vec3& p : mesh.positions) box.min = glm::min(box.min, p), box.max = glm::max(box.max, p);
  box.hips_y = box.min.y + 0.53f * box.height();
  for (const char* name : {"sacroiliac", "HumanoidRoot", "pelvis", "hips", "Hips", "root"}) {
    const int joint = skeleton.find(name);
    if (joint < 0) continue;
    std::vector<mat4> model(skeleton.size());
    local_to_model(skeleton, rest_pose(skeleton), model);
    const float y = model[static_cast<std::size_t>(joint)][3].y;
    if (y > box.min.y && y < box.max.y) box.hips_y = y;
    break;
  }
  return box;
}

const char* preset_name(CameraPreset preset) {
  switch (preset) {
    case CameraPreset::Front: return "front";
    case CameraPreset::Side: return "side";
    case CameraPreset::ThreeQuarter: return "three-quarter";
    case CameraPreset::Top: return "top";
    case CameraPreset::SideSection: return "side-section";
  }
  return "?";
}

CameraPreset parse_camera_preset(const std::string& name) {
  for (CameraPreset p : kCameraPresets)
    if (name == preset_name(p)) return p;
  throw Error("unknown camera '" + name + "' (front, side, three-quarter, top, side-section)");
}

std::vector<CameraPreset> parse_camera_list(const std::string& list) {
  std::vector<CameraPreset> presets;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) presets.push_back(parse_camera_preset(item));
  if (presets.empty()) throw Error("--camera needs at least one camera name");
  if (presets.size() > 9) throw Error("--camera: at most 9 cameras in one split view, got " + std::to_string(presets.size()));
  return presets;
}

Camera preset_camera(CameraPreset preset, const FramingBox& box, float aspect) {
  const Region space = signing_space(box);
  const float cx = (box.min.x + box.max.x) * 0.5f, reach = box.reach();
  switch (preset) {
    case CameraPreset::Front: return fit(space, {0, 0, -1}, {0, 1, 0}, aspect, false);
    case CameraPreset::Side: return fit(space, {-1, 0, 0}, {0, 1, 0}, aspect, false);
    case CameraPreset::ThreeQuarter:
      return fit(space, {-std::sin(deg(40.0f)), -0.15f, -std::cos(deg(40.0f))}, {0, 1, 0}, aspect, false);
    case CameraPreset::Top:
      return fit({{cx - reach, box.min.y, box.min.z - 0.1f * reach}, {cx + reach, box.max.y, box.max.z + 0.6f * reach}},
                 {0, -1, 0}, {0, 0, -1}, aspect, true);
    case CameraPreset::SideSection:
      return fit({box.min, {box.max.x, box.max.y, box.max.z + 0.6f * reach}}, {-1, 0, 0}, {0, 1, 0}, aspect, true);
  }
  throw Error("unknown camera preset");
}

Camera orbit_camera(const Orbit& orbit, float aspect) {
  const float pitch = std::clamp(orbit.pitch, deg(-89.0f), deg(89.0f));
  const vec3 offset{std::sin(orbit.yaw) * std::cos(pitch), std::sin(pitch), std::cos(orbit.yaw) * std::cos(pitch)};
  Camera camera;
  camera.target = orbit.target;
  camera.eye = orbit.target + offset * orbit.distance;
  camera.view = glm::lookAt(camera.eye, camera.target, vec3(0, 1, 0));
  camera.projection = glm::perspective(orbit.vertical_fov, aspect, std::max(0.01f, orbit.distance * 0.05f),
                                       orbit.distance * 4.0f + 10.0f);
  return camera;
}

Orbit preset_orbit(CameraPreset preset, const FramingBox& box, float aspect) {
  const Camera camera = preset_camera(preset, box, aspect);
  const vec3 offset = camera.eye - camera.target;
  Orbit orbit;
  orbit.target = camera.target;
  orbit.distance = camera.orthographic ? 2.5f * box.height() : glm::length(offset);
  const vec3 d = glm::normalize(offset);
  orbit.pitch = std::asin(std::clamp(d.y, -1.0f, 1.0f));
  orbit.yaw = std::atan2(d.x, d.z);
  orbit.vertical_fov = kPerspectiveFov;
  return orbit;
}

std::vector<Viewport> split_viewports(int count, int width, int height) {
  if (count <= 0) return {};
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<float>(count))));
  const int rows = (count + columns - 1) / columns;
  std::vector<Viewport> panes;
  for (int i = 0; i < count; ++i) {
    const int r = i / columns, c = i % columns;
    const int x0 = c * width / columns, x1 = (c + 1) * width / columns;
    const int y0 = r * height / rows, y1 = (r + 1) * height / rows;
    panes.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return panes;
}

}  // namespace gestura
