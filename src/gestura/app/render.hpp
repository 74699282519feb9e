#pragma once
// render: the avatar rendered headless (EGL) to a PNG, a PNG contact sheet, GIF, MP4 or WebM — at
// rest, doing the test wave, or playing a motion on its skeleton. view: the same subject in a
// window (the window itself is the adapter's: apps/gestura/cmd_view.cpp, the studio).
#include <optional>
#include <string>
#include <vector>

#include "gestura/app/codecs.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/app/render_subject.hpp"
#include "gestura/render/render_job.hpp"

namespace gestura::app {

struct RenderRequest {
  SubjectChoice subject;
  MotionOutput output;  // required: .png, .gif, .mp4 or .webm
  std::optional<OrbitView> orbit;
  std::optional<HexColor> background;
  std::vector<std::string> color;  // MATERIAL=#rrggbb
  float time = 0.0f;
  float seconds = 2.0f;
  std::optional<int> msaa;  // unset: by output (RenderJob::msaa_samples 0)
  bool cpu_skinning = false;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    SubjectChoice::fields(self.subject, visit);
    MotionOutput::fields(self.output, visit);
    visit(self.orbit, FieldInfo{.name = "orbit", .help = "free camera: degrees about +Y from the front, degrees up, metres away from the target X,Y,Z (default: the body's centre), instead of --camera", .value = "YAW,PITCH,DIST[,X,Y,Z]", .group = "Output"});
    visit(self.background, FieldInfo{.name = "background", .help = "background colour", .value = "#rrggbb", .group = "Output", .unset = "#999ea3"});
    visit(self.color, FieldInfo{.name = "color", .help = "colour of skin, cloth, hair, eye-white, iris, lips, teeth, tongue, brow, pupil or mouth (repeatable)", .value = "MATERIAL=#rrggbb", .group = "Output"});
    visit(self.time, FieldInfo{.name = "time", .help = "the time a single PNG shows (s)", .value = "S", .min = 0, .max = 3600, .group = "Output"});
    visit(self.seconds, FieldInfo{.name = "seconds", .help = "animation length at rest (s)", .value = "S", .min = 0, .max = 3600, .group = "Output"});
    visit(self.msaa, FieldInfo{.name = "msaa", .help = "edge smoothing: 4 or 2 samples per pixel (multisampling), or 1 sample and an edge filter (half the cost on a CPU renderer)", .value = "N", .min = 1, .max = 4, .group = "Output", .unset = "1 for video, 4 for .png"});
    visit(self.cpu_skinning, FieldInfo{.name = "cpu_skinning", .help = "skin on the CPU and upload (comparison path)", .group = "Output"});
  }
};

struct RenderResult {
  RenderReport report;  // frames written, the GL renderer used
  std::string written;
  std::vector<Notice> notices;
};

// The render job the request describes (all its options checked); throws AppError (usage).
RenderJob render_job(const RenderRequest& request);
void validate(const RenderRequest& request);
RenderResult run(const RenderRequest& request, const RunContext& context = {});
nlohmann::json to_json(const RenderResult& result);

struct ViewRequest {
  SubjectChoice subject;
  SubjectExtras extras;  // a sign or English text
  CameraList camera{CameraPreset::Front};
  ImageSize size{1280, 720};
  std::optional<HexColor> background;
  std::string screenshot;  // save the window after `frames` frames and quit
  int frames = 30;
  std::optional<float> at;  // start paused at this time

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    SubjectChoice::fields(self.subject, visit);
    SignSource::fields(self.extras.sign, visit);
    visit(self.extras.text, FieldInfo{.name = "text", .help = "English to translate and sign, as gestura say does", .value = "TEXT"});
    visit(self.camera, FieldInfo{.name = "camera", .help = "start camera: front, side, three-quarter, top, side-section, follow", .value = "PRESET", .group = "Output"});
    visit(self.size, FieldInfo{.name = "size", .help = "window size", .value = "WxH", .group = "Output"});
    visit(self.background, FieldInfo{.name = "background", .help = "background colour", .value = "#rrggbb", .group = "Output"});
    visit(self.screenshot, FieldInfo{.name = "screenshot", .help = "save the window after --frames frames and quit (for scripts, Xvfb)", .value = "PATH.png", .group = "Output"});
    visit(self.frames, FieldInfo{.name = "frames", .help = "frames before the screenshot", .value = "N", .min = 1, .max = 100000, .group = "Output"});
    visit(self.at, FieldInfo{.name = "at", .help = "start paused at this time of the motion (s)", .value = "SECONDS", .min = 0, .max = 3600, .group = "Output"});
  }
};

void validate(const ViewRequest& request);
// The subject the window shows (the window is the caller's).
LoadedSubject run(const ViewRequest& request, const RunContext& context = {});

}  // namespace gestura::app
