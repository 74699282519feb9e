// gestura mouth WORD — the phonemes eSpeak NG gives a word and the face channels of its mouthing
// (app/mouth.hpp).
#include <cstdio>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "gestura/app/mouth.hpp"

namespace gestura::cli {
namespace {

Invocation prepare() {
  auto request = std::make_shared<app::MouthRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  invocation.run = [request](const app::RunContext& context) {
    const app::MouthResult r = app::run(*request, context);
    std::cout << "phonemes:";
    for (const auto& p : r.phonemes)
      std::cout << ' ' << (p.stress == face::Stress::primary ? "'" : p.stress == face::Stress::secondary ? "," : "") << p.symbol;
    std::cout << '\n';
    const nlohmann::json result = app::to_json(r);
    for (const auto& channel : result.at("channels")) {
      char line[128];
      std::snprintf(line, sizeof line, "%-12s peak %.2f at %.3f s (%zu keys)",
                    channel.at("name").get<std::string>().c_str(), channel.at("peak").get<double>(),
                    channel.at("at").get<double>(), channel.at("keys").get<std::size_t>());
      std::cout << line << '\n';
    }
    return 0;
  };
  return invocation;
}

const Registration reg{{"mouth", "phonemes and mouthing channels of a word",
                        "Phonemizes WORD with eSpeak NG (en-us, ASCII mnemonics, ' = primary and , = secondary stress)\n"
                        "and prints the mouthing channels it gives over a sign lasting from --start to --end seconds:\n"
                        "for every channel its peak weight and when it is reached, in order of first use.",
                        prepare}};

}  // namespace
}  // namespace gestura::cli
