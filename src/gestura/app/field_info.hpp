#pragma once
// What a request says about one of its fields: the name it goes by (the JSON key, and on the
// command line --name or a bare argument), one line of help, and the limits checked for every
// value however it arrives (command line, JSON, code).
#include <limits>
#include <string_view>

namespace gestura::app {

struct FieldInfo {
  std::string_view name;        // JSON key; the command line spells it --name
  std::string_view help;        // one line, for --help and API docs
  std::string_view value = {};  // placeholder in usage lines: N, S, WxH, FILE
  double min = -std::numeric_limits<double>::infinity();  // numbers: inclusive bounds
  double max = std::numeric_limits<double>::infinity();
  char short_flag = 0;          // a one-letter command-line alias, e.g. 'o' for -o
  bool positional = false;      // command line: given as a bare argument (TEXT, FILE)
  bool negated = false;         // a bool that defaults to true; the command line has --no-NAME
  bool required = false;        // must be given (a non-empty string, an optional with a value)
  std::string_view group = {};  // a heading the command line's help lists it under ("Avatar", "Output")
  std::string_view unset = {};  // what an absent optional value means, for help ("30", "the input's rate")
};

}  // namespace gestura::app
