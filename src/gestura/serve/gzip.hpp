#pragma once
// Content-Encoding: gzip for clients that accept it (every browser): JSON, scripts and glTF shrink
// to a third or less. Files are compressed once and kept (keyed by path and ETag) up to a bound.
#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

namespace gestura::serve {

// gzip (RFC 1952) of `data` with zlib; throws std::runtime_error when zlib fails.
std::string gzip(std::string_view data);

// Whether a body of this type is worth compressing (text, JSON, JavaScript, glTF; not video).
bool compressible(std::string_view content_type);
// Whether an Accept-Encoding header lists gzip (without q=0).
bool accepts_gzip(std::string_view accept_encoding);

class GzipCache {
 public:
  explicit GzipCache(std::size_t max_bytes = 64u << 20) : max_bytes_(max_bytes) {}
  // The gzip of `data`, computed once per key.
  std::string get(const std::string& key, std::string_view data);

 private:
  std::mutex mutex_;
  std::map<std::string, std::string> entries_;
  std::size_t bytes_ = 0, max_bytes_;
};

}  // namespace gestura::serve
