// gestura fingerspell: plan the fingerspelling of a text and print the timed letter targets.
#include <cstdio>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"

namespace {

using namespace gestura;

float parse_rate(const std::string& text) {
  std::size_t used = 0;
  float value = 0.0f;
  try {
    value = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0.0f)) throw Error("--rate needs a positive number of letters per second, got '" + text + "'");
  return value;
}

const char* double_name(DoubleMark mark) {
  switch (mark) {
    case DoubleMark::None: return "";
    case DoubleMark::Slide: return "slide";
    case DoubleMark::Bounce: return "bounce";
  }
  return "";
}

int run(const std::vector<std::string>& args) {
  ManualAlphabet alphabet = ManualAlphabet::Asl;
  SpellingStyle style = SpellingStyle::Fluent;
  SpellingOptions options;
  std::string text;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--alphabet") {
      const std::string v = cli::flag_value(args, i);
      if (v == "asl") alphabet = ManualAlphabet::Asl;
      else if (v == "bsl") alphabet = ManualAlphabet::Bsl;
      else throw Error("--alphabet must be asl or bsl, got '" + v + "'");
    } else if (a == "--careful") {
      style = SpellingStyle::Careful;
    } else if (a == "--rate") {
      options.letters_per_second = parse_rate(cli::flag_value(args, i));
    } else if (a.size() > 1 && a[0] == '-') {
      throw Error("unknown flag " + a);
    } else {
      if (!text.empty()) text += ' ';
      text += a;
    }
  }
  if (text.empty()) throw Error("nothing to spell (usage: gestura fingerspell [--alphabet asl|bsl] TEXT)");
  const SpellingPlan plan = plan_spelling(text, alphabet, style, options);
  std::printf("%s, %.2f letters/s, %zu letters, %.3f s\n", alphabet == ManualAlphabet::Asl ? "ASL" : "BSL",
              static_cast<double>(plan.letters_per_second), plan.letters.size(), static_cast<double>(plan.duration));
  std::printf("letter  start  reached    end  double  shape/site\n");
  for (const LetterTarget& t : plan.letters) {
    std::string detail;
    if (alphabet == ManualAlphabet::Asl) {
      const AslLetter& letter = *find_asl_letter(t.letter);
      detail = std::string(to_string(letter.handshape)) + " fingers " + std::string(to_string(letter.finger)) +
               " palm " + std::string(to_string(letter.palm)) + (letter.movement ? " +movement" : "");
    } else {
      const BslLetter& letter = *find_bsl_letter(t.letter);
      detail = std::string(to_string(letter.site)) + (letter.movement ? " +movement" : "");
    }
    std::printf("%6c %6.3f %8.3f %6.3f  %-6s  %s\n", t.letter, static_cast<double>(t.start), static_cast<double>(t.reached),
                static_cast<double>(t.end), double_name(t.doubled), detail.c_str());
  }
  return 0;
}

const cli::Registration reg{{"fingerspell", "plan ASL/BSL fingerspelling of a text and print the letter timings",
                             "usage: gestura fingerspell [--alphabet asl|bsl] [--careful] [--rate LETTERS_PER_S] TEXT...\n"
                             "  Prints one line per letter: start of the transition, when the letter is reached,\n"
                             "  when it is left, how a doubled letter is marked, and the letter's shape (ASL) or\n"
                             "  contact site (BSL). ASL spells A-Z and 0-9, BSL A-Z; fluent 6 (ASL) / 5 (BSL)\n"
                             "  letters per second, --careful 4 / 3.5.",
                             run}};

}  // namespace
