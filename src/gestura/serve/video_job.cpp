#include "gestura/serve/video_job.hpp"

#include <array>
#include <string_view>

#include "gestura/serve/look_choice.hpp"
#include "gestura/serve/public_request.hpp"
#include "gestura/serve/request_json.hpp"

namespace gestura::serve {

VideoJob parse_video_job(const nlohmann::json& body_in, int max_text) {
  nlohmann::json body = body_in;
  VideoJob job;
  if (body.is_object() && body.contains("format")) {
    if (!body["format"].is_string() || (body["format"] != "mp4" && body["format"] != "webm")) app::usage_error("format", "is mp4 or webm");
    job.format = body["format"].get<std::string>();
    body.erase("format");
  }
  const std::string look = take_look(body);
  Public<app::SayRequest, VideoFields> request;
  app::read_json(body, request);
  job.say = std::move(request.request);
  job.say.avatar.avatar = look;
  if (job.say.text.size() > static_cast<std::size_t>(max_text))
    throw app::AppError(app::ErrorCategory::too_large, app::Place{"text", {}},
                        std::to_string(job.say.text.size()) + " bytes of text; this server signs at most " + std::to_string(max_text) +
                            " bytes per request (split longer text)");
  if (job.say.output.picture.size.width * job.say.output.picture.size.height > kMaxVideoPixels)
    throw app::AppError(app::ErrorCategory::too_large, app::Place{"size", {}}, "videos are at most 1280x720 pixels here");
  job.say.output.output = "job" + job.extension();
  app::validate(job.say);  // every mistake is the request's answer, not a failed job later
  return job;
}

}  // namespace gestura::serve
