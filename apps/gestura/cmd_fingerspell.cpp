// gestura fingerspell: spell a text with the ASL or BSL manual alphabet — print the timed letters,
// and with -o perform them on the avatar and write the motion like `gestura sign` (motion_output.hpp).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sentence/fingerspelling_performance.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "motion_output.hpp"

namespace {

using namespace gestura;

float parse_positive(const std::string& flag, const std::string& text, const char* what) {
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(value > 0.0f))
    throw Error(flag + " needs a positive number " + what + ", got '" + text + "'");
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

std::string letter_detail(ManualAlphabet alphabet, char symbol) {
  if (alphabet == ManualAlphabet::Asl) {
    const AslLetter& letter = *find_asl_letter(symbol);
    return std::string(to_string(letter.handshape)) + " fingers " + std::string(to_string(letter.finger)) + " palm " +
           std::string(to_string(letter.palm)) + (letter.movement ? " +movement" : "");
  }
  const BslLetter& letter = *find_bsl_letter(symbol);
  return std::string(to_string(letter.site)) + (letter.movement ? " +movement" : "");
}

void print_letters(ManualAlphabet alphabet, const std::vector<LetterTarget>& letters) {
  std::printf("letter  start  reached    end  double  shape/site\n");
  for (const LetterTarget& t : letters)
    std::printf("%6c %6.3f %8.3f %6.3f  %-6s  %s\n", t.letter, static_cast<double>(t.start), static_cast<double>(t.reached),
                static_cast<double>(t.end), double_name(t.doubled), letter_detail(alphabet, t.letter).c_str());
}

int run(const std::vector<std::string>& args) {
  ManualAlphabet alphabet = ManualAlphabet::Asl;
  SpellingStyle style = SpellingStyle::Fluent;
  SpellingOptions spelling;
  FingerspellingOptions perform;
  cli::MotionOutput out;
  std::string avatar_spec = "default";
  std::string text;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (cli::parse_motion_output_flag(args, i, out)) continue;
    if (a == "--alphabet") {
      const std::string v = cli::flag_value(args, i);
      if (v == "asl") alphabet = ManualAlphabet::Asl;
      else if (v == "bsl") alphabet = ManualAlphabet::Bsl;
      else throw Error("--alphabet must be asl or bsl, got '" + v + "'");
    } else if (a == "--careful") {
      style = SpellingStyle::Careful;
    } else if (a == "--rate") {
      spelling.letters_per_second = parse_positive(a, cli::flag_value(args, i), "of letters per second");
    } else if (a == "--speed") {
      perform.speed = parse_positive(a, cli::flag_value(args, i), "(tempo factor 0.25–4)");
      if (perform.speed < 0.25f || perform.speed > 4.0f) throw Error("--speed must be between 0.25 and 4");
    } else if (a == "--avatar") {
      avatar_spec = cli::flag_value(args, i);
    } else if (a.size() > 1 && a[0] == '-') {
      throw Error("unknown flag " + a + " (see gestura fingerspell --help)");
    } else {
      if (!text.empty()) text += ' ';
      text += a;
    }
  }
  if (text.find_first_not_of(' ') == std::string::npos)
    throw Error("nothing to spell (usage: gestura fingerspell [--alphabet asl|bsl] TEXT [-o OUT])");
  if (!out.path.empty()) cli::check_motion_output(out);
  const SpellingPlan plan = plan_spelling(text, alphabet, style, spelling);
  const char* name = alphabet == ManualAlphabet::Asl ? "ASL" : "BSL";

  if (out.path.empty()) {
    std::vector<LetterTarget> letters = plan.letters;
    for (LetterTarget& t : letters) t.start /= perform.speed, t.reached /= perform.speed, t.end /= perform.speed;
    std::printf("%s, %.2f letters/s, %zu letters, %.3f s\n", name, static_cast<double>(plan.letters_per_second * perform.speed),
                plan.letters.size(), static_cast<double>(plan.duration / perform.speed));
    print_letters(alphabet, letters);
    return 0;
  }

  const Avatar avatar = load_avatar(avatar_spec);
  const SigningRig rig = make_signing_rig(avatar);
  perform.fps = static_cast<float>(out.fps);
  const FingerspellingPerformance result = perform_fingerspelling(plan, rig, perform);
  const int frames = cli::write_motion(out, avatar.skeleton, result.clip, &avatar.mesh,
                                       0.5f * (result.spelling_start + result.spelling_end));
  std::printf("%s: %s, %.2f letters/s, %zu letters, %.2f s (spelling %.2f–%.2f s), %d frames\n", out.path.c_str(), name,
              static_cast<double>(plan.letters_per_second * perform.speed), plan.letters.size(),
              static_cast<double>(result.clip.duration), static_cast<double>(result.spelling_start),
              static_cast<double>(result.spelling_end), frames);
  print_letters(alphabet, result.letters);
  return 0;
}

const cli::Registration reg{{"fingerspell", "spell a text with the ASL or BSL manual alphabet; -o performs it on the avatar",
                             "usage: gestura fingerspell [--alphabet asl|bsl] [--careful] [--rate LETTERS_PER_S] [--speed S]\n"
                             "                           [-o OUT [--avatar SPEC] [--fps N] [--size WxH] [--camera LIST] [--sheet]] TEXT...\n\n"
                             "Prints one line per letter: start of the transition, when the letter is reached, when it\n"
                             "is left, how a doubled letter is marked (slide or bounce), and the letter's shape (ASL) or\n"
                             "contact site (BSL). ASL spells A-Z and 0-9 one-handed; BSL A-Z with both hands (the\n"
                             "non-dominant hand presents, the dominant hand touches). Fluent 6 (ASL) / 5 (BSL) letters\n"
                             "per second, --careful 4 / 3.5, or --rate N; --speed scales every time (0.25–4).\n"
                             "With -o the avatar performs the text from rest to rest, its eyes on the spelling hand,\n"
                             "and the times printed are the clip's. A single .png shows the middle of the spelling.\n" +
                                 std::string(cli::kMotionOutputUsage),
                             run}};

}  // namespace
