#include "gestura/app/render.hpp"

#include "gestura/render/look.hpp"

namespace gestura::app {

RenderJob render_job(const RenderRequest& request) {
  RenderJob job = app::render_job(request.output, request.time);
  if (request.orbit) {
    Orbit orbit;
    orbit.yaw = deg(request.orbit->yaw_degrees);
    orbit.pitch = deg(request.orbit->pitch_degrees);
    orbit.distance = request.orbit->distance;
    job.orbit_about_body = !request.orbit->target;
    if (request.orbit->target) orbit.target = *request.orbit->target;
    job.orbit = orbit;
  }
  if (request.background) job.look.background = request.background->rgb;
  for (const std::string& setting : request.color)
    as_field_error(ErrorCategory::usage, "color", [&] { apply_color_setting(job.look, setting); });
  job.rest_seconds = request.seconds;
  job.msaa_samples = request.msaa.value_or(0);
  job.skinning = request.cpu_skinning ? SkinningDevice::Cpu : SkinningDevice::Gpu;
  return job;
}

void validate(const RenderRequest& request) {
  check_fields(request);
  validate(request.subject);
  if (request.msaa == 3) usage_error("msaa", "3 is not 1, 2 or 4");
  if (request.output.output.empty()) usage_error("output", "missing (.png, .gif, .mp4 or .webm)");
  if (motion_file_kind(request.output.output) != MotionFileKind::Pictures)
    usage_error("output", request.output.output + ": render writes pictures: .png, .gif, .mp4 or .webm");
  validate(request.output, true);
  as_field_error(ErrorCategory::usage, "output", [&] { validate(render_job(request)); });
}

RenderResult run(const RenderRequest& request, const RunContext& context) {
  validate(request);
  const RenderJob job = render_job(request);
  LoadedSubject loaded = load_subject(request.subject, {}, context);
  RenderResult result;
  result.notices = std::move(loaded.notices);
  result.report = as_field_error(ErrorCategory::output, "output", [&] {
    return render_to_file(loaded.subject, job, render_monitor(context, "rendering " + job.output));
  });
  result.written = job.output;
  return result;
}

nlohmann::json to_json(const RenderResult& result) {
  return {{"frames", result.report.frames}, {"renderer", result.report.renderer}, {"written", result.written}};
}

void validate(const ViewRequest& request) {
  check_fields(request);
  validate(request.subject, request.extras);
  if (request.camera.size() != 1) usage_error("camera", "the viewer starts with one camera");
}

LoadedSubject run(const ViewRequest& request, const RunContext& context) {
  validate(request);
  return load_subject(request.subject, request.extras, context);
}

}  // namespace gestura::app
