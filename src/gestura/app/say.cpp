#include "gestura/app/say.hpp"

#include "gestura/app/workspace.hpp"
#include "gestura/core/file_extension.hpp"

namespace gestura::app {
namespace {

// A sentence is many moments: a .png is a contact sheet of it.
MotionOutput sentence_output(const SayRequest& request) {
  MotionOutput out = request.output;
  if (has_extension(out.output, ".png")) out.sheet = true;
  return out;
}

}  // namespace

void validate(const SayRequest& request) {
  check_fields(request);
  if (request.text.find_first_not_of(" \t\r\n") == std::string::npos) usage_error("text", "is empty");
  if (request.text.size() > kMaxSayBytes)
    throw AppError(ErrorCategory::too_large, Place{"text", {}},
                   std::to_string(request.text.size()) + " bytes of text; say signs at most " +
                       std::to_string(kMaxSayBytes) + " bytes per call (split longer text into parts)");
  validate(request.avatar);
  validate(sentence_output(request), false);
}

SayResult run(const SayRequest& request, const RunContext& context) {
  validate(request);
  RunWorkspace workspace(context);
  const MotionOutput out = sentence_output(request);
  SayOptions options;
  options.speed = request.speed;
  options.lang = request.lang;
  options.mouthing = request.mouthing;
  options.nonmanuals = request.nonmanuals;
  options.fps = static_cast<float>(out.picture.rate());

  const Signer& signer = workspace->signer(request.avatar);
  context.check_stop();
  SayResult result;
  result.performance = as_field_error(ErrorCategory::input, "text", [&] { return signer.say(request.text, options); });
  for (const std::string& n : result.performance.notes) result.notices.push_back(note(n));
  context.check_stop();
  if (!out.output.empty()) {
    const Avatar& avatar = workspace->avatar(request.avatar);
    result.written = write_motion(out, avatar.skeleton, result.performance.clip, &avatar.mesh,
                                  0.5f * result.performance.duration, context);
  }
  return result;
}

nlohmann::json to_json(const SayResult& result) {
  const SentencePerformance& p = result.performance;
  nlohmann::json out;
  auto& glosses = out["glosses"] = nlohmann::json::array();
  for (const PerformedGloss& g : p.glosses)
    glosses.push_back({{"gloss", g.gloss}, {"source", g.source}, {"start", g.start}, {"end", g.end}});
  out["duration"] = p.duration;
  out["transitions"] = {{"count", p.motion.transitions}, {"via", p.motion.via}, {"escaped", p.motion.escaped}};
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const Notice& n : result.notices) notes.push_back(n.text());
  if (result.written) out["written"] = {{"path", result.written->path}, {"frames", result.written->frames}};
  return out;
}

}  // namespace gestura::app
