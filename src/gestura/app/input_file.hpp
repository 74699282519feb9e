#pragma once
// Inputs named by a request field: files that must exist, and text that comes from a file or, for
// "-", from standard input (so text of any length can be passed, not only what fits an argument).
#include <cstddef>
#include <string>
#include <string_view>

namespace gestura::app {

// The most text read from one file or standard input (commands have their own, smaller limits).
inline constexpr std::size_t kMaxTextInputBytes = 64u * 1024u * 1024u;

// not_found at `field` when `path` does not exist, input when it is not a regular file.
void require_file(std::string_view field, const std::string& path);

// The whole of `path` ("-": standard input) as text. Throws AppError: not_found for a missing file,
// too_large past `max_bytes` (naming the limit), input for an unreadable file or text that is not
// UTF-8 (naming the byte).
std::string read_text_input(std::string_view field, const std::string& path, std::size_t max_bytes);

}  // namespace gestura::app
