#include "gestura/render/render_job.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/render/encoder_thread.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/progress.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {
namespace {

constexpr int kSheetColumns = 4, kSheetFrames = 16;

bool ends_with_png(const std::string& path) { return has_extension(path, ".png"); }

// Calls the monitor, or draws a progress bar on a terminal when no one watches.
class FrameWatch {
 public:
  FrameWatch(const RenderMonitor& monitor, const std::string& label, int total)
      : monitor_(monitor), total_(total) {
    if (!monitor_.frame_done) bar_.emplace(label, total);
  }
  void before_frame() const {
    if (monitor_.stop_requested && monitor_.stop_requested()) throw Cancelled("render stopped");
  }
  void done(int frames) {
    if (monitor_.frame_done) monitor_.frame_done(frames, total_);
    else bar_->update(frames);
  }

 private:
  const RenderMonitor& monitor_;
  int total_;
  std::optional<Progress> bar_;
};

}  // namespace

void check_image_size(ImageSize size) {
  const std::string text = std::to_string(size.width) + "x" + std::to_string(size.height);
  for (int side : {size.width, size.height})
    if (side < kMinImageSide || side > kMaxImageSide)
      throw Error("size " + text + ": each side must be " + std::to_string(kMinImageSide) + ".." +
                  std::to_string(kMaxImageSide) + " pixels");
  if (static_cast<long>(size.width) * size.height > kMaxImagePixels)
    throw Error("size " + text + ": at most " + std::to_string(kMaxImagePixels) + " pixels in all (e.g. 4096x2304)");
}

void validate(const RenderJob& job) {
  if (job.output.empty()) throw Error("no output file (-o OUT.png|.gif|.mp4|.webm)");
  const bool png = ends_with_png(job.output);
  if (!png) video_format_of(job.output);  // throws for unknown extensions
  if (job.sheet && !png) throw Error("--sheet writes a PNG contact sheet; " + job.output + " is not .png");
  check_image_size(job.size);
  if (job.fps < 1 || job.fps > kMaxFps) throw Error("fps " + std::to_string(job.fps) + " is outside 1.." + std::to_string(kMaxFps));
  if (job.cameras.empty() && !job.orbit) throw Error("no camera");
  if (job.msaa_samples != 0 && job.msaa_samples != 1 && job.msaa_samples != 2 && job.msaa_samples != 4)
    throw Error("msaa " + std::to_string(job.msaa_samples) + ": 1, 2 or 4 samples per pixel (0: by output)");
  if (!png && video_format_of(job.output) != VideoFormat::Gif && (job.size.width % 2 || job.size.height % 2))
    throw Error("cannot write " + job.output + ": MP4/WebM need an even width and height");
}

// Video: one sample and the edge filter (half a 4-sample frame's cost on llvmpipe, bench R1).
// Pictures: 4 samples, whose edges stay smoother at small sizes (contact-sheet tiles); a still's
// speed does not matter.
Antialiasing job_antialiasing(const RenderJob& job) {
  const int samples = job.msaa_samples != 0 ? job.msaa_samples : ends_with_png(job.output) ? 4 : 1;
  return samples == 1 && job.edge_filter ? Antialiasing::EdgeFilter : antialiasing_for_samples(samples);
}

int frame_count(float seconds, int fps) {
  return std::max(1, static_cast<int>(std::floor(seconds * static_cast<float>(fps) + 1e-3f)) + 1);
}

std::vector<View> job_views(const RenderJob& job, const FramingBox& box, int width, int height, const FramingBox* follow) {
  std::vector<View> views;
  if (job.orbit) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    Orbit orbit = *job.orbit;
    if (job.orbit_about_body) orbit.target = preset_orbit(CameraPreset::Front, box, aspect).target;
    views.push_back({orbit_camera(orbit, aspect), {0, 0, width, height}});
    return views;
  }
  const std::vector<Viewport> panes = split_viewports(static_cast<int>(job.cameras.size()), width, height);
  for (std::size_t i = 0; i < panes.size(); ++i) {
    const float aspect = static_cast<float>(panes[i].width) / static_cast<float>(std::max(1, panes[i].height));
    const FramingBox& framed = follow && job.cameras[i] == CameraPreset::Follow ? *follow : box;
    views.push_back({preset_camera(job.cameras[i], framed, aspect), panes[i]});
  }
  return views;
}

namespace {

// The framing of a subject for a job: the clip-wide box, and per frame at `fps` the follow box
// when a follow camera is asked for.
struct JobFraming {
  FramingBox box;
  std::vector<FramingBox> follow;
  float fps = 30.0f;
  JobFraming(const RenderSubject& subject, const RenderJob& job, float frame_rate, int frames)
      : box(framing_box(subject.mesh, subject.skeleton, subject.clip ? &*subject.clip : nullptr)), fps(frame_rate) {
    const bool follows = !job.orbit && std::find(job.cameras.begin(), job.cameras.end(), CameraPreset::Follow) != job.cameras.end();
    if (follows && subject.clip) follow = follow_framing(box, subject.skeleton, *subject.clip, fps, frames);
  }
  const FramingBox* at(float t) const {
    if (follow.empty()) return nullptr;
    const long i = std::lround(t * fps);
    return &follow[static_cast<std::size_t>(std::clamp<long>(i, 0, static_cast<long>(follow.size()) - 1))];
  }
};

}  // namespace

