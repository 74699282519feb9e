#pragma once
// What a client sends as JSON: the body parsed under the server's limits, and the fields each route
// lets a client set (the rest of a request is the server's, see public_request.hpp). Kept apart from
// the handlers so the fuzz target reads bodies exactly as the server does.
#include <array>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gestura::serve {

inline constexpr int kMaxJsonDepth = 32;

// The body as JSON. Throws app::AppError (usage, so 400) naming "body" for malformed JSON, binary
// bodies (invalid UTF-8 is malformed JSON), numbers past a double's range, and nesting deeper than
// kMaxJsonDepth.
nlohmann::json parse_request_json(std::string_view body);

struct SayFields {
  static constexpr std::array<std::string_view, 6> names{"text", "lang", "speed", "mouthing", "nonmanuals", "fps"};
};
struct VideoFields {
  static constexpr std::array<std::string_view, 8> names{"text", "lang", "speed", "mouthing", "nonmanuals", "fps", "size", "camera"};
};
struct SignFields {
  static constexpr std::array<std::string_view, 5> names{"hamnosys", "names", "gloss", "speed", "fps"};
};
struct GlossFields {
  static constexpr std::array<std::string_view, 3> names{"text", "lang", "open"};
};

}  // namespace gestura::serve
