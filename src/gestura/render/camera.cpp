#include "gestura/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <sstream>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/skeleton/joint_names.hpp"

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

// The signing space above the hips: body width widened to the hands' reach, and room in front,
// grown to hold the limbs over the clip.
Region signing_space(const FramingBox& box) {
  const float cx = box.centre_x, reach = box.reach();
  Region r{{cx - reach, box.hips_y, box.min.z}, {cx + reach, box.max.y + 0.03f * box.height(), box.max.z + 0.6f * reach}};
  if (box.has_limbs) r.min = glm::min(r.min, box.limbs_min), r.max = glm::max(r.max, box.limbs_max);
  return r;
}

// Interpreter framing from the front: the crown just below the top edge, the hips' cut at the
// bottom edge, the signer on the centre line; the camera backs off (and the cut moves down) only
// as far as the limb box needs to stay inside the image with a small margin.
Camera interpreter_camera(const FramingBox& box, float aspect) {
  const float t = std::tan(kPerspectiveFov * 0.5f);
  const float top = box.max.y + 0.04f * box.height(), bottom = box.hips_y;
  const float cx = box.centre_x, zc = 0.5f * (box.min.z + box.max.z);
  struct Need {
    vec3 p;
    float margin;
  };
  std::vector<Need> needs{{{cx, top, zc}, 1.0f}, {{cx, bottom, zc}, 1.0f}};
  if (box.has_limbs)
    for (int corner = 0; corner < 8; ++corner)
      needs.push_back({{(corner & 1) ? box.limbs_max.x : box.limbs_min.x, (corner & 2) ? box.limbs_max.y : box.limbs_min.y,
                        (corner & 4) ? box.limbs_max.z : box.limbs_min.z}, 1.06f});
  // For a distance D: the band of camera heights that keeps every point inside (empty = too close).
  const auto band = [&](float distance, float& lo, float& hi) {
    const float eye_z = zc + distance;
    lo = -std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::max();
    for (const Need& n : needs) {
      const float dz = eye_z - n.p.z;
      if (dz < 0.1f) return false;
      if (std::abs(n.p.x - cx) > dz * t * aspect / n.margin) return false;
      lo = std::max(lo, n.p.y - dz * t / n.margin);
      hi = std::min(hi, n.p.y + dz * t / n.margin);
    }
    return lo <= hi;
  };
  float near_d = 0.5f * (top - bottom) / t, far_d = 50.0f * std::max(near_d, 0.1f), lo = 0.0f, hi = 0.0f;
  if (band(near_d, lo, hi)) far_d = near_d;
  for (int i = 0; i < 40 && far_d - near_d > 1e-4f; ++i) {
    const float mid = 0.5f * (near_d + far_d);
    (band(mid, lo, hi) ? far_d : near_d) = mid;
  }
  const float distance = far_d;
  band(distance, lo, hi);
  // Keep the crown at the top edge; what the extra distance buys goes below.
  const float cy = std::clamp(top - distance * t, lo, hi);
  Camera camera;
  camera.target = {cx, cy, zc};
  camera.eye = {cx, cy, zc + distance};
  camera.view = glm::lookAt(camera.eye, camera.target, vec3(0, 1, 0));
  camera.projection = glm::perspective(kPerspectiveFov, aspect, std::max(0.02f, distance - 1.5f), distance + 3.0f);
  return camera;
}

// The joints the framing keeps in view: elbows, and the hand's wrist, thumb tip and finger tips.
struct LimbJoints {
  std::vector<int> elbows, hands, shoulders;
};

LimbJoints limb_joints(const Skeleton& skeleton) {
  const std::vector<std::string> hanim = guess_hanim_names(skeleton);
  const auto find = [&](const std::string& name) {
    const auto it = std::find(hanim.begin(), hanim.end(), name);
    return it == hanim.end() ? -1 : static_cast<int>(it - hanim.begin());
  };
  LimbJoints out;
  for (const std::string side : {"l_", "r_"}) {
    if (const int j = find(side + "elbow"); j >= 0) out.elbows.push_back(j);
    if (const int j = find(side + "shoulder"); j >= 0) out.shoulders.push_back(j);
    for (const char* part : {"wrist", "thumb_tip", "index_tip", "middle_tip", "pinky_tip"})
      if (const int j = find(side + part); j >= 0) out.hands.push_back(j);
  }
  return out;
}

