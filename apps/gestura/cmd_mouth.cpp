// gestura mouth WORD — the phonemes eSpeak NG gives a word and the face channels of its mouthing.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/mouthing.hpp"
#include "gestura/face/phonemizer.hpp"

namespace {

using gestura::Error;

constexpr const char* kUsage = R"(usage: gestura mouth WORD [--start S] [--end E] [--amplitude A]

Phonemizes WORD with eSpeak NG (en-us, ASCII mnemonics, ' = primary and , = secondary stress) and
prints the mouthing channels it gives over a sign lasting from S to E seconds (default 0 to 0.6):
for every channel its peak weight and when it is reached, in order of first use.
  --amplitude A   0..1 scale of the articulation (default 1; ~0.5 for reduced mouthing))";

float number(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const float v = std::stof(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw Error("bad value '" + text + "' for " + flag);
}

int run(const std::vector<std::string>& args) {
  std::optional<std::string> word;
  float start = 0.0f, end = 0.6f;
  gestura::face::MouthingOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--start") start = number(args[i], gestura::cli::flag_value(args, i));
    else if (args[i] == "--end") end = number(args[i], gestura::cli::flag_value(args, i));
    else if (args[i] == "--amplitude") options.amplitude = number(args[i], gestura::cli::flag_value(args, i));
    else if (args[i].rfind("--", 0) == 0) throw Error("unknown flag " + args[i] + " (see gestura mouth --help)");
    else if (word) throw Error("one word only (see gestura mouth --help)");
    else word = args[i];
  }
  if (!word) throw Error("missing WORD (see gestura mouth --help)");
  if (!(end > start)) throw Error("--end must be later than --start");

  const auto phonemes = gestura::face::phonemize(*word);
  std::cout << "phonemes:";
  for (const auto& p : phonemes)
    std::cout << ' ' << (p.stress == gestura::face::Stress::primary ? "'" : p.stress == gestura::face::Stress::secondary ? "," : "")
              << p.symbol;
  std::cout << '\n';
  gestura::Clip clip;
  gestura::face::add_mouthing(*word, start, end, options, clip);
  for (std::size_t c = 0; c < clip.channels.size(); ++c) {
    const auto& tr = clip.channels[c];
    const auto peak = std::max_element(tr.values.begin(), tr.values.end());
    if (peak == tr.values.end()) continue;
    char line[128];
    std::snprintf(line, sizeof line, "%-12s peak %.2f at %.3f s (%zu keys)", clip.channel_names[c].c_str(), *peak,
                  tr.times[static_cast<std::size_t>(peak - tr.values.begin())], tr.size());
    std::cout << line << '\n';
  }
  return 0;
}

const gestura::cli::Registration reg{{"mouth", "phonemes and mouthing channels of a word", kUsage, run}};

}  // namespace
