#include "gestura/app/sign.hpp"

#include "gestura/app/workspace.hpp"

namespace gestura::app {

void validate(const SignRequest& request) {
  check_fields(request);
  validate(request.source);
  validate(request.avatar);
  validate(request.output, true);
}

SignResult perform(const SignRequest& request, const RunContext& context) {
  check_fields(request);
  validate(request.source);
  validate(request.avatar);
  // The notation first: a bad sign fails before the avatar is built.
  const LoadedSign sign = load_sign(request.source);
  RunWorkspace workspace(context);
  const SigningRig& rig = workspace->rig(request.avatar);
  context.check_stop();

  PlanOptions plan;
  plan.speed = request.speed;
  SignResult result;
  result.synthesis = synthesize_sign(sign.manual, sign.nonmanual, rig, plan,
                                     PerformOptions{static_cast<float>(request.output.picture.rate())});
  for (const NonManualWarning& w : result.synthesis.warnings)
    result.notices.push_back(warning(w.message, SourceLocation{sign.file, w.line}));
  result.problem = synthesis_problem(result.synthesis, rig);
  if (result.problem) result.notices.push_back(warning(*result.problem));
  return result;
}

SignResult run(const SignRequest& request, const RunContext& context) {
  validate(request);
  RunWorkspace workspace(context);  // one for both steps: the avatar is built once
  RunContext shared = context;
  shared.workspace = &*workspace;
  SignResult result = perform(request, shared);
  context.check_stop();
  const Avatar& avatar = workspace->avatar(request.avatar);
  const SignPlan& p = result.synthesis.plan;
  result.written = write_motion(request.output, avatar.skeleton, result.synthesis.clip, &avatar.mesh,
                                0.5f * (p.sign_start + p.sign_end), context);
  return result;
}

nlohmann::json to_json(const SignResult& result) {
  const SignSynthesis& s = result.synthesis;
  nlohmann::json out{{"duration", s.clip.duration},
                     {"sign_start", s.plan.sign_start},
                     {"sign_end", s.plan.sign_end},
                     {"frames", s.stats.frames},
                     {"written", {{"path", result.written.path}, {"frames", result.written.frames}}}};
  out["problem"] = result.problem ? nlohmann::json(*result.problem) : nlohmann::json();
  auto& notes = out["notes"] = nlohmann::json::array();
  for (const Notice& n : result.notices) notes.push_back(n.text());
  return out;
}

}  // namespace gestura::app