// Model-space joint positions at `frames` moments i / fps (clamped into the clip).
std::vector<std::vector<vec3>> sample_positions(const Skeleton& skeleton, const Clip& clip, float fps, int frames) {
  std::vector<std::vector<vec3>> out(static_cast<std::size_t>(std::max(frames, 0)), std::vector<vec3>(skeleton.size()));
  const Pose rest = rest_pose(skeleton);
  Pose pose;
  Sampler sampler(clip);
  std::vector<mat4> model(skeleton.size());
  for (int f = 0; f < frames; ++f) {
    sampler.sample(std::min(static_cast<float>(f) / fps, clip.duration), WrapMode::Clamp, rest, pose);
    local_to_model(skeleton, pose, model);
    model_positions(model, out[static_cast<std::size_t>(f)]);
  }
  return out;
}

// Grows `box`'s limb box by the elbows (unless `hands_only`) and, when above the hips, the hands
// at one moment.
void add_limbs(FramingBox& box, const LimbJoints& limbs, const std::vector<vec3>& p, bool hands_only = false) {
  const auto add = [&](const vec3& q) {
    if (!box.has_limbs) box.limbs_min = box.limbs_max = q, box.has_limbs = true;
    box.limbs_min = glm::min(box.limbs_min, q), box.limbs_max = glm::max(box.limbs_max, q);
  };
  if (!hands_only)
    for (int j : limbs.elbows) add(p[static_cast<std::size_t>(j)]);
  for (int j : limbs.hands)
    if (p[static_cast<std::size_t>(j)].y > box.hips_y) add(p[static_cast<std::size_t>(j)]);
}

}  // namespace

float FramingBox::reach() const { return std::max((max.x - min.x) * 0.5f, 0.3f * height()); }

FramingBox framing_box(const Mesh& mesh, const Skeleton& skeleton, const Clip* clip) {
  if (mesh.positions.empty()) throw Error("framing: the mesh has no vertices");
  FramingBox box;
  box.min = box.max = mesh.positions[0];
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
  box.centre_x = 0.5f * (box.min.x + box.max.x);
  if (skeleton.size() > 0) {
    std::vector<mat4> model(skeleton.size());
    local_to_model(skeleton, rest_pose(skeleton), model);
    const float root_x = model[0][3].x;
    if (root_x > box.min.x && root_x < box.max.x) box.centre_x = root_x;
  }
  const LimbJoints limbs = limb_joints(skeleton);
  if (limbs.elbows.empty()) return box;
  if (clip && clip->duration > 0.0f && clip->joint_count() == skeleton.size()) {
    const int frames = static_cast<int>(std::ceil(clip->duration * 30.0f)) + 1;
    for (const std::vector<vec3>& p : sample_positions(skeleton, *clip, 30.0f, frames)) add_limbs(box, limbs, p);
  } else {
    std::vector<vec3> p(skeleton.size());
    std::vector<mat4> model(skeleton.size());
    local_to_model(skeleton, rest_pose(skeleton), model);
    model_positions(model, p);
    add_limbs(box, limbs, p);
  }
  return box;
}

