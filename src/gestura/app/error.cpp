#include "gestura/app/error.hpp"

#include <new>

namespace gestura::app {
namespace {

std::string compose(const Place& place, const std::string& message) {
  std::string out = place.field;
  const std::string source = place.source.to_string();
  if (!source.empty()) out += (out.empty() ? "" : ": ") + source;
  return out.empty() ? message : out + ": " + message;
}

}  // namespace

std::string_view to_string(ErrorCategory category) {
  switch (category) {
    case ErrorCategory::usage: return "usage";
    case ErrorCategory::input: return "input";
    case ErrorCategory::not_found: return "not_found";
    case ErrorCategory::conflict: return "conflict";
    case ErrorCategory::too_large: return "too_large";
    case ErrorCategory::output: return "output";
    case ErrorCategory::cancelled: return "cancelled";
    case ErrorCategory::internal: return "internal";
  }
  return "internal";
}

int exit_code(ErrorCategory category) {
  switch (category) {
    case ErrorCategory::usage: return 2;
    case ErrorCategory::cancelled: return 130;  // the shell's code for a job stopped by SIGINT
    default: return 1;
  }
}

int http_status(ErrorCategory category) {
  switch (category) {
    case ErrorCategory::usage: return 400;
    case ErrorCategory::input: return 422;
    case ErrorCategory::not_found: return 404;
    case ErrorCategory::conflict: return 409;
    case ErrorCategory::too_large: return 413;
    case ErrorCategory::cancelled: return 499;  // client closed request (nginx's convention)
    case ErrorCategory::output:
    case ErrorCategory::internal: return 500;
  }
  return 500;
}

AppError::AppError(ErrorCategory category, Place place, const std::string& message)
    : Error(place.source, message), category_(category), place_(std::move(place)), what_(compose(place_, message)) {}

void usage_error(std::string_view field, const std::string& message) {
  throw AppError(ErrorCategory::usage, Place{std::string(field), {}}, message);
}

void not_found(std::string_view field, const std::string& message) {
  throw AppError(ErrorCategory::not_found, Place{std::string(field), {}}, message);
}

ErrorReport classify(const std::exception& e) {
  if (const auto* app = dynamic_cast<const AppError*>(&e)) return {app->category(), app->place(), app->message()};
  if (const auto* stop = dynamic_cast<const Cancelled*>(&e)) return {ErrorCategory::cancelled, {}, stop->message()};
  if (const auto* error = dynamic_cast<const Error*>(&e)) return {ErrorCategory::input, Place{{}, error->where()}, error->message()};
  if (dynamic_cast<const std::bad_alloc*>(&e)) return {ErrorCategory::too_large, {}, "out of memory: the input is too large"};
  return {ErrorCategory::internal, {}, e.what()};
}

ErrorReport classify_current() {
  try {
    throw;
  } catch (const std::exception& e) {
    return classify(e);
  } catch (...) {
    return {ErrorCategory::internal, {}, "unknown error"};
  }
}

}  // namespace gestura::app
