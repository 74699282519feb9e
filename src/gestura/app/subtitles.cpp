#include "gestura/app/subtitles.hpp"

#include "gestura/app/input_file.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/core/file_extension.hpp"
#include "gestura/io/subtitles.hpp"

namespace gestura::app {
namespace {

RenderJob job_of(const SubtitlesRequest& request) {
  RenderJob job;
  job.output = request.output;
  job.size = request.picture.size;
  job.fps = request.picture.rate();
  job.cameras = request.picture.camera;
  return job;
}

Subtitles read_input(const std::string& input) {
  if (input != "-") {
    require_file("input", input);
    return read_subtitles(input);
  }
  const std::string text = read_text_input("input", "-", kMaxSubtitleBytes);
  const std::size_t body = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // a UTF-8 byte order mark
  const bool vtt = text.compare(body, 6, "WEBVTT") == 0;
  return parse_subtitles(text, vtt ? SubtitleFormat::WebVtt : SubtitleFormat::Srt, "<stdin>");
}

}  // namespace

void validate(const SubtitlesRequest& request) {
  check_fields(request);
  if (request.input != "-" && !has_extension(request.input, ".srt") && !has_extension(request.input, ".vtt"))
    usage_error("input", request.input + ": subtitles are .srt or .vtt files (or '-' for standard input)");
  if (!has_extension(request.output, ".mp4") && !has_extension(request.output, ".webm"))
    usage_error("output", request.output + ": the output must be a .mp4 or .webm video");
  validate(request.avatar);
  as_field_error(ErrorCategory::usage, "output", [&] { validate(job_of(request)); });
}

SubtitlesResult run(const SubtitlesRequest& request, const RunContext& context) {
  validate(request);  // before the slow parts
  const Subtitles subs = read_input(request.input);
  const std::string source = request.input == "-" ? "<stdin>" : request.input;
  SubtitlesResult result;
  for (const std::string& n : subs.notes) result.notices.push_back(note(n));
  if (subs.cues.empty()) throw AppError(ErrorCategory::input, Place{"input", {source}}, "no subtitle cues");

  RunWorkspace workspace(context);
  const Avatar& avatar = workspace->avatar(request.avatar);
  const Signer& signer = workspace->signer(request.avatar);
  SayOptions say;
  say.fps = static_cast<float>(request.picture.rate());
  int signed_cues = 0;
  const SignFunction sign = [&](std::string_view text, float speed) {
    context.check_stop();
    context.report("signing " + source, ++signed_cues, static_cast<int>(subs.cues.size()));
    SayOptions options = say;
    options.speed = speed;
    return signer.say(text, options);
  };
  SubtitleFitOptions fit;
  fit.max_speed = request.max_speed;
  fit.slack = request.slack;
  try {
    result.track = fit_subtitles(subs.cues, sign, avatar.skeleton, fit);
  } catch (const AppError&) {
    throw;
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {  // a cue the signer refused: name the file too
    if (e.where().line > 0 && e.where().file.empty())
      throw AppError(ErrorCategory::input, Place{"input", {source, e.where().line, 0, -1}}, e.message());
    throw;
  }
  const RenderJob job = job_of(request);
  result.report = as_field_error(ErrorCategory::output, "output", [&] {
    return render_to_file(RenderSubject{avatar.skeleton, avatar.mesh, result.track.clip}, job,
                          render_monitor(context, "rendering " + job.output));
  });
  result.written = request.output;
  return result;
}

nlohmann::json to_json(const SubtitlesResult& result) {
  nlohmann::json out;
  auto& cues = out["cues"] = nlohmann::json::array();
  for (const FittedCue& c : result.track.cues)
    cues.push_back({{"index", c.index}, {"cue_start", c.cue_start}, {"cue_end", c.cue_end}, {"start", c.start},
                    {"duration", c.duration}, {"speed", c.speed}, {"fit", to_string(c.fit)},
                    {"coarticulated", c.coarticulated}, {"glosses", c.glosses}, {"notes", c.notes}});
  out["duration"] = result.track.clip.duration;
  out["frames"] = result.report.frames;
  out["written"] = result.written;
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const Notice& n : result.notices) notes.push_back(n.text());
  return out;
}

}  // namespace gestura::app
