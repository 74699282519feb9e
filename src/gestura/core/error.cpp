#include "gestura/core/error.hpp"

namespace gestura {

std::string SourceLocation::to_string() const {
  std::string out = file;
  if (line > 0) {
    out.append(out.empty() ? "line " : ":").append(std::to_string(line));
    if (column > 0) out.append(":").append(std::to_string(column));
  }
  if (index >= 0) {
    if (!out.empty()) out.append(", ");
    out.append("symbol ").append(std::to_string(index));
  }
  return out;
}

static std::string compose(const SourceLocation& where, const std::string& message) {
  const std::string place = where.to_string();
  return place.empty() ? message : place + ": " + message;
}

Error::Error(const std::string& message) : std::runtime_error(message), message_(message) {}

Error::Error(const SourceLocation& where, const std::string& message)
    : std::runtime_error(compose(where, message)), where_(where), message_(message) {}

}  // namespace gestura
