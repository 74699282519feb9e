#include "gestura/serve/api_error.hpp"

#include <nlohmann/json.hpp>

namespace gestura::serve {

ApiResponse error_response(const app::ErrorReport& report) {
  nlohmann::json e{{"code", report.http_status()}, {"category", app::to_string(report.category)}, {"message", report.message}};
  if (!report.place.field.empty()) e["field"] = report.place.field;
  const SourceLocation& s = report.place.source;
  // A file path inside the server would tell the client nothing it sent; keep only the name.
  if (!s.file.empty()) e["file"] = s.file.substr(s.file.find_last_of('/') + 1);
  if (s.line > 0) e["line"] = s.line;
  if (s.column > 0) e["column"] = s.column;
  if (s.index >= 0) e["symbol"] = s.index;
  // A message may quote the client's bytes (a parse error's token): invalid UTF-8 is replaced.
  return ApiResponse::json(report.http_status(), nlohmann::json{{"error", e}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

ApiResponse current_error_response() { return error_response(app::classify_current()); }

ApiResponse error_response(int status, const std::string& category, const std::string& message, const std::string& field) {
  nlohmann::json e{{"code", status}, {"category", category}, {"message", message}};
  if (!field.empty()) e["field"] = field;
  return ApiResponse::json(status, nlohmann::json{{"error", e}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

}  // namespace gestura::serve
