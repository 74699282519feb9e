#pragma once
// Cameras for looking at a signing avatar: presets framed from the avatar's own bounds (so they
// work on any body size), a free orbit camera, and split views (several cameras in one image).
// Conventions: metres, +Y up, the avatar faces +Z, its left is +X.
#include <span>
#include <string>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/anim/clip.hpp"
#include "gestura/core/math.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// What the presets frame: the body's bounding box at rest, the height of the hips, below which
// the interpreter framing cuts, and what must stay in view while the avatar signs: the elbows at
// every moment, the hands whenever they are above the hips (in the signing space).
struct FramingBox {
  vec3 min{0.0f};
  vec3 max{0.0f};
  float hips_y = 0.0f;
  float centre_x = 0.0f;       // the body's centre line (the root joint at rest, else the box's middle)
  bool has_limbs = false;      // the skeleton has H-Anim elbows and wrists
  vec3 limbs_min{0.0f}, limbs_max{0.0f};  // box of the elbows and the raised hands over the clip

  float height() const { return max.y - min.y; }
  // Half-width of the signing space around the body's centre line (hands reach beyond the torso).
  float reach() const;
};

// Mesh bounds at bind pose; hips from a joint named like the pelvis (sacroiliac, HumanoidRoot,
// pelvis, hips, root — first found) or, without one, at 53% of the height. With a clip, the limb
// box covers the whole clip (sampled at 30 fps); without, the rest pose.
FramingBox framing_box(const Mesh& mesh, const Skeleton& skeleton, const Clip* clip = nullptr);

// The follow camera's framing for frames 0..frames-1 at `fps`: the box of the raised hands within
// ±0.4 s of each frame (at least shoulder-wide), and a cut that rises from the hips to mid-chest
// while the hands sign high, smoothed over time so the camera glides.
std::vector<FramingBox> follow_framing(const FramingBox& box, const Skeleton& skeleton, const Clip& clip, float fps,
                                       int frames);

enum class CameraPreset : std::uint8_t { Front, Side, ThreeQuarter, Top, SideSection, Follow };
inline constexpr CameraPreset kCameraPresets[] = {CameraPreset::Front, CameraPreset::Side, CameraPreset::ThreeQuarter,
                                                  CameraPreset::Top, CameraPreset::SideSection, CameraPreset::Follow};

const char* preset_name(CameraPreset preset);
// Accepts front, side, three-quarter, top, side-section, follow; throws gestura::Error listing them otherwise.
CameraPreset parse_camera_preset(const std::string& name);
// A comma-separated list ("front,side"), at least one, at most 9 (a 3×3 split).
std::vector<CameraPreset> parse_camera_list(const std::string& list);

struct Camera {
  mat4 view{1.0f};
  mat4 projection{1.0f};
  vec3 eye{0.0f};
  vec3 target{0.0f};
  bool orthographic = false;
};

// front: interpreter framing as on television: from just above the head to the hips, the signer
//   centred, widened (zoomed out) only as far as the elbows and raised hands need; perspective, from +Z.
// follow: the same framing over a follow_framing box: it tightens on the active signing space.
// side: the avatar's left side, hips up. three-quarter: front-left, 40° round, slightly above.
// top: orthographic plan view (looking down, the avatar's front towards the image bottom).
// side-section: orthographic section from the avatar's left, whole body plus the space in front.
Camera preset_camera(CameraPreset preset, const FramingBox& box, float aspect);

// Free orbit about `target`: yaw about +Y from the +Z axis (0 = in front of the avatar), pitch up
// from the horizontal plane, both radians.
struct Orbit {
  float yaw = 0.0f;
  float pitch = 0.0f;
  float distance = 3.0f;
  vec3 target{0.0f, 1.2f, 0.0f};
  float vertical_fov = deg(30.0f);
};
Camera orbit_camera(const Orbit& orbit, float aspect);
// The orbit that sees what a perspective preset sees (orthographic ones map to their direction).
Orbit preset_orbit(CameraPreset preset, const FramingBox& box, float aspect);

// A pixel rectangle, origin at the image's top-left.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};
// Splits an image into a near-square grid of `count` panes, row by row.
std::vector<Viewport> split_viewports(int count, int width, int height);

}  // namespace gestura
