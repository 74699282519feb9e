#include "gestura/app/notice.hpp"

namespace gestura::app {

std::string Notice::text() const {
  const std::string place = where.to_string();
  return std::string(level == Level::note ? "note: " : "warning: ") + (place.empty() ? "" : place + ": ") + message;
}

}  // namespace gestura::app
