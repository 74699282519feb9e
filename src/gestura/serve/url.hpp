#pragma once
// The target of an HTTP request split into a decoded path and query. Malformed escapes, NUL bytes
// and invalid UTF-8 are errors (usage, field "url"): they never reach a handler or the file system.
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace gestura::serve {

// "%41+b" → "A b" when plus_is_space (query values), "A+b" otherwise (paths). Throws AppError (usage).
std::string percent_decode(std::string_view text, bool plus_is_space);

struct Target {
  std::string path;
  std::map<std::string, std::string> query;
};
Target parse_target(std::string_view target);

// RFC 3986 unreserved characters kept, everything else %XX (for Location headers and links).
std::string percent_encode(std::string_view text);

bool valid_utf8(std::string_view text);

}  // namespace gestura::serve
