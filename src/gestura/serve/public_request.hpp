#pragma once
// A request of the command layer as the API exposes it: only the listed fields. The others (files
// to read or write, avatar assets, lexicon paths) are the server's to choose, so a client can name
// none of them; JSON naming one is an unknown field (400) like any other.
//
//   struct SayFields { static constexpr std::array names{"text", "lang", "speed"}; };
//   auto say = request_from_json<Public<app::SayRequest, SayFields>>(body).request;
#include <algorithm>
#include <string_view>

#include "gestura/app/fields.hpp"

namespace gestura::serve {

template <class R, class Allowed>
struct Public {
  R request;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    R::fields(self.request, [&](auto& value, const app::FieldInfo& field) {
      if (std::find(Allowed::names.begin(), Allowed::names.end(), std::string_view(field.name)) != Allowed::names.end())
        visit(value, field);
    });
  }
};

}  // namespace gestura::serve
