#pragma once
// mouth: the phonemes eSpeak NG gives a word and the face channels of its mouthing over a sign.
#include <string>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/fields.hpp"
#include "gestura/face/phoneme.hpp"

namespace gestura::app {

struct MouthRequest {
  std::string word;
  float start = 0.0f, end = 0.6f;  // the sign's span, seconds
  float amplitude = 1.0f;

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.word, FieldInfo{.name = "word", .help = "the word to mouth", .value = "WORD", .positional = true, .required = true});
    visit(self.start, FieldInfo{.name = "start", .help = "when the sign starts (s)", .value = "S", .min = 0, .max = 3600});
    visit(self.end, FieldInfo{.name = "end", .help = "when the sign ends (s), after --start", .value = "E", .min = 0, .max = 3600});
    visit(self.amplitude, FieldInfo{.name = "amplitude", .help = "scale of the articulation (~0.5 for reduced mouthing)", .value = "A", .min = 0, .max = 1});
  }
};

struct MouthResult {
  std::vector<face::Phoneme> phonemes;
  Clip clip;  // the face channels (visemes, jaw_open, mouthPucker)
};

void validate(const MouthRequest& request);
MouthResult run(const MouthRequest& request, const RunContext& context = {});
nlohmann::json to_json(const MouthResult& result);

}  // namespace gestura::app
