#pragma once
// Rendering a subject to a file: one still (PNG), a contact sheet (16 frames in a 4×4 grid as one
// PNG) or an animation (GIF/MP4/WebM), headless. The job's limits are checked here; reading them
// from text is the command layer's (app/).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gestura/io/keypoints.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/render/look.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/render/subject.hpp"

namespace gestura {

inline constexpr int kMinImageSide = 16, kMaxImageSide = 4096;
// 4096×2304: with 4× MSAA colour and depth that is already ~300 MB of render target.
inline constexpr long kMaxImagePixels = 4096L * 2304L;
inline constexpr int kMaxFps = 120;

struct ImageSize {
  int width = 0, height = 0;
};
// Both sides in [16, 4096] and at most kMaxImagePixels in all; throws gestura::Error naming the limit otherwise.
void check_image_size(ImageSize size);

struct RenderJob {
  std::string output;                          // .png, .gif, .mp4 or .webm
  ImageSize size{1280, 720};
  int fps = 30;
  std::vector<CameraPreset> cameras{CameraPreset::Front};  // more than one: split view
  std::optional<Orbit> orbit;                  // replaces the presets when set
  bool orbit_about_body = true;                // aim the orbit at the front framing's centre, not orbit->target
  Look look;
  bool sheet = false;                          // PNG only: 4×4 contact sheet over the clip
  float still_time = 0.0f;                     // the time a single PNG shows
  float rest_seconds = 2.0f;                   // animation length when the subject has no clip
  SkinningDevice skinning = SkinningDevice::Gpu;
  int msaa_samples = 0;                        // 1, 2 or 4 (llvmpipe: 2 is 4; 4 costs about twice 1, bench R1);
                                               // 0: by output (job_antialiasing: video 1, PNG 4)
  bool edge_filter = true;                     // with 1 sample: edges smoothed by the edge filter
};

// Throws gestura::Error for a bad combination (sheet with a video, unknown extension, sizes out of
// range, odd sizes for MP4/WebM) before anything is rendered.
void validate(const RenderJob& job);

// The renderer's antialiasing for the job's msaa_samples, edge_filter and output.
Antialiasing job_antialiasing(const RenderJob& job);

// The number of frames an animation of `seconds` at `fps` has: frames at 0, 1/fps, … up to and
// including the end (at least 1).
int frame_count(float seconds, int fps);

struct RenderReport {
  int frames = 0;
  std::string renderer;  // GL platform and renderer name
};

// Who watches a long render: frame_done after every frame (without it, a progress bar on a
// terminal's stderr), stop_requested before every frame (true: the render stops, throwing
// gestura::Cancelled, and leaves no file).
struct RenderMonitor {
  std::function<void(int done, int total)> frame_done;
  std::function<bool()> stop_requested;
};

// Renders headless and writes job.output (staged: nothing is left behind on failure).
RenderReport render_to_file(const RenderSubject& subject, const RenderJob& job, const RenderMonitor& monitor = {});

// The views for an image of `width`×`height`: one per camera (split grid) or the orbit. A follow
// camera frames `follow` when given (the moment's follow_framing box), else `box`.
std::vector<View> job_views(const RenderJob& job, const FramingBox& box, int width, int height,
                            const FramingBox* follow = nullptr);

// What the first camera of `job` sees at frames 0..frames-1 (i / fps), as pinhole cameras over the
// whole job.size image, for projecting joints exactly as the pictures show them (the .pose
// writer): one camera for a fixed framing, one per frame for the follow camera. Throws
// gestura::Error for an orthographic camera (top, side-section).
std::vector<PinholeCamera> job_pinhole_cameras(const RenderSubject& subject, const RenderJob& job, float fps, int frames);

}  // namespace gestura
