#pragma once
// Writing a motion a request made (a sign, a sentence, a reach, a retargeted clip) to the file its
// output field names, chosen by the extension in any case: .json joint positions, .bvh motion,
// .glb/.gltf animation (with the body when there is one), .pose Holistic landmarks, or .png/.gif/.mp4/.webm pictures of the
// body performing it. Every such request takes these same fields.
#include <optional>
#include <string>

#include "gestura/anim/clip.hpp"
#include "gestura/app/codecs.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::app {

// How pictures of a motion are made.
struct PictureOptions {
  ImageSize size{1280, 720};
  std::optional<int> fps;  // none: 30, or the source's own rate where a command keeps it (retarget)
  CameraList camera{CameraPreset::Front};

  int rate() const { return fps.value_or(30); }

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.size, FieldInfo{.name = "size", .help = "image size, 16..4096 per side, at most 4096x2304 pixels", .value = "WxH", .group = "Output"});
    visit(self.fps, FieldInfo{.name = "fps", .help = "frames per second", .value = "N", .min = 1, .max = kMaxFps, .group = "Output", .unset = "30"});
    visit(self.camera, FieldInfo{.name = "camera", .help = "front, side, three-quarter, top, side-section, follow; a comma list (front,side) renders a split view", .value = "LIST", .group = "Output"});
  }
};

struct MotionOutput {
  std::string output;  // the file; empty: nothing is written
  PictureOptions picture;
  bool sheet = false;  // .png only: 16 frames in a 4x4 grid

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.output, FieldInfo{.name = "output", .help = "the file to write, by extension: .json, .bvh, .glb, .gltf, .pose, .png, .gif, .mp4, .webm", .value = "OUT", .short_flag = 'o', .group = "Output"});
    PictureOptions::fields(self.picture, visit);
    visit(self.sheet, FieldInfo{.name = "sheet", .help = ".png: a 4x4 contact sheet of 16 frames instead of one moment", .group = "Output"});
  }
};

inline constexpr const char* kMotionOutputHelp =
    "OUT by extension: .json joint positions ({\"fps\", \"joints\", \"frames\"}; metres, +Y up, facing +Z,\n"
    "H-Anim names), .bvh motion, .glb/.gltf animation with the avatar's body, .pose MediaPipe Holistic\n"
    "landmarks (pose-format; pixels as the pictures of the same --size/--camera show them), or pictures of the avatar:\n"
    ".png (one moment; --sheet: 16 frames in a 4x4 grid), .gif, .mp4, .webm.";

enum class MotionFileKind { JointPositions, Bvh, Gltf, Pose, Pictures, Unknown };
MotionFileKind motion_file_kind(const std::string& path);

// True when writing `out` needs the body (a mesh skinned to the clip's skeleton).
bool output_shows_body(const MotionOutput& out);

// The checks made before any work: an output is named (when `required`), its extension is one this
// writes, and picture options fit it. Throws AppError (usage) at the field.
void validate(const MotionOutput& out, bool required);

// The render job for pictures of `out`, showing `still_time` when it is a single .png.
RenderJob render_job(const MotionOutput& out, float still_time);

// What write_motion wrote.
struct WrittenFile {
  std::string path;
  int frames = 0;
};

// Contract: clip valid for skeleton; body (may be null unless output_shows_body for pictures) skinned
// to the skeleton. still_time: the moment a single .png shows. frame_time: spacing of .json/.bvh
// frames (0: 1/fps). Long renders report to and stop by `context`.
WrittenFile write_motion(const MotionOutput& out, const Skeleton& skeleton, const Clip& clip, const Mesh* body,
                         float still_time, const RunContext& context, float frame_time = 0.0f);

// The monitor that connects a render to the context's progress and stop.
RenderMonitor render_monitor(const RunContext& context, const std::string& stage);

}  // namespace gestura::app
