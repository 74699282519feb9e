#pragma once
// The gestura command line: a thin adapter over the command layer (src/gestura/app). Each
// cmd_*.cpp registers one command: its help, the request whose fields become its flags and
// arguments, and how the result is printed. main.cpp turns the registry into a CLI11 parser and
// the errors into messages and exit codes.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"

namespace gestura::cli {

// One flag or argument: a request field, or a flag of the command line alone (--json, --file).
struct FieldBinding {
  enum class Shape { value, list, flag };
  app::FieldInfo info;
  Shape shape = Shape::value;
  std::function<void(std::string_view text)> set;  // flag: called with "" when given
  std::string default_text;                         // shown in --help; empty: none worth showing
};

// What a command prepared for one parse: its flags bound to a request it owns, and the code that
// runs the request once they are set. The exit status comes from run.
struct Invocation {
  std::vector<FieldBinding> fields;
  std::function<int(const app::RunContext& context)> run;
};

struct Command {
  std::string name;
  std::string summary;      // one line for `gestura --help`
  std::string description;  // the text of `gestura NAME --help` below the flags
  std::function<Invocation()> prepare;
  std::vector<Command> actions;  // sub-commands (avatar export, lexicon add, ...): prepare is then empty
};

std::vector<Command>& registry();

struct Registration {
  explicit Registration(Command command) { registry().push_back(std::move(command)); }
};

// "1.7", "0.25", "30": a default as a person writes it.
std::string shown_number(double value);

// Every field of `request` as a binding that sets it from command-line text.
template <app::FieldTable R>
std::vector<FieldBinding> bind_fields(R& request) {
  std::vector<FieldBinding> out;
  R::fields(request, [&]<class T>(T& value, const app::FieldInfo& info) {
    FieldBinding b;
    b.info = info;
    const nlohmann::json initial = app::value_to_json(value);
    if (initial.is_number_float()) b.default_text = shown_number(initial.get<double>());
    else if (initial.is_number()) b.default_text = initial.dump();
    else if (initial.is_string()) b.default_text = initial.get<std::string>();
    if (b.default_text.empty()) b.default_text = info.unset;
    if constexpr (std::same_as<T, bool>) {
      b.shape = FieldBinding::Shape::flag;
      b.set = [&value, negated = info.negated](std::string_view) { value = !negated; };
    } else {
      if constexpr (std::same_as<T, std::vector<std::string>>) b.shape = FieldBinding::Shape::list;
      b.set = [&value, info](std::string_view text) { app::set_from_text(value, text, info); };
    }
    out.push_back(std::move(b));
  });
  return out;
}

// The binding of field `name` (it must exist: a mistake of the command's code otherwise).
FieldBinding& binding(std::vector<FieldBinding>& fields, std::string_view name);
// Leaves a field off the command line (the command sets it itself, e.g. an action's kind).
void unbind(std::vector<FieldBinding>& fields, std::string_view name);

// A flag of the command line alone.
inline FieldBinding flag(app::FieldInfo info, bool& target) {
  return {info, FieldBinding::Shape::flag, [&target](std::string_view) { target = true; }};
}
inline FieldBinding option(app::FieldInfo info, std::string& target) {
  return {info, FieldBinding::Shape::value, [&target](std::string_view text) { target = std::string(text); }};
}

// The text of a TEXT argument: itself, or standard input when it is "-", or the file --file names
// ("-" for standard input too). Throws the request's errors (not_found, too_large, input).
std::string text_argument(const std::string& text, const std::string& file, std::size_t max_bytes);

}  // namespace gestura::cli
