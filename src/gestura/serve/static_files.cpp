#include "gestura/serve/static_files.hpp"

#include <algorithm>
#include <map>
#include <system_error>

#include "gestura/serve/api_error.hpp"
#include "gestura/serve/router.hpp"

namespace gestura::serve {
namespace fs = std::filesystem;

std::optional<fs::path> resolve_static(const fs::path& root, const std::string& url_path) {
  fs::path relative;
  for (const std::string& part : split_path(url_path)) {
    // No parent steps, no hidden files (.git, .env), no backslashes a Windows-minded client sends.
    if (part == ".." || part.front() == '.' || part.find('\\') != std::string::npos) return std::nullopt;
    relative /= part;
  }
  std::error_code ec;
  fs::path file = root / relative;
  if (fs::is_directory(file, ec)) file /= "index.html";
  const fs::path real = fs::canonical(file, ec);
  if (ec || !fs::is_regular_file(real, ec)) return std::nullopt;
  // A symbolic link inside the root must not lead out of it.
  const auto [end, _] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
  if (end != root.end()) return std::nullopt;
  return real;
}

std::string mime_type(const fs::path& file) {
  static const std::map<std::string, std::string> types{
      {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"}, {".css", "text/css; charset=utf-8"},
      {".json", "application/json"}, {".svg", "image/svg+xml"}, {".png", "image/png"},
      {".ico", "image/x-icon"}, {".glb", "model/gltf-binary"}, {".wasm", "application/wasm"},
      {".txt", "text/plain; charset=utf-8"}, {".md", "text/plain; charset=utf-8"}, {".map", "application/json"}};
  const auto it = types.find(file.extension().string());
  return it == types.end() ? "application/octet-stream" : it->second;
}

ApiResponse static_file(const fs::path& root, const ApiRequest& request) {
  const std::optional<fs::path> file = resolve_static(root, request.path);
  if (!file) return error_response(404, "not_found", "no file " + request.path);
  std::error_code ec;
  const auto size = fs::file_size(*file, ec);
  const auto time = fs::last_write_time(*file, ec);
  const std::string etag = "\"" + std::to_string(size) + "-" + std::to_string(time.time_since_epoch().count()) + "\"";
  ApiResponse r;
  r.headers.emplace_back("ETag", etag);
  r.headers.emplace_back("Cache-Control", "no-cache");  // revalidate: cheap 304s, never stale code
  if (request.if_none_match == etag) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  r.content_type = mime_type(*file);
  r.file = file->string();
  return r;
}

}  // namespace gestura::serve
