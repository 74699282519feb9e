#pragma once
// A video render job as the API accepts it: the JSON body of POST /api/video, checked. The same
// body is the payload a worker reads from the broker's stream, so a worker checks it by the same
// rules (a malformed payload there is dead-lettered with the reason this gives).
//
//   {"text": "hello", "size": "160x90", "fps": 10, "format": "webm"}
#include <string>

#include <nlohmann/json.hpp>

#include "gestura/app/say.hpp"

namespace gestura::serve {

struct VideoJob {
  app::SayRequest say;       // output.output is a placeholder: the runner names the file
  std::string format = "mp4";  // mp4 or webm
  std::string extension() const { return "." + format; }
  std::string content_type() const { return format == "webm" ? "video/webm" : "video/mp4"; }
};

constexpr int kMaxVideoPixels = 1280 * 720;

// Throws AppError naming the field: unknown fields (files and avatar assets are the server's),
// a format other than mp4/webm, text over `max_text` bytes, more than 1280x720 pixels.
VideoJob parse_video_job(const nlohmann::json& body, int max_text);

}  // namespace gestura::serve
