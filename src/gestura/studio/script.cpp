#include "gestura/studio/script.hpp"

#include <fstream>
#include <map>
#include <sstream>

#include "gestura/core/error.hpp"

namespace gestura::studio {
namespace {

struct Arity {
  int min = 0, max = 0;
  bool rest = false;  // the last argument is the rest of the line
};

const std::map<std::string, Arity>& actions() {
  static const std::map<std::string, Arity> table{
      {"open", {1, 3}},          {"new", {0, 0}},           {"duplicate", {0, 0}},     {"save", {0, 0}},
      {"delete", {0, 0}},        {"undo", {0, 0}},          {"redo", {0, 0}},          {"set", {2, 2, true}},
      {"select-symbol", {1, 1}}, {"palette", {1, 1}},       {"replace-symbol", {2, 2}}, {"insert-symbol", {2, 2}},
      {"remove-symbol", {1, 1}}, {"nonmanual", {1, 2}}, {"search", {0, 1, true}},  {"filter", {2, 2}},        {"panel", {1, 1}},
      {"camera", {1, 1}},        {"time", {1, 1}},          {"play", {0, 0}},          {"pause", {0, 0}},
      {"wait", {1, 1}},          {"import", {1, 1}},        {"export", {1, 1}},        {"recover", {0, 0}},
      {"discard-recovery", {0, 0}}, {"screenshot", {1, 1}}, {"dump", {1, 1}},          {"kill", {0, 0}},
      {"quit", {0, 0}},          {"mode", {1, 1}},          {"topic", {1, 1, true}},         {"word", {1, 1}},
      {"sentence", {1, 1, true}}, {"quiz", {1, 1}},         {"answer", {1, 1}},        {"next-question", {0, 0}},
      {"views", {1, 1}},         {"speed", {1, 1}},         {"export-sign", {1, 1}},
      {"pose-joint", {1, 1}},    {"pose-angles", {3, 3}},   {"pose-hand", {2, 2}},     {"pose-mirror", {0, 0}},
      {"pose-morph", {2, 2}},
      // pose editor: pick a limb by clicking the view, drag a hand or foot (IK)
      {"pose-pick", {2, 2}},     {"pose-drag", {4, 4}},     {"pose-drag-by", {4, 4}},
      // timeline editor
      {"timeline-say", {1, 1, true}}, {"timeline-sign", {0, 0}}, {"timeline-clear", {0, 0}}, {"key-pose", {0, 1}},
      {"key", {3, 3}},           {"move-key", {3, 3}},      {"move-keys-at", {2, 2}},  {"key-interp", {3, 6}},
      {"bar-duration", {2, 2}},  {"export-timeline", {1, 1}}, {"save-clip-sign", {1, 2}}, {"loop", {1, 1}},
      {"timeline-zoom", {1, 1}}, {"strip-zoom", {1, 1}}, {"where-key", {3, 3}}, {"wait-file", {1, 1}},
      // figure editor
      {"figure-joint", {1, 1}},  {"figure-rename", {1, 1}}, {"figure-add", {4, 4}},    {"figure-remove", {0, 0}},
      {"figure-copy", {0, 0}},   {"figure-mirror", {0, 0}}, {"figure-offset", {3, 3}}, {"figure-limits", {3, 3}},
      {"figure-order", {1, 1}},  {"figure-dh", {0, 0}},     {"figure-save", {1, 1}},   {"figure-load", {1, 1}},
      {"figure-view", {1, 1}},
      // the environment and colour editors
      {"env-open", {1, 1}},      {"env-save", {0, 1}},      {"env-select", {1, 1}},    {"env-tool", {1, 1}},
      {"env-snap", {1, 2}},      {"env-click", {3, 3}},     {"env-drag", {5, 6}},      {"env-drag-from", {4, 5}},
      {"env-set", {2, 4}},       {"env-add", {1, 2}},       {"env-delete", {0, 0}},    {"env-duplicate", {0, 0}},
      {"env-group", {2, 2, true}}, {"env-colour", {1, 1, true}}, {"env-ramp", {2, 2}},   {"env-keep", {1, 1}},
      {"env-slot", {1, 1}},      {"env-orbit", {3, 3}},     {"env-zoom", {2, 2}},      {"env-frame", {0, 0}},
      {"env-walk", {2, 2}},      {"env-walk-time", {1, 1}}, {"env-stop", {0, 0}}};
  return table;
}

}  // namespace

std::vector<ScriptStep> parse_script(const std::string& text, const std::string& file_name) {
  std::vector<ScriptStep> steps;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    std::istringstream words(line);
    ScriptStep step;
    step.line = number;
    if (!(words >> step.action)) continue;
    const auto it = actions().find(step.action);
    const SourceLocation where{file_name, number};
    if (it == actions().end()) throw Error(where, "unknown studio action '" + step.action.substr(0, 40) + "'");
    const Arity arity = it->second;
    for (std::string word; static_cast<int>(step.args.size()) < arity.max - (arity.rest ? 1 : 0) && words >> word;)
      step.args.push_back(word);
    if (arity.rest) {
      std::string rest;
      std::getline(words, rest);
      const auto first = rest.find_first_not_of(" \t");
      if (first != std::string::npos) step.args.push_back(rest.substr(first));
    } else if (std::string extra; words >> extra) {
      throw Error(where, "'" + step.action + "' takes at most " + std::to_string(arity.max) + " arguments");
    }
    if (static_cast<int>(step.args.size()) < arity.min)
      throw Error(where, "'" + step.action + "' needs " + std::to_string(arity.min) + " argument" + (arity.min == 1 ? "" : "s"));
    steps.push_back(std::move(step));
  }
  return steps;
}

std::vector<ScriptStep> read_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(SourceLocation{path}, "cannot read the script");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().find('\0') != std::string::npos) throw Error(SourceLocation{path}, "the script is not text");
  return parse_script(text.str(), path);
}

}  // namespace gestura::studio
