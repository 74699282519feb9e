#include "gestura/io/makehuman_files.hpp"

#include <fstream>
#include <sstream>

namespace gestura::makehuman_detail {

std::string read_file(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot open file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(SourceLocation{path}, "cannot read file");
  if (static_cast<std::size_t>(size) > max_bytes)
    throw Error(SourceLocation{path}, "file too large (" + std::to_string(size) + " bytes, limit " +
                                          std::to_string(max_bytes) + ")");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(text.data(), size);
  if (!in) throw Error(SourceLocation{path}, "cannot read file");
  return text;
}

nlohmann::json parse_json(std::string_view text, const std::string& name) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    SourceLocation where{name, 1, 1};
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++where.line;
        where.column = 1;
      } else {
        ++where.column;
      }
    }
    std::string message = e.what();
    const std::size_t colon = message.rfind(": ");  // drop nlohmann's "[json.exception…] parse error at…"
    throw Error(where, "invalid JSON: " + (colon == std::string::npos ? message : message.substr(colon + 2)));
  } catch (const nlohmann::json::exception& e) {  // e.g. a number past a double's range
    throw Error(SourceLocation{name}, std::string("invalid JSON: ") + e.what());
  }
}

void field_error(const std::string& name, const std::string& field, const std::string& message) {
  throw Error(SourceLocation{name}, "field '" + field + "': " + message);
}

const nlohmann::json& member(const nlohmann::json& object, const char* key, nlohmann::json::value_t kind,
                             const std::string& name, const std::string& field) {
  const std::string here = field.empty() ? std::string(key) : field + "." + key;
  if (!object.is_object()) field_error(name, field.empty() ? "(top level)" : field, "expected an object");
  const auto it = object.find(key);
  if (it == object.end()) field_error(name, here, "missing");
  const bool ok = kind == nlohmann::json::value_t::number_float ? it->is_number() : it->type() == kind;
  if (!ok) field_error(name, here, std::string("expected ") + nlohmann::json(kind).type_name());
  return *it;
}

}  // namespace gestura::makehuman_detail
