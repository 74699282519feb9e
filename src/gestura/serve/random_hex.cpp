#include "gestura/serve/random_hex.hpp"

#include <cstdio>
#include <mutex>
#include <random>

namespace gestura::serve {

std::string random_hex(int words) {
  static std::mutex m;
  static std::mt19937_64 random{std::random_device{}()};
  std::lock_guard lock(m);
  std::string out;
  for (int i = 0; i < words; ++i) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(random()));
    out += text;
  }
  return out;
}

}  // namespace gestura::serve
