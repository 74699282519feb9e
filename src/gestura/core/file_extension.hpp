#pragma once
// A file's extension as formats are chosen by it: lower case with the dot (".mp4" for "Talk.MP4"),
// empty when the last path component has none. One rule for every reader and writer, so `.MP4`,
// `.Bvh` and `.mp4` are the same format everywhere.
#include <string>
#include <string_view>

namespace gestura {

std::string lower_extension(std::string_view path);

// True when `path`'s extension is `ext` (given in lower case with the dot), in any case.
inline bool has_extension(std::string_view path, std::string_view ext) { return lower_extension(path) == ext; }

}  // namespace gestura
