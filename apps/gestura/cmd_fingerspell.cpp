// gestura fingerspell: a text spelled with the ASL or BSL manual alphabet (app/fingerspell.hpp) —
// the timed letters, and with -o the avatar performing them.
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "gestura/app/fingerspell.hpp"
#include "gestura/sign/fingerspelling_asl.hpp"
#include "gestura/sign/fingerspelling_bsl.hpp"

namespace gestura::cli {
namespace {

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

Invocation prepare() {
  auto request = std::make_shared<app::FingerspellRequest>();
  Invocation invocation;
  invocation.fields = bind_fields(*request);
  // The words of TEXT may come as separate arguments: they are joined by spaces.
  FieldBinding& text = binding(invocation.fields, "text");
  text.shape = FieldBinding::Shape::list;
  text.set = [request](std::string_view word) { request->text += (request->text.empty() ? "" : " ") + std::string(word); };
  invocation.run = [request](const app::RunContext& context) {
    const app::FingerspellResult r = app::run(*request, context);
    const ManualAlphabet alphabet = request->alphabet;
    const char* name = alphabet == ManualAlphabet::Asl ? "ASL" : "BSL";
    const double rate = static_cast<double>(r.plan.letters_per_second * request->speed);
    if (!r.performance) {
      std::printf("%s, %.2f letters/s, %zu letters, %.3f s\n", name, rate, r.plan.letters.size(),
                  static_cast<double>(r.plan.duration / request->speed));
    } else {
      std::printf("%s: %s, %.2f letters/s, %zu letters, %.2f s (spelling %.2f–%.2f s), %d frames\n", r.written->path.c_str(),
                  name, rate, r.plan.letters.size(), static_cast<double>(r.performance->clip.duration),
                  static_cast<double>(r.performance->spelling_start), static_cast<double>(r.performance->spelling_end),
                  r.written->frames);
    }
    print_letters(alphabet, r.letters);
    return 0;
  };
  return invocation;
}

const Registration reg{{"fingerspell", "spell a text with the ASL or BSL manual alphabet; -o performs it on the avatar",
                        "Prints one line per letter: start of the transition, when the letter is reached, when it\n"
                        "is left, how a doubled letter is marked (slide or bounce), and the letter's shape (ASL) or\n"
                        "contact site (BSL). ASL spells A-Z and 0-9 one-handed; BSL A-Z with both hands (the\n"
                        "non-dominant hand presents, the dominant hand touches). Accented letters are spelled as\n"
                        "their base letter (José as J-O-S-E); other characters are refused by name.\n"
                        "With -o the avatar performs the text from rest to rest, its eyes on the spelling hand,\n"
                        "and the times printed are the clip's. A single .png shows the middle of the spelling.\n" +
                            std::string(app::kMotionOutputHelp),
                        prepare}};

}  // namespace
}  // namespace gestura::cli
