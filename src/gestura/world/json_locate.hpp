#pragma once
// Where a JSON pointer's value starts in the JSON text (1-based line and column), so errors about a
// value read from a file can name its place like a parser error does. nlohmann::json keeps no source
// positions; this walks the text once more along the pointer's path.
#include <string>
#include <string_view>

#include "gestura/core/error.hpp"

namespace gestura {

class JsonLocator {
 public:
  JsonLocator() = default;
  JsonLocator(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)) {}

  // The place of the value at `pointer` ("/objects/2/size"); the deepest existing prefix when the
  // pointer goes further than the text (a missing member is reported at its object). Line 0 when
  // there is no text.
  SourceLocation locate(std::string_view pointer) const;

  // An error at the pointer's place whose message starts with the pointer:
  // "room.json:14:17: /objects/2/size: sizes must be positive".
  [[noreturn]] void fail(std::string_view pointer, const std::string& message) const;

  const std::string& file() const { return file_; }

 private:
  std::string text_;
  std::string file_;
};

// A JSON syntax error from nlohmann (byte offset) as a located gestura::Error.
[[noreturn]] void throw_json_syntax_error(std::string_view text, const std::string& file, std::size_t byte,
                                          const std::string& what);

}  // namespace gestura
