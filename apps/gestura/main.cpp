// gestura — a virtual human that signs. The command line: CLI11 parses, the command layer
// (src/gestura/app) validates and runs, and this file turns errors into one line and an exit code.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "command.hpp"
#include "gestura/app/error.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/app/number.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/progress.hpp"

#ifndef GESTURA_VERSION
#define GESTURA_VERSION "0"
#endif

namespace gestura::cli {

std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

std::string shown_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(static_cast<float>(value)));
  return text;
}

FieldBinding& binding(std::vector<FieldBinding>& fields, std::string_view name) {
  for (FieldBinding& b : fields)
    if (b.info.name == name) return b;
  throw std::logic_error("no field " + std::string(name));
}

void unbind(std::vector<FieldBinding>& fields, std::string_view name) {
  std::erase_if(fields, [&](const FieldBinding& b) { return b.info.name == name; });
}

std::string text_argument(const std::string& text, const std::string& file, std::size_t max_bytes) {
  if (!file.empty()) {
    if (!text.empty()) app::usage_error("file", "give the text as TEXT or with --file, not both");
    return app::read_text_input("file", file, max_bytes);
  }
  if (text == "-") return app::read_text_input("text", "-", max_bytes);
  return text;
}

namespace {

// A field's name on the command line: --shoulder-width for shoulder_width.
std::string flag_name(const app::FieldInfo& info) {
  std::string name(info.name);
  std::replace(name.begin(), name.end(), '_', '-');
  return (info.negated ? "--no-" : "--") + name;
}

// How a field is shown in messages: its flag, or its placeholder when it is an argument.
std::string spelling(const app::FieldInfo& info) {
  return info.positional ? std::string(info.value.empty() ? info.name : info.value) : flag_name(info);
}

// One command as parsed: its CLI11 app, its words ("avatar export") and what it prepared.
struct Prepared {
  CLI::App* app = nullptr;
  std::string words;
  Invocation invocation;
};

void add_bindings(CLI::App& sub, std::vector<FieldBinding>& fields) {
  for (FieldBinding& b : fields) {
    std::string names;
    if (b.info.positional) {
      names = spelling(b.info);
    } else {
      if (b.info.short_flag) names = std::string("-") + b.info.short_flag + ",";
      names += flag_name(b.info);
    }
    // The help line: what it is, its range and its default.
    std::string help = (b.info.negated ? "without " : "") + std::string(b.info.help);
    const std::string range = app::range_text(b.info);
    if (!range.empty()) help += " (" + range + ")";
    if (!b.default_text.empty()) help += "  [" + b.default_text + "]";
    const auto set = b.set;
    CLI::Option* option = nullptr;
    switch (b.shape) {
      case FieldBinding::Shape::flag:
        option = sub.add_flag_callback(names, [set] { set(""); }, help);
        break;
      case FieldBinding::Shape::value:
        option = sub.add_option_function<std::string>(names, [set](const std::string& text) { set(text); }, help);
        option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        break;
      case FieldBinding::Shape::list:
        option = sub.add_option_function<std::vector<std::string>>(
            names, [set](const std::vector<std::string>& items) { for (const std::string& item : items) set(item); }, help);
        break;
    }
    if (b.shape != FieldBinding::Shape::flag && !b.info.positional && !b.info.value.empty())
      option->type_name(std::string(b.info.value));
    if (b.info.positional) option->type_name("");
    if (!b.info.group.empty()) option->group(std::string(b.info.group));
  }
}

void define(CLI::App& parent, const Command& command, const std::string& words, std::vector<std::unique_ptr<Prepared>>& out) {
  CLI::App* sub = parent.add_subcommand(command.name, command.summary);
  if (!command.description.empty()) sub->footer(command.description);
  if (!command.actions.empty()) {
    sub->require_subcommand(1);
    for (const Command& action : command.actions) define(*sub, action, words + " " + action.name, out);
    return;
  }
  auto prepared = std::make_unique<Prepared>();
  prepared->app = sub;
  prepared->words = words;
  prepared->invocation = command.prepare();
  add_bindings(*sub, prepared->invocation.fields);
  out.push_back(std::move(prepared));
}

void print_overview(const std::vector<Command>& commands) {
  std::cout << "gestura " GESTURA_VERSION " — a virtual human that signs\n\n"
               "usage: gestura COMMAND [ARGS]   (gestura COMMAND --help for details; gestura --version)\n\ncommands:\n";
  std::vector<const Command*> sorted;
  for (const Command& c : commands) sorted.push_back(&c);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (const Command* c : sorted) std::printf("  %-12s %s\n", c->name.c_str(), c->summary.c_str());
}

// The error as one line: "gestura CMD: PLACE: MESSAGE", the field shown as the flag that sets it.
int report(const app::ErrorReport& error, const Prepared* command) {
  std::string place;
  if (!error.place.field.empty()) {
    place = error.place.field;
    if (command)
      for (const FieldBinding& b : command->invocation.fields)
        if (b.info.name == error.place.field) place = spelling(b.info);
  }
  const std::string source = error.place.source.to_string();
  if (!source.empty()) place += (place.empty() ? "" : ": ") + source;
  const std::string who = command ? "gestura " + command->words : "gestura";
  std::cerr << who << ": " << (place.empty() ? "" : place + ": ") << error.message;
  if (error.category == app::ErrorCategory::usage && command) std::cerr << " (see " << who << " --help)";
  std::cerr << "\n";
  return error.exit_code();
}

// Progress of long jobs as a bar on a terminal's stderr (silent otherwise).
struct ProgressBar {
  std::optional<Progress> bar;
  std::string stage;