std::vector<FramingBox> follow_framing(const FramingBox& box, const Skeleton& skeleton, const Clip& clip, float fps,
                                       int frames) {
  std::vector<FramingBox> out(static_cast<std::size_t>(std::max(frames, 0)), box);
  const LimbJoints limbs = limb_joints(skeleton);
  if (frames <= 0 || !(fps > 0.0f) || limbs.elbows.empty() || clip.joint_count() != skeleton.size()) return out;
  const std::vector<std::vector<vec3>> p = sample_positions(skeleton, clip, fps, frames);
  float shoulders_y = box.max.y - 0.18f * box.height();
  if (!limbs.shoulders.empty()) {
    shoulders_y = 0.0f;
    for (int j : limbs.shoulders) shoulders_y += p[0][static_cast<std::size_t>(j)].y / static_cast<float>(limbs.shoulders.size());
  }
  // The cut never rises above mid-chest: the face and the upper body stay in the picture.
  const float chest_y = shoulders_y - 0.12f * box.height();
  const int window = std::max(1, static_cast<int>(std::lround(0.4f * fps)));
  std::vector<float> cut(out.size());
  std::vector<vec3> lo(out.size()), hi(out.size());
  for (int f = 0; f < frames; ++f) {
    FramingBox b = box;
    b.has_limbs = false;
    // The active space: where the hands are around this moment, never narrower than the shoulders.
    for (int j : limbs.shoulders) add_limbs(b, {{j}, {}, {}}, p[0]);
    for (int g = std::max(0, f - window); g <= std::min(frames - 1, f + window); ++g) add_limbs(b, limbs, p[static_cast<std::size_t>(g)], true);
    float lowest_hand = std::numeric_limits<float>::max();
    for (int g = std::max(0, f - window); g <= std::min(frames - 1, f + window); ++g)
      for (int j : limbs.hands)
        if (p[static_cast<std::size_t>(g)][static_cast<std::size_t>(j)].y > box.hips_y)
          lowest_hand = std::min(lowest_hand, p[static_cast<std::size_t>(g)][static_cast<std::size_t>(j)].y);
    cut[static_cast<std::size_t>(f)] = std::clamp(lowest_hand - 0.06f * box.height(), box.hips_y, std::max(box.hips_y, chest_y));
    lo[static_cast<std::size_t>(f)] = b.limbs_min, hi[static_cast<std::size_t>(f)] = b.limbs_max;
  }
  // Two passes of a ±0.25 s moving average: the camera eases in and out instead of jumping.
  const int smooth = std::max(1, static_cast<int>(std::lround(0.25f * fps)));
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<float> c0 = cut;
    const std::vector<vec3> l0 = lo, h0 = hi;
    for (int f = 0; f < frames; ++f) {
      float c = 0.0f, n = 0.0f;
      vec3 l(0.0f), h(0.0f);
      for (int g = std::max(0, f - smooth); g <= std::min(frames - 1, f + smooth); ++g)
        c += c0[static_cast<std::size_t>(g)], l += l0[static_cast<std::size_t>(g)], h += h0[static_cast<std::size_t>(g)], n += 1.0f;
      cut[static_cast<std::size_t>(f)] = c / n, lo[static_cast<std::size_t>(f)] = l / n, hi[static_cast<std::size_t>(f)] = h / n;
    }
  }
  // A speed limit on top: on a long hold the average still zooms the whole way in half a second, and
  // the eye, at about 2.5 times the framed extent's change (the lens sees the box at ~30°), moved 5 cm a
  // frame. Each framed coordinate may change by at most kFramingSpeed; limiting forward alone would
  // make the camera lag, so the limit runs forward and backward and the two are averaged (each step
  // of the average is within the limit, and the move is centred on the moment that asks for it).
  constexpr float kFramingSpeed = 0.3f;  // m/s of the framed box: the eye glides at ≤ ~0.75 m/s
  const float max_step = kFramingSpeed / fps;
  const auto limit_speed = [&](std::vector<float>& x) {
    std::vector<float> forward = x, backward = x;
    for (std::size_t f = 1; f < x.size(); ++f)
      forward[f] = std::clamp(forward[f], forward[f - 1] - max_step, forward[f - 1] + max_step);
    for (std::size_t f = x.size() - 1; f-- > 0;)
      backward[f] = std::clamp(backward[f], backward[f + 1] - max_step, backward[f + 1] + max_step);
    for (std::size_t f = 0; f < x.size(); ++f) x[f] = 0.5f * (forward[f] + backward[f]);
  };
  limit_speed(cut);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float> l(out.size()), h(out.size());
    for (std::size_t f = 0; f < out.size(); ++f) l[f] = lo[f][axis], h[f] = hi[f][axis];
    limit_speed(l), limit_speed(h);
    for (std::size_t f = 0; f < out.size(); ++f) lo[f][axis] = l[f], hi[f][axis] = h[f];
  }
  for (int f = 0; f < frames; ++f) {
    FramingBox& b = out[static_cast<std::size_t>(f)];
    b.hips_y = cut[static_cast<std::size_t>(f)];
    b.has_limbs = true;
    b.limbs_min = lo[static_cast<std::size_t>(f)], b.limbs_max = hi[static_cast<std::size_t>(f)];
  }
  return out;
}

const char* preset_name(CameraPreset preset) {
  switch (preset) {
    case CameraPreset::Front: return "front";
    case CameraPreset::Side: return "side";
    case CameraPreset::ThreeQuarter: return "three-quarter";
    case CameraPreset::Top: return "top";
    case CameraPreset::SideSection: return "side-section";
    case CameraPreset::Follow: return "follow";
  }
  return "?";
}

CameraPreset parse_camera_preset(const std::string& name) {
  for (CameraPreset p : kCameraPresets)
    if (name == preset_name(p)) return p;
  throw Error("unknown camera '" + name + "' (front, side, three-quarter, top, side-section, follow)");
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
  const float cx = box.centre_x, reach = box.reach();
  switch (preset) {
    case CameraPreset::Front:
    case CameraPreset::Follow: return interpreter_camera(box, aspect);
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
