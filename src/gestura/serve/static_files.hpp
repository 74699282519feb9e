#pragma once
// The web page's files: a GET path mapped to a file under the web root, never outside it (no "..",
// no hidden files, symbolic links resolved and checked), with its MIME type. "/" is index.html, a
// folder its index.html. Three.js comes from the root's node_modules (served at /node_modules/...).
#include <filesystem>
#include <optional>
#include <string>

#include "gestura/serve/message.hpp"

namespace gestura::serve {

// The file `url_path` names under `root` (already canonical), or nothing when it is outside the
// root, hidden, missing or not a regular file.
std::optional<std::filesystem::path> resolve_static(const std::filesystem::path& root, const std::string& url_path);

std::string mime_type(const std::filesystem::path& file);

// 200 with the file (streamed by the adapter), 304 when the ETag matches, 404 otherwise.
ApiResponse static_file(const std::filesystem::path& root, const ApiRequest& request);

}  // namespace gestura::serve
