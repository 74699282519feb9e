#include "gestura/serve/look_choice.hpp"

#include "gestura/app/error.hpp"
#include "gestura/body/avatar_look.hpp"
#include "gestura/serve/room.hpp"

namespace gestura::serve {

std::string take_look(nlohmann::json& body) {
  std::string look = "default";
  if (!body.is_object()) return look;
  for (const char* key : {"avatar", "look"}) {
    if (!body.contains(key)) continue;
    if (!body[key].is_string()) app::usage_error(key, "expected the name of a look (" + look_names() + ")");
    look = body[key].get<std::string>();
    if (!valid_look(look)) app::usage_error(key, "is one of " + look_names() + ", not '" + look + "'");
    body.erase(key);
  }
  return look;
}

}  // namespace gestura::serve
