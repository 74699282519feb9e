#pragma once
// Subcommand registry of the gestura CLI. Each cmd_*.cpp file registers one command with a static
// Registration object; main() dispatches on argv[1].
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gestura::cli {

struct Command {
  std::string name;
  std::string summary;  // one line for `gestura --help`
  std::string usage;    // full text for `gestura NAME --help`
  std::function<int(const std::vector<std::string>& args)> run;  // args exclude the command name
};

std::vector<Command>& registry();

struct Registration {
  explicit Registration(Command command) { registry().push_back(std::move(command)); }
};

// Small argument helpers shared by commands.
bool wants_help(const std::vector<std::string>& args);
// Throws gestura::Error("bad flag ...") when the flag's value is missing.
std::string flag_value(const std::vector<std::string>& args, std::size_t& i);

}  // namespace gestura::cli
