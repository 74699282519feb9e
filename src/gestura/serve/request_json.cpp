#include "gestura/serve/request_json.hpp"

#include <string>

#include "gestura/app/error.hpp"

namespace gestura::serve {

nlohmann::json parse_request_json(std::string_view body) {
  using nlohmann::json;
  try {
    return json::parse(body, [](int depth, json::parse_event_t, json&) {
      if (depth > kMaxJsonDepth) throw app::AppError(app::ErrorCategory::usage, app::Place{"body", {}}, "the JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      return true;
    });
  } catch (const json::exception& e) {
    // parse_error for syntax and encoding; out_of_range for a number past a double's range
    // ("1e400"), which is as much the client's mistake.
    std::string message = e.what();
    if (const std::size_t p = message.find("] "); p != std::string::npos) message = message.substr(p + 2);
    throw app::AppError(app::ErrorCategory::usage, app::Place{"body", {}}, "not valid JSON: " + message);
  }
}

}  // namespace gestura::serve
