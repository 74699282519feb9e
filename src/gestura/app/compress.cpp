#include "gestura/app/compress.hpp"

#include <chrono>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/app/motion_files.hpp"
#include "gestura/compress/compressed_clip.hpp"
#include "gestura/core/file_extension.hpp"

namespace gestura::app {
namespace {

struct Input {
  Skeleton skeleton;
  Clip clip;
  float rate = 30.0f;  // the source's own frame rate
};

// "synthetic" or "synthetic:SECONDS" names the test motion; anything else is a file.
bool is_synthetic(const std::string& input) { return input == "synthetic" || input.starts_with("synthetic:"); }

Input load_input(const CompressRequest& request) {
  Input in;
  if (is_synthetic(request.input)) {
    float seconds = 15.0f;
    if (request.input.size() > 9)
      seconds = parse_number<float>(std::string_view(request.input).substr(10),
                                    FieldInfo{.name = "input", .min = 0.001, .max = 3600});
    in.skeleton = synthetic_humanoid();
    in.clip = synthetic_clip(in.skeleton, seconds, 30.0f);
    return in;
  }
  MotionFile file = read_motion_file(request.input, {request.scale, request.z_up, request.skeleton}, "input");
  in.skeleton = std::move(file.motion.skeleton);
  in.clip = std::move(file.motion.clip);
  in.rate = 1.0f / file.motion.frame_time;
  return in;
}

}  // namespace

void validate(const CompressRequest& request) {
  check_fields(request);
  if (!is_synthetic(request.input) && !is_motion_file(request.input))
    usage_error("input", request.input + ": expected synthetic[:SECONDS] or a motion file (" + motion_file_extensions() + ")");
}

CompressResult run(const CompressRequest& request, const RunContext&) {
  validate(request);
  const Input in = load_input(request);
  CompressionSettings settings;
  settings.max_error = request.error_cm * 0.01f;
  settings.sample_rate = request.rate.value_or(in.rate);

  CompressResult result;
  const auto t0 = std::chrono::steady_clock::now();
  const CompressedClip compressed = compress(in.clip, in.skeleton, settings, &result.report);
  result.compress_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Pose pose = rest_pose(in.skeleton);
  result.frames = compressed.frame_count();
  const auto t1 = std::chrono::steady_clock::now();
  for (std::uint32_t f = 0; f < result.frames; ++f) compressed.sample(static_cast<float>(f) / compressed.sample_rate(), pose);
  result.decompress_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  result.joints = in.skeleton.size();
  result.rate = compressed.sample_rate();
  result.bound = settings.max_error;
  if (!request.output.empty()) {
    as_field_error(ErrorCategory::output, "output", [&] { save_gcl(request.output, compressed); });
    result.written = request.output;
  }
  return result;
}

nlohmann::json to_json(const CompressResult& r) {
  return {{"joints", r.joints},
          {"frames", r.frames},
          {"rate", r.rate},
          {"bytes", r.report.bytes},
          {"raw_bytes", r.report.raw_bytes},
          {"max_error_m", r.report.max_error},
          {"p99_error_m", r.report.p99_error},
          {"bound_m", r.bound},
          {"within_bound", r.report.within_bound},
          {"passes", r.report.passes},
          {"compress_seconds", r.compress_seconds},
          {"decompress_seconds", r.decompress_seconds},
          {"written", r.written}};
}

void validate(const DecompressRequest& request) {
  check_fields(request);
  if (!has_extension(request.input, ".gcl")) usage_error("input", request.input + ": expected a .gcl file");
}

DecompressResult run(const DecompressRequest& request, const RunContext&) {
  validate(request);
  // Keep the reference's channel layout, so the output reads like the file that was compressed.
  const MotionFile file = read_motion_file(request.input, {request.scale, request.z_up, request.skeleton}, "input");
  as_field_error(ErrorCategory::output, "output", [&] { save_bvh(request.output, file.motion); });
  return {file.motion.skeleton.size(), static_cast<std::uint32_t>(file.motion.frame_count), 1.0f / file.motion.frame_time,
          request.output};
}

nlohmann::json to_json(const DecompressResult& r) {
  return {{"joints", r.joints}, {"frames", r.frames}, {"rate", r.rate}, {"written", r.written}};
}

}  // namespace gestura::app