  void operator()(const app::ProgressUpdate& update) {
    if (!bar || update.stage != stage) bar.emplace(update.stage, update.total), stage = update.stage;
    bar->update(update.done);
  }
};

}  // namespace
}  // namespace gestura::cli

int main(int argc, char** argv) {
  using namespace gestura::cli;
  namespace app = gestura::app;
  const std::vector<Command>& commands = registry();
  if (argc < 2 || std::string_view(argv[1]) == "help") {
    print_overview(commands);
    return argc < 2 ? 2 : 0;
  }
  const std::string first = argv[1];
  if (first == "--help" || first == "-h") {
    print_overview(commands);
    return 0;
  }
  const auto command = std::find_if(commands.begin(), commands.end(), [&](const Command& c) { return c.name == first; });
  if (first[0] != '-' && command == commands.end()) {
    std::cerr << "gestura: unknown command '" << first << "' (see gestura --help)\n";
    return 2;
  }
  // A command made of actions (avatar export, lexicon add): name the action that is missing or unknown.
  if (command != commands.end() && !command->actions.empty()) {
    std::string names;
    for (const Command& a : command->actions) names += (names.empty() ? "" : ", ") + a.name;
    const std::string action = argc > 2 ? argv[2] : "";
    const bool known = std::any_of(command->actions.begin(), command->actions.end(), [&](const Command& a) { return a.name == action; });
    if (action.empty() || (!known && action[0] != '-')) {
      std::cerr << "gestura " << first << ": " << (action.empty() ? "missing action" : "unknown action '" + action + "'")
                << " (" << names << "; see gestura " << first << " --help)\n";
      return 2;
    }
  }

  CLI::App cli("gestura — a virtual human that signs", "gestura");
  cli.set_version_flag("--version", "gestura " GESTURA_VERSION);
  cli.require_subcommand(1);
  cli.get_formatter()->column_width(34);
  std::vector<std::unique_ptr<Prepared>> prepared;
  try {
    for (const Command& c : commands) define(cli, c, c.name, prepared);
  } catch (const std::exception& e) {  // two commands claiming one flag: a bug of ours
    std::cerr << "gestura: internal error setting up the command line: " << e.what() << "\n";
    return 1;
  }

  const Prepared* chosen = nullptr;
  const auto find_chosen = [&] {
    for (const auto& p : prepared)
      if (p->app->parsed()) chosen = p.get();
  };
  gestura::remove_staged_files_on_signals();  // Ctrl-C or SIGTERM leaves no temporary output behind
  try {
    cli.parse(argc, argv);
    find_chosen();
    if (!chosen) throw app::AppError(app::ErrorCategory::usage, "missing action");
    ProgressBar bar;
    app::RunContext context;
    context.citation_store = app::user_citation_store();  // a second `gestura say` starts warm
    context.progress = [&bar](const app::ProgressUpdate& update) { bar(update); };
    return chosen->invocation.run(context);
  } catch (const CLI::CallForHelp&) {
    find_chosen();
    CLI::App* shown = chosen ? chosen->app : &cli;
    for (CLI::App* a = &cli; a; ) {  // the deepest parsed command (a group such as `avatar` too)
      CLI::App* next = nullptr;
      for (CLI::App* s : a->get_subcommands()) next = s;
      if (!next) break;
      shown = next;
      a = next;
    }
    std::string parents;  // "gestura avatar" for the usage line of `gestura avatar export`
    for (const CLI::App* p = shown->get_parent(); p; p = p->get_parent()) parents = p->get_name() + (parents.empty() ? "" : " " + parents);
    std::cout << shown->help(parents);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    find_chosen();
    std::string who = "gestura";
    for (CLI::App* a = &cli;;) {
      CLI::App* next = nullptr;
      for (CLI::App* s : a->get_subcommands()) next = s;
      if (!next) break;
      who += " " + next->get_name();
      a = next;
    }
    std::cerr << who << ": " << e.what() << " (see " << who << " --help)\n";
    return 2;
  } catch (...) {
    find_chosen();
    return report(app::classify_current(), chosen);
  }
}
