#pragma once
// say: English text → ASL performed by an avatar (sentence/signer.hpp), optionally written out.
#include <optional>
#include <string>

#include "gestura/app/avatar_choice.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/app/notice.hpp"
#include "gestura/sentence/signer.hpp"

namespace gestura::app {

struct SayRequest {
  std::string text;
  std::string lang = "ase";
  float speed = 1.0f;
  bool mouthing = true;
  bool nonmanuals = true;
  AvatarChoice avatar;
  MotionOutput output;  // optional: without it only the timeline is made

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.text, FieldInfo{.name = "text", .help = "English text to sign", .value = "TEXT", .positional = true, .required = true});
    visit(self.lang, FieldInfo{.name = "lang", .help = "sign language (ISO 639-3); only ase (ASL) has a lexicon", .value = "L"});
    visit(self.speed, FieldInfo{.name = "speed", .help = "tempo factor", .value = "S", .min = 0.25, .max = 2});
    visit(self.mouthing, FieldInfo{.name = "mouthing", .help = "mouthing of the English words with the signs", .negated = true});
    visit(self.nonmanuals, FieldInfo{.name = "nonmanuals", .help = "non-manual markers (question brows, negation headshake, blinks)", .negated = true});
    AvatarChoice::fields(self.avatar, visit);
    MotionOutput::fields(self.output, visit);
  }
};

struct SayResult {
  SentencePerformance performance;  // clip, glosses with times, duration, notes, plan, motion stats
  std::vector<Notice> notices;
  std::optional<WrittenFile> written;
};

// Fields, the text's size (too_large past kMaxSayBytes) and the output; throws AppError.
void validate(const SayRequest& request);
SayResult run(const SayRequest& request, const RunContext& context = {});

nlohmann::json to_json(const SayResult& result);

}  // namespace gestura::app
