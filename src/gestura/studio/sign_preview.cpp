#include "gestura/studio/sign_preview.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace gestura::studio {

SignPreview preview_sign(const SignDraft& draft, const SigningRig& rig, float fps) {
  SignPreview out;
  const auto start = std::chrono::steady_clock::now();
  if (auto error = notation_error(draft)) {
    out.error = std::move(error);
    return out;
  }
  try {
    const sign::HamSign sign = sign::parse_hamnosys_names(draft.names);
    for (const sign::ParseNote& note : sign.notes) out.problems.push_back({"note: " + note.text, note.symbol_index, -1.0f});
    const std::vector<sign::NonManual> tiers = to_sigml_tiers(draft.nonmanuals);
    SignSynthesis s = synthesize_sign(sign, tiers, rig, PlanOptions{}, PerformOptions{fps});
    if (const auto problem = synthesis_problem(s, rig)) {
      // The moment the worst deviation happened, so the timeline can mark it.
      float when = s.stats.key_position_time;
      if (s.stats.key_orientation_error > deg(25.0f)) when = s.stats.key_orientation_time;
      out.problems.push_back({*problem, -1, when});
    }
    for (const NonManualWarning& w : s.warnings) out.problems.push_back({w.message, -1, -1.0f});
    out.sign_start = s.plan.sign_start;
    out.sign_end = s.plan.sign_end;
    out.clip = std::move(s.clip);
  } catch (const Error& e) {
    out.error = NotationError{e.where().index, e.message()};
  } catch (const std::exception& e) {
    out.error = NotationError{-1, e.what()};
  }
  out.synthesis_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

float finger_flexion_degrees(const Skeleton& skeleton, std::span<const mat4> model, char side) {
  const std::string prefix(1, side);
  const int wrist = skeleton.find(prefix + "_wrist");
  if (wrist < 0 || static_cast<std::size_t>(wrist) >= model.size()) return -1.0f;
  const mat3 wrist_frame = mat3(model[wrist]);
  float total = 0.0f;
  for (const char* finger : {"index", "middle", "ring", "pinky"}) {
    const int distal = skeleton.find(prefix + "_" + finger + "3");
    if (distal < 0 || static_cast<std::size_t>(distal) >= model.size()) return -1.0f;
    const mat3 relative = glm::transpose(glm::mat3(glm::normalize(wrist_frame[0]), glm::normalize(wrist_frame[1]),
                                                   glm::normalize(wrist_frame[2]))) *
                          glm::mat3(glm::normalize(vec3(model[distal][0])), glm::normalize(vec3(model[distal][1])),
                                    glm::normalize(vec3(model[distal][2])));
    const float trace = relative[0][0] + relative[1][1] + relative[2][2];
    total += std::acos(std::clamp((trace - 1.0f) * 0.5f, -1.0f, 1.0f));
  }
  return glm::degrees(total);
}

}  // namespace gestura::studio
