#pragma once
// Internal to the MakeHuman readers: whole-file reading and JSON parsing with error places.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"

namespace gestura::makehuman_detail {

// The whole file; gestura::Error if it cannot be opened or exceeds `max_bytes`.
std::string read_file(const std::string& path, std::size_t max_bytes = std::size_t{256} << 20);

// Parses JSON; a syntax error becomes gestura::Error at name:line:column.
nlohmann::json parse_json(std::string_view text, const std::string& name);

// An error about a JSON field: "name: field 'bones.wrist.L.parent': message".
[[noreturn]] void field_error(const std::string& name, const std::string& field, const std::string& message);

// `object[key]` checked to exist with the expected kind.
const nlohmann::json& member(const nlohmann::json& object, const char* key, nlohmann::json::value_t kind,
                             const std::string& name, const std::string& field);

}  // namespace gestura::makehuman_detail
