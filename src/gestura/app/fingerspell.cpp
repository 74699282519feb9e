#include "gestura/app/fingerspell.hpp"

#include "gestura/app/workspace.hpp"

namespace gestura::app {

void validate(const FingerspellRequest& request) {
  check_fields(request);
  if (request.text.find_first_not_of(" \t\r\n") == std::string::npos) usage_error("text", "nothing to spell");
  validate(request.avatar);
  validate(request.output, false);
}

FingerspellResult run(const FingerspellRequest& request, const RunContext& context) {
  validate(request);
  SpellingOptions spelling;
  spelling.letters_per_second = request.rate.value_or(0.0f);
  FingerspellResult result;
  result.plan = as_field_error(ErrorCategory::input, "text", [&] {
    return plan_spelling(request.text, request.alphabet, request.careful ? SpellingStyle::Careful : SpellingStyle::Fluent,
                         spelling);
  });
  if (request.output.output.empty()) {
    result.letters = result.plan.letters;
    for (LetterTarget& t : result.letters) t.start /= request.speed, t.reached /= request.speed, t.end /= request.speed;
    return result;
  }
  RunWorkspace workspace(context);
  const Avatar& avatar = workspace->avatar(request.avatar);
  const SigningRig& rig = workspace->rig(request.avatar);
  context.check_stop();
  FingerspellingOptions perform;
  perform.speed = request.speed;
  perform.fps = static_cast<float>(request.output.picture.rate());
  result.performance = perform_fingerspelling(result.plan, rig, perform);
  result.letters = result.performance->letters;
  context.check_stop();
  result.written = write_motion(request.output, avatar.skeleton, result.performance->clip, &avatar.mesh,
                                0.5f * (result.performance->spelling_start + result.performance->spelling_end), context);
  return result;
}

nlohmann::json to_json(const FingerspellResult& result) {
  nlohmann::json out{{"alphabet", result.plan.alphabet == ManualAlphabet::Asl ? "asl" : "bsl"},
                     {"letters_per_second", result.plan.letters_per_second}};
  auto& letters = out["letters"] = nlohmann::json::array();
  for (const LetterTarget& t : result.letters)
    letters.push_back({{"letter", std::string(1, t.letter)}, {"start", t.start}, {"reached", t.reached}, {"end", t.end}});
  if (result.performance) {
    out["duration"] = result.performance->clip.duration;
    out["spelling_start"] = result.performance->spelling_start;
    out["spelling_end"] = result.performance->spelling_end;
  }
  if (result.written) out["written"] = {{"path", result.written->path}, {"frames", result.written->frames}};
  return out;
}

}  // namespace gestura::app
