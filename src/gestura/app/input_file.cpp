#include "gestura/app/input_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "gestura/app/error.hpp"
#include "gestura/core/utf8.hpp"

namespace gestura::app {

void require_file(std::string_view field, const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    throw AppError(ErrorCategory::not_found, Place{std::string(field), {path}}, "no such file");
  if (std::filesystem::is_directory(status))
    throw AppError(ErrorCategory::input, Place{std::string(field), {path}}, "is a directory, not a file");
}

std::string read_text_input(std::string_view field, const std::string& path, std::size_t max_bytes) {
  const bool stdin_ = path == "-";
  const std::string name = stdin_ ? "<stdin>" : path;
  if (!stdin_) require_file(field, path);
  std::ifstream file;
  if (!stdin_) {
    file.open(path, std::ios::binary);
    if (!file) throw AppError(ErrorCategory::input, Place{std::string(field), {name}}, "cannot open for reading");
  }
  std::istream& in = stdin_ ? std::cin : file;
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw AppError(ErrorCategory::too_large, Place{std::string(field), {name}},
                     "more than " + std::to_string(max_bytes) + " bytes of text (the limit here)");
  }
  if (in.bad()) throw AppError(ErrorCategory::input, Place{std::string(field), {name}}, "read failed");
  as_field_error(ErrorCategory::input, field, [&] {
    try {
      utf8::validate(text);
    } catch (const Error& e) {
      throw Error(SourceLocation{name}, e.message());
    }
  });
  return text;
}

}  // namespace gestura::app
