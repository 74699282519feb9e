#pragma once
// The one error model of the command layer. Every failure a request can meet is reported as a
// category, a message and a place; adapters only translate:
//
//   category      meaning                                                   exit  HTTP
//   usage         the request itself is wrong: unknown or missing field,     2     400
//                 a value out of range, fields that do not go together
//   input         an input (file, notation, text) cannot be read or used;   1     422
//                 the place names the file:line:col or symbol
//   not_found     a named thing does not exist (file, lexicon entry, sign)   1     404
//   conflict      the change collides with what is stored                    1     409
//   too_large     a documented limit is exceeded (text, frames, sizes)       1     413
//   output        the result could not be written (unwritable, disk full)    1     500
//   cancelled     the caller stopped a long job                              130   499
//   internal      anything else (a bug)                                      1     500
//
// The CLI prints "gestura CMD: PLACE: MESSAGE", where a request field is shown as the flag or
// argument that sets it; the server answers {"error": {category, field, file, line, column,
// symbol, message}} with the HTTP status.
#include <exception>
#include <string>
#include <string_view>

#include "gestura/core/error.hpp"

namespace gestura::app {

enum class ErrorCategory { usage, input, not_found, conflict, too_large, output, cancelled, internal };

std::string_view to_string(ErrorCategory category);
int exit_code(ErrorCategory category);
int http_status(ErrorCategory category);

// Where a problem is: a field of the request (its JSON key, e.g. "fps"), a place inside an input
// (file:line:col, symbol index), or both.
struct Place {
  std::string field;
  SourceLocation source;

  bool empty() const { return field.empty() && source.to_string().empty(); }
};

// An error raised by the command layer with its category. what() is "field: place: message".
class AppError : public Error {
 public:
  AppError(ErrorCategory category, Place place, const std::string& message);
  AppError(ErrorCategory category, const std::string& message) : AppError(category, Place{}, message) {}

  ErrorCategory category() const noexcept { return category_; }
  const Place& place() const noexcept { return place_; }
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  ErrorCategory category_;
  Place place_;
  std::string what_;
};

// Shorthands for the common cases.
[[noreturn]] void usage_error(std::string_view field, const std::string& message);
[[noreturn]] void not_found(std::string_view field, const std::string& message);

// Any exception as the error model sees it. AppError keeps its own category; gestura::Cancelled is
// cancelled; other gestura::Error are input errors at their place; std::bad_alloc is too_large;
// everything else is internal.
struct ErrorReport {
  ErrorCategory category = ErrorCategory::internal;
  Place place;
  std::string message;

  int exit_code() const { return app::exit_code(category); }
  int http_status() const { return app::http_status(category); }
};

ErrorReport classify(const std::exception& e);
// The exception being handled (call inside a catch block).
ErrorReport classify_current();

// Runs `body`; an input error thrown inside (gestura::Error without a category) becomes `category`
// at `field`. For library calls whose failures are really about one request field.
template <class F>
decltype(auto) as_field_error(ErrorCategory category, std::string_view field, F&& body) {
  try {
    return body();
  } catch (const AppError&) {
    throw;
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    throw AppError(category, Place{std::string(field), e.where()}, e.message());
  }
}

}  // namespace gestura::app
