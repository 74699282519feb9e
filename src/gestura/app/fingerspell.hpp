#pragma once
// fingerspell: a text spelled with the ASL or BSL manual alphabet — the timed letters, and when an
// output is named, the avatar performing them from rest to rest.
#include <optional>
#include <string>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/sentence/fingerspelling_performance.hpp"
#include "gestura/sign/fingerspelling_plan.hpp"

namespace gestura::app {

struct FingerspellRequest {
  std::string text;
  ManualAlphabet alphabet = ManualAlphabet::Asl;
  bool careful = false;
  std::optional<float> rate;  // letters per second; default: the alphabet's fluent or careful rate
  float speed = 1.0f;
  AvatarChoice avatar;
  MotionOutput output;  // optional: without it only the letter timings are made

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.text, FieldInfo{.name = "text", .help = "the text to spell (letters, digits for ASL; spaces separate words)", .value = "TEXT", .positional = true, .required = true});
    visit(self.alphabet, FieldInfo{.name = "alphabet", .help = "asl (one-handed) or bsl (two-handed)", .value = "asl|bsl"});
    visit(self.careful, FieldInfo{.name = "careful", .help = "the careful pace of names and unfamiliar words (ASL 4, BSL 3.5 letters/s)"});
    visit(self.rate, FieldInfo{.name = "rate", .help = "letters per second", .value = "N", .min = 0.5, .max = 20, .unset = "ASL 6, BSL 5; --careful 4, 3.5"});
    visit(self.speed, FieldInfo{.name = "speed", .help = "scales every time", .value = "S", .min = 0.25, .max = 4});
    AvatarChoice::fields(self.avatar, visit);
    MotionOutput::fields(self.output, visit);
  }
};

struct FingerspellResult {
  SpellingPlan plan;                                     // at the plan's own pace
  std::vector<LetterTarget> letters;                     // the letters on the result's clock (speed applied)
  std::optional<FingerspellingPerformance> performance;  // with an output
  std::optional<WrittenFile> written;
};

void validate(const FingerspellRequest& request);
FingerspellResult run(const FingerspellRequest& request, const RunContext& context = {});
nlohmann::json to_json(const FingerspellResult& result);

}  // namespace gestura::app
