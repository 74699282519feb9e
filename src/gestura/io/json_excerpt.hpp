#pragma once
// A JSON value as an error message quotes it. Numbers, literals and strings (cut to 40 bytes) are
// written as they are; arrays and objects only by kind and size: dumping them recurses as deep as
// they nest, and a hostile file nests deeply enough to overflow the stack (a glTF node whose child
// was an array nested 200,000 deep crashed `gestura convert`).
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace gestura {

std::string json_excerpt(const nlohmann::json& value);

}  // namespace gestura
