#include "gestura/sign/sign_check.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/core/parallel_for.hpp"
#include "gestura/sign/hamnosys_describe.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::sign {
namespace {

// One sign as read from the file: where it is, and its notation or why it could not be read.
struct ReadSign {
  std::string place;
  std::optional<HamSign> sign;
  std::vector<NonManual> nonmanual;
  std::string error;  // when there is no sign
  bool clip = false;  // a clip sign: a recorded motion, no notation to parse
};

// Counts the signs in file order. Synthesis (the costly step, ~10 ms a sign) runs on every core a
// batch at a time; the counting stays serial, so the report is the serial one: the same failures
// in the same order, and max_failures stops at the same sign (a batch may have synthesized a few
// signs past it, which are not counted).
void count_signs(CheckReport& report, const std::vector<ReadSign>& signs, const CheckOptions& options) {
  const bool synthesize = report.synthesis_connected;
  const std::size_t batch = synthesize ? 16 * static_cast<std::size_t>(worker_count()) : signs.size();
  std::vector<std::optional<std::string>> problems;
  for (std::size_t begin = 0; begin < signs.size(); begin += batch) {
    const std::size_t end = std::min(signs.size(), begin + batch);
    problems.assign(end - begin, std::nullopt);
    if (synthesize)
      parallel_for(end - begin, [&](std::size_t i) {
        const ReadSign& s = signs[begin + i];
        if (s.sign) problems[i] = options.synthesize(*s.sign, s.nonmanual);
      });
    for (std::size_t i = begin; i < end; ++i) {
      if (options.max_failures > 0 && report.failed >= options.max_failures) {
        report.stopped = true;
        return;
      }
      ++report.signs;
      const ReadSign& s = signs[i];
      if (s.clip) {
        ++report.clips;
        report.notes.push_back(s.place + ": clip sign (keyframed motion, no notation to check)");
        continue;
      }
      if (!s.sign) {
        ++report.failed;
        report.failures.push_back(s.place + ": " + s.error);
        continue;
      }
      ++report.parsed;
      for (const ParseNote& note : s.sign->notes)
        report.notes.push_back(s.place + ": note: symbol " + std::to_string(note.symbol_index) + ": " + note.text);
      if (options.describe_parsed) report.descriptions.push_back(s.place + ": " + describe(*s.sign));
      if (!synthesize) continue;
      if (const auto& why = problems[i - begin]) {
        ++report.failed;
        report.failures.push_back(s.place + ": synthesis failed: " + *why);
      } else {
        ++report.synthesized;
      }
    }
  }
}

ReadSign unreadable(std::string place, std::string why) { return {std::move(place), std::nullopt, {}, std::move(why)}; }

std::string_view extension(std::string_view path) {
  const auto dot = path.rfind('.');
  const auto slash = path.find_last_of("/\\");
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
  return path.substr(dot);
}

}  // namespace

CheckReport check_jsonl(std::string_view text, std::string_view file_name, const CheckOptions& options) {
  CheckReport report;
  report.synthesis_connected = static_cast<bool>(options.synthesize);
  std::vector<ReadSign> signs;
  std::size_t start = 0;
  int line_number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    std::string place = std::string(file_name) + ":" + std::to_string(line_number);
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) {
      signs.push_back(unreadable(std::move(place), "not a JSON object"));
      continue;
    }
    if (const auto g = j.find("gloss"); g != j.end() && g->is_string()) place += ": " + g->get<std::string>();
    const auto ham = j.find("hamnosys");
    const auto names = j.find("names");
    const bool have_unicode = ham != j.end() && ham->is_string() && !ham->get_ref<const std::string&>().empty();
    const bool have_names = names != j.end() && names->is_string() && !names->get_ref<const std::string&>().empty();
    if (const auto clip = j.find("clip_base64"); !have_unicode && !have_names && clip != j.end() && clip->is_string() &&
                                                 !clip->get_ref<const std::string&>().empty()) {
      ReadSign r{std::move(place), std::nullopt, {}, {}};
      r.clip = true;
      signs.push_back(std::move(r));
      continue;
    }
    if (!have_unicode && !have_names) {
      signs.push_back(unreadable(std::move(place), "no `hamnosys` (or `names`) string"));
      continue;
    }
    try {
      HamSign sign = have_unicode ? parse_hamnosys_unicode(ham->get_ref<const std::string&>(), options.parse)
                                  : parse_hamnosys_names(names->get_ref<const std::string&>(), options.parse);
      signs.push_back({std::move(place), std::move(sign), {}, {}});
    } catch (const Error& e) {
      signs.push_back(unreadable(std::move(place), e.what()));
    }
  }
  count_signs(report, signs, options);
  return report;
}

CheckReport check_sigml(std::string_view text, std::string_view file_name, const CheckOptions& options) {
  CheckReport report;
  report.synthesis_connected = static_cast<bool>(options.synthesize);
  std::vector<ReadSign> signs;
  for (SigmlEntry& entry : read_sigml_entries(text, file_name, options.parse)) {
    std::string place = std::string(file_name) + ":" + std::to_string(entry.line) + ": " + entry.gloss;
    if (entry.sign) signs.push_back({std::move(place), std::move(entry.sign->manual), std::move(entry.sign->nonmanual), {}});
    else signs.push_back(unreadable(std::move(place), entry.error->message()));
  }
  count_signs(report, signs, options);
  return report;
}

CheckReport check_file(const std::string& path, const CheckOptions& options) {
  const std::string_view ext = extension(path);
  if (ext != ".jsonl" && ext != ".sigml") throw Error(path + ": unknown file type: expected .jsonl or .sigml");
  const std::string text = read_text_file(path);
  return ext == ".jsonl" ? check_jsonl(text, path, options) : check_sigml(text, path, options);
}

}  // namespace gestura::sign