std::vector<PinholeCamera> job_pinhole_cameras(const RenderSubject& subject, const RenderJob& job, float fps, int frames) {
  RenderJob single = job;
  if (!single.orbit) single.cameras.resize(1);
  const JobFraming framing(subject, single, fps, frames);
  std::vector<PinholeCamera> cameras;
  for (int f = 0; f < (framing.follow.empty() ? 1 : frames); ++f) {
    const Camera camera =
        job_views(single, framing.box, job.size.width, job.size.height, framing.at(static_cast<float>(f) / fps)).at(0).camera;
    if (camera.orthographic)
      throw Error("the " + std::string(preset_name(single.cameras.at(0))) +
                  " camera is orthographic; joints are projected through a perspective camera (front, side, three-quarter, follow)");
    PinholeCamera pinhole;
    pinhole.position = camera.eye;
    pinhole.target = camera.target;
    pinhole.vertical_fov = 2.0f * std::atan(1.0f / camera.projection[1][1]);
    pinhole.width = job.size.width;
    pinhole.height = job.size.height;
    cameras.push_back(pinhole);
  }
  return cameras;
}

RenderReport render_to_file(const RenderSubject& subject, const RenderJob& job, const RenderMonitor& monitor) {
  validate(job);
  Animator animator(subject);
  const bool png = ends_with_png(job.output);
  const float duration = subject.clip ? animator.duration() : job.rest_seconds;
  if (!png) check_output_length(duration, job.fps, job.output);
  // Open the output first: an unwritable path fails before any rendering.
  std::optional<StagedFile> still;
  std::optional<VideoWriter> video;
  if (png) still.emplace(job.output);
  else video.emplace(job.output, job.size.width, job.size.height, job.fps);

  HeadlessGlContext context;
  Renderer renderer(job.look, job_antialiasing(job));
  renderer.upload(subject.mesh);
  renderer.set_occluders(find_occluders(subject.skeleton, subject.mesh));
  RenderReport report;
  report.renderer = context.description();
  Image frame;
  const JobFraming framing(subject, job, static_cast<float>(job.fps), frame_count(duration, job.fps));
  const FramingBox& box = framing.box;

  if (png && job.sheet) {
    const int w = std::max(kMinImageSide, job.size.width / kSheetColumns);
    const int h = std::max(kMinImageSide, job.size.height / kSheetColumns);
    renderer.resize(w, h);
    std::vector<Image> tiles;
    FrameWatch progress(monitor, "rendering sheet", kSheetFrames);
    for (int i = 0; i < kSheetFrames; ++i) {
      progress.before_frame();
      const float t = duration * static_cast<float>(i) / static_cast<float>(kSheetFrames - 1);
      animator.pose_at(t);
      renderer.render(job_views(job, box, w, h, framing.at(t)), animator.skinning(), animator.morph_weights(), job.skinning);
      renderer.read_pixels(frame);
      tiles.push_back(frame);
      progress.done(i + 1);
    }
    write_png(*still, contact_sheet(tiles, kSheetColumns));
    report.frames = kSheetFrames;
    return report;
  }

  renderer.resize(job.size.width, job.size.height);
  if (png) {
    animator.pose_at(job.still_time);
    renderer.render(job_views(job, box, job.size.width, job.size.height, framing.at(job.still_time)), animator.skinning(),
                    animator.morph_weights(), job.skinning);
    renderer.read_pixels(frame);
    write_png(*still, frame);
    report.frames = 1;
    return report;
  }
  const int frames = frame_count(duration, job.fps);
  FrameWatch progress(monitor, "rendering " + job.output, frames);
  EncoderThread encoder(*video);  // frame i is encoded while frame i+1 is drawn
  const std::vector<View> fixed_views = job_views(job, box, job.size.width, job.size.height);
  for (int i = 0; i < frames; ++i) {
    progress.before_frame();
    const float t = static_cast<float>(i) / static_cast<float>(job.fps);
    animator.pose_at(t);
    const FramingBox* follow = framing.at(t);
    renderer.render(follow ? job_views(job, box, job.size.width, job.size.height, follow) : fixed_views, animator.skinning(),
                    animator.morph_weights(), job.skinning);
    renderer.read_pixels(frame);
    encoder.submit(frame);
    progress.done(i + 1);
  }
  encoder.finish();
  report.frames = frames;
  return report;
}

}  // namespace gestura
