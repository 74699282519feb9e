#include "gestura/serve/gzip.hpp"

#include <stdexcept>
#include <zlib.h>

namespace gestura::serve {

std::string gzip(std::string_view data) {
  z_stream z{};
  // 15 + 16: a gzip header and trailer around the deflate stream.
  if (deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("zlib: cannot start");
  std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("zlib: cannot compress");
  return out;
}

bool compressible(std::string_view type) {
  return type.starts_with("text/") || type.starts_with("application/json") || type.starts_with("model/gltf") ||
         type.starts_with("image/svg") || type.starts_with("application/wasm");
}

bool accepts_gzip(std::string_view header) {
  const std::size_t p = header.find("gzip");
  if (p == std::string_view::npos) return false;
  const std::string_view rest = header.substr(p + 4, 8);
  return rest.find("q=0") == std::string_view::npos || rest.find("q=0.") != std::string_view::npos;
}

std::string GzipCache::get(const std::string& key, std::string_view data) {
  {
    std::lock_guard lock(mutex_);
    if (const auto it = entries_.find(key); it != entries_.end()) return it->second;
  }
  std::string packed = gzip(data);
  std::lock_guard lock(mutex_);
  if (bytes_ + packed.size() > max_bytes_) entries_.clear(), bytes_ = 0;  // rare: files change or many versions
  bytes_ += packed.size();
  entries_.emplace(key, packed);
  return packed;
}

}  // namespace gestura::serve
