#pragma once
// Which look a request performs on. A look is a built-in look of the generated avatar
// (`gestura avatar looks`); a client never names an avatar file of the server's.
#include <string>

#include <nlohmann/json.hpp>

namespace gestura::serve {

// Takes "look" (or "avatar", the command line's name for it) out of a JSON body and returns it;
// "default" when absent. Throws a usage AppError naming the key for a non-string or unknown look.
std::string take_look(nlohmann::json& body);

}  // namespace gestura::serve
