#include "gestura/sign/sign_check.hpp"

#include <nlohmann/json.hpp>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_describe.hpp"
#include "gestura/sign/sigml.hpp"

namespace gestura::sign {
namespace {

// Counts a parsed sign and runs synthesis when connected.
void after_parse(CheckReport& report, const HamSign& sign, std::span<const NonManual> nonmanual,
                 const std::string& place, const CheckOptions& options) {
  ++report.parsed;
  for (const ParseNote& note : sign.notes)
    report.notes.push_back(place + ": note: symbol " + std::to_string(note.symbol_index) + ": " + note.text);
  if (options.describe_parsed) report.descriptions.push_back(place + ": " + describe(sign));
  if (!options.synthesize) return;
  if (const auto why = options.synthesize(sign, nonmanual)) {
    ++report.failed;
    report.failures.push_back(place + ": synthesis failed: " + *why);
  } else {
    ++report.synthesized;
  }
}

void parse_failed(CheckReport& report, const std::string& place, const std::string& reason) {
  ++report.failed;
  report.failures.push_back(place + ": " + reason);
}

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
  std::size_t start = 0;
  int line_number = 0;
  while (start < text.size()) {
    if (options.max_failures > 0 && report.failed >= options.max_failures) {
      report.stopped = true;
      break;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    ++report.signs;
    std::string place = std::string(file_name) + ":" + std::to_string(line_number);
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) {
      parse_failed(report, place, "not a JSON object");
      continue;
    }
    if (const auto g = j.find("gloss"); g != j.end() && g->is_string()) place += ": " + g->get<std::string>();
    const auto ham = j.find("hamnosys");
    const auto names = j.find("names");
    const bool have_unicode = ham != j.end() && ham->is_string() && !ham->get_ref<const std::string&>().empty();
    const bool have_names = names != j.end() && names->is_string() && !names->get_ref<const std::string&>().empty();
    if (!have_unicode && !have_names) {
      parse_failed(report, place, "no `hamnosys` (or `names`) string");
      continue;
    }
    try {
      const HamSign sign = have_unicode ? parse_hamnosys_unicode(ham->get_ref<const std::string&>(), options.parse)
                                        : parse_hamnosys_names(names->get_ref<const std::string&>(), options.parse);
      after_parse(report, sign, {}, place, options);
    } catch (const Error& e) {
      parse_failed(report, place, e.what());
    }
  }
  return report;
}

CheckReport check_sigml(std::string_view text, std::string_view file_name, const CheckOptions& options) {
  CheckReport report;
  report.synthesis_connected = static_cast<bool>(options.synthesize);
  for (const SigmlEntry& entry : read_sigml_entries(text, file_name, options.parse)) {
    if (options.max_failures > 0 && report.failed >= options.max_failures) {
      report.stopped = true;
      break;
    }
    ++report.signs;
    const std::string place = std::string(file_name) + ":" + std::to_string(entry.line) + ": " + entry.gloss;
    if (entry.sign) after_parse(report, entry.sign->manual, entry.sign->nonmanual, place, options);
    else parse_failed(report, place, entry.error->message());
  }
  return report;
}

CheckReport check_file(const std::string& path, const CheckOptions& options) {
  const std::string_view ext = extension(path);
  if (ext != ".jsonl" && ext != ".sigml") throw Error(path + ": unknown file type: expected .jsonl or .sigml");
  const std::string text = read_text_file(path);
  return ext == ".jsonl" ? check_jsonl(text, path, options) : check_sigml(text, path, options);
}

}  // namespace gestura::sign
