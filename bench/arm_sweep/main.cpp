// gestura-arm-sweep: one line per sign of a lexicon (.jsonl) or SiGML file, with what the arm
// solver made of it: the key-posture misses `gestura check` judges (place at the body, place in
// space, turn), the deepest hand point in the body, how high an elbow rose over its shoulder, and
// check's verdict. For comparing two solvers sign by sign (diff two runs); not a test:
// `make arm-sweep ARGS=FILE`.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/core/parallel_for.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"
#include "gestura/sign/sign_synthesis.hpp"
#include "gestura/sign/signing_rig.hpp"

using namespace gestura;

namespace {

struct Entry {
  std::string place;  // file:line: gloss
  std::optional<sign::HamSign> sign;
  std::vector<sign::NonManual> nonmanual;
};

std::vector<Entry> read_entries(const std::string& path) {
  std::vector<Entry> out;
  if (path.size() > 6 && path.substr(path.size() - 6) == ".sigml") {
    for (sign::SigmlEntry& e : sign::read_sigml_entries(sign::read_text_file(path), path))
      out.push_back({path + ":" + std::to_string(e.line) + ": " + e.gloss,
                     e.sign ? std::optional<sign::HamSign>(std::move(e.sign->manual)) : std::nullopt,
                     e.sign ? std::move(e.sign->nonmanual) : std::vector<sign::NonManual>{}});
    return out;
  }
  std::ifstream file(path);
  std::string line;
  int number = 0;
  while (std::getline(file, line)) {
    ++number;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    Entry e{path + ":" + std::to_string(number) + ": " + j.value("gloss", std::string("?")), std::nullopt, {}};
    try {
      if (j.contains("hamnosys") && j["hamnosys"].is_string() && !j["hamnosys"].get<std::string>().empty())
        e.sign = sign::parse_hamnosys_unicode(j["hamnosys"].get<std::string>());
      else if (j.contains("names") && j["names"].is_string())
        e.sign = sign::parse_hamnosys_names(j["names"].get<std::string>());
      else
        continue;
    } catch (const std::exception&) {
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help") {
    std::puts("usage: gestura-arm-sweep FILE.jsonl|FILE.sigml...\n"
              "prints per sign: place  body-miss-cm space-miss-cm turn-deg depth-cm elbow-rise-cm  verdict");
    return argc < 2 ? 2 : 0;
  }
  const Avatar avatar = build_avatar();
  const SigningRig rig = make_signing_rig(avatar);
  std::vector<Entry> entries;
  for (int i = 1; i < argc; ++i) {
    std::vector<Entry> more = read_entries(argv[i]);
    for (Entry& e : more) entries.push_back(std::move(e));
  }
  std::vector<std::string> lines(entries.size());
  std::vector<PerformanceStats> stats(entries.size());
  parallel_for(entries.size(), [&](std::size_t i) {
    const Entry& e = entries[i];
    char buf[160];
    if (!e.sign) {
      lines[i] = e.place + "\tparse-failed";
      return;
    }
    try {
      const SignSynthesis r = synthesize_sign(*e.sign, e.nonmanual, rig);
      const PerformanceStats& s = r.stats;
      stats[i] = s;
      const auto problem = synthesis_problem(r, rig);
      std::snprintf(buf, sizeof buf, "\t%.1f\t%.1f\t%.0f\t%.1f\t%+.0f\t", 100.0f * s.key_position_error,
                    100.0f * s.key_space_position_error, to_degrees(s.key_orientation_error),
                    100.0f * s.max_penetration, 100.0f * s.max_elbow_rise);
      lines[i] = e.place + buf + (problem ? "FAIL " + *problem : std::string("ok"));
    } catch (const std::exception& x) {
      lines[i] = e.place + "\tFAIL " + x.what();
    }
  });
  int failed = 0, raised = 0, place = 0, turn = 0;
  const SynthesisTolerance tol;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::puts(lines[i].c_str());
    if (lines[i].find("\tFAIL") != std::string::npos) ++failed;
    const PerformanceStats& s = stats[i];
    if (s.key_position_error > tol.position || s.key_space_position_error > tol.space_position) ++place;
    if (s.key_orientation_error > tol.orientation) ++turn;
    if (s.max_elbow_rise > 0.10f) ++raised;
  }
  std::printf("# %zu signs: %d fail check; %d off place, %d turned, %d raise an elbow over 10 cm above its shoulder\n",
              lines.size(), failed, place, turn, raised);
  return 0;
}
