#include "gestura/render/render_job.hpp"

#include <charconv>
#include <cmath>
#include <regex>

#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/encoder_thread.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/progress.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {
namespace {

constexpr int kSheetColumns = 4, kSheetFrames = 16;

bool ends_with_png(const std::string& path) {
  return path.size() >= 4 && (path.compare(path.size() - 4, 4, ".png") == 0 || path.compare(path.size() - 4, 4, ".PNG") == 0);
}

}  // namespace

ImageSize parse_image_size(const std::string& text) {
  static const std::regex pattern("([0-9]{1,6})[xX]([0-9]{1,6})");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) throw Error("bad --size '" + text + "' (expected WIDTHxHEIGHT, e.g. 1280x720)");
  const ImageSize size{std::stoi(m[1]), std::stoi(m[2])};
  for (int side : {size.width, size.height})
    if (side < kMinImageSide || side > kMaxImageSide)
      throw Error("bad --size '" + text + "': each side must be " + std::to_string(kMinImageSide) + ".." +
                  std::to_string(kMaxImageSide) + " pixels");
  if (static_cast<long>(size.width) * size.height > kMaxImagePixels)
    throw Error("bad --size '" + text + "': at most " + std::to_string(kMaxImagePixels) + " pixels in all (e.g. 4096x2304)");
  return size;
}

int parse_fps(const std::string& text) {
  int fps = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), fps);
  if (ec != std::errc() || end != text.data() + text.size() || fps < 1 || fps > kMaxFps)
    throw Error("bad --fps '" + text + "' (a whole number 1.." + std::to_string(kMaxFps) + ")");
  return fps;
}

float parse_seconds(const std::string& text, const std::string& flag) {
  float value = 0.0f;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || value < 0.0f || value > 3600.0f)
    throw Error("bad " + flag + " '" + text + "' (seconds, 0..3600)");
  return value;
}

int parse_msaa(const std::string& text) {
  if (text == "1" || text == "2" || text == "4") return text[0] - '0';
  throw Error("bad --msaa '" + text + "' (1, 2 or 4 samples per pixel)");
}

void validate(const RenderJob& job) {
  if (job.output.empty()) throw Error("no output file (-o OUT.png|.gif|.mp4|.webm)");
  const bool png = ends_with_png(job.output);
  if (!png) video_format_of(job.output);  // throws for unknown extensions
  if (job.sheet && !png) throw Error("--sheet writes a PNG contact sheet; " + job.output + " is not .png");
  parse_image_size(std::to_string(job.size.width) + "x" + std::to_string(job.size.height));
  if (job.fps < 1 || job.fps > kMaxFps) throw Error("bad fps " + std::to_string(job.fps));
  if (job.cameras.empty() && !job.orbit) throw Error("no camera");
  parse_msaa(std::to_string(job.msaa_samples));
  if (!png && video_format_of(job.output) != VideoFormat::Gif && (job.size.width % 2 || job.size.height % 2))
    throw Error("cannot write " + job.output + ": MP4/WebM need an even width and height");
}

int frame_count(float seconds, int fps) {
  return std::max(1, static_cast<int>(std::floor(seconds * static_cast<float>(fps) + 1e-3f)) + 1);
}

std::vector<View> job_views(const RenderJob& job, const FramingBox& box, int width, int height) {
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
    views.push_back({preset_camera(job.cameras[i], box, aspect), panes[i]});
  }
  return views;
}

RenderReport render_to_file(const RenderSubject& subject, const RenderJob& job) {
  validate(job);
  Animator animator(subject);
  const FramingBox box = framing_box(subject.mesh, subject.skeleton);
  const bool png = ends_with_png(job.output);
  const float duration = subject.clip ? animator.duration() : job.rest_seconds;
  if (!png) check_output_length(duration, job.fps, job.output);
  // Open the output first: an unwritable path fails before any rendering.
  std::optional<StagedFile> still;
  std::optional<VideoWriter> video;
  if (png) still.emplace(job.output);
  else video.emplace(job.output, job.size.width, job.size.height, job.fps);

  HeadlessGlContext context;
  Renderer renderer(job.look, job.msaa_samples);
  renderer.upload(subject.mesh);
  RenderReport report;
  report.renderer = context.description();
  Image frame;

  if (png && job.sheet) {
    const int w = std::max(kMinImageSide, job.size.width / kSheetColumns);
    const int h = std::max(kMinImageSide, job.size.height / kSheetColumns);
    renderer.resize(w, h);
    const std::vector<View> views = job_views(job, box, w, h);
    std::vector<Image> tiles;
    Progress progress("rendering sheet", kSheetFrames);
    for (int i = 0; i < kSheetFrames; ++i) {
      animator.pose_at(duration * static_cast<float>(i) / static_cast<float>(kSheetFrames - 1));
      renderer.render(views, animator.skinning(), animator.morph_weights(), job.skinning);
      renderer.read_pixels(frame);
      tiles.push_back(frame);
      progress.update(i + 1);
    }
    write_png(*still, contact_sheet(tiles, kSheetColumns));
    report.frames = kSheetFrames;
    return report;
  }

  renderer.resize(job.size.width, job.size.height);
  const std::vector<View> views = job_views(job, box, job.size.width, job.size.height);
  if (png) {
    animator.pose_at(job.still_time);
    renderer.render(views, animator.skinning(), animator.morph_weights(), job.skinning);
    renderer.read_pixels(frame);
    write_png(*still, frame);
    report.frames = 1;
    return report;
  }
  const int frames = frame_count(duration, job.fps);
  Progress progress("rendering " + job.output, frames);
  EncoderThread encoder(*video);  // frame i is encoded while frame i+1 is drawn
  for (int i = 0; i < frames; ++i) {
    animator.pose_at(static_cast<float>(i) / static_cast<float>(job.fps));
    renderer.render(views, animator.skinning(), animator.morph_weights(), job.skinning);
    renderer.read_pixels(frame);
    encoder.submit(frame);
    progress.update(i + 1);
  }
  encoder.finish();
  report.frames = frames;
  return report;
}

}  // namespace gestura
