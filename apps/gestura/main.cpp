// gestura — a virtual human that signs. Dispatches to the registered subcommands.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/staged_file.hpp"

namespace gestura::cli {

std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

bool wants_help(const std::vector<std::string>& args) {
  return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

std::string flag_value(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw Error("flag " + args[i] + " needs a value");
  return args[++i];
}

static void print_help() {
  std::cout << "gestura — a virtual human that signs\n\nusage: gestura COMMAND [ARGS]   (gestura COMMAND --help for details)\n\ncommands:\n";
  auto commands = registry();
  std::sort(commands.begin(), commands.end(), [](auto& a, auto& b) { return a.name < b.name; });
  for (const Command& c : commands) std::printf("  %-12s %s\n", c.name.c_str(), c.summary.c_str());
}

}  // namespace gestura::cli

int main(int argc, char** argv) {
  using namespace gestura::cli;
  if (argc < 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h" ||
      std::string_view(argv[1]) == "help") {
    print_help();
    return argc < 2 ? 2 : 0;
  }
  gestura::remove_staged_files_on_signals();  // Ctrl-C or SIGTERM leaves no temporary output behind
  const std::string name = argv[1];
  std::vector<std::string> args(argv + 2, argv + argc);
  for (const Command& c : registry()) {
    if (c.name != name) continue;
    if (wants_help(args)) {
      std::cout << c.usage << "\n";
      return 0;
    }
    try {
      return c.run(args);
    } catch (const std::exception& e) {
      std::cerr << "gestura " << name << ": " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "gestura: unknown command '" << name << "' (see gestura --help)\n";
  return 2;
}
