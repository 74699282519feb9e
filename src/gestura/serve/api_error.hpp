#pragma once
// Errors as the API answers them: the command layer's error model (app/error.hpp) as JSON with its
// HTTP status, plus the few failures only a server has (no such route, wrong method, busy, timed out).
//
//   {"error": {"code": 422, "category": "input", "message": "...", "field": "hamnosys",
//              "file": ..., "line": ..., "column": ..., "symbol": ...}}   (place keys only when known)
#include <string>

#include "gestura/app/error.hpp"
#include "gestura/serve/message.hpp"

namespace gestura::serve {

// The response for a classified error of the command layer.
ApiResponse error_response(const app::ErrorReport& report);
// The response for the exception being handled (call inside a catch block).
ApiResponse current_error_response();
// A server-level failure: status with a category of its own ("not_found", "method", "busy",
// "timeout", "unsupported_media_type", "usage").
ApiResponse error_response(int status, const std::string& category, const std::string& message,
                           const std::string& field = {});

}  // namespace gestura::serve
