#pragma once
// Sign synthesis in one call: notation → plan → performed clip on the avatar.
#include <span>
#include <vector>

#include "gestura/sign/sign_nonmanual.hpp"
#include "gestura/sign/sign_performer.hpp"

namespace gestura {

struct SignSynthesis {
  Clip clip;
  SignPlan plan;
  PerformanceStats stats;
  std::vector<NonManualWarning> warnings;  // non-manual values not performed, with their XML lines
};

SignSynthesis synthesize_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& plan_options = {},
                              const PerformOptions& perform_options = {});
// The same with the sign's non-manual tiers (SiGML) performed over [plan.sign_start, plan.sign_end]
// (sign_nonmanual.hpp); values it cannot perform end up in `warnings`, never as an error. The
// hands' penetration (stats) is measured again on the final clip, as the body may have moved.
SignSynthesis synthesize_sign(const sign::HamSign& sign, std::span<const sign::NonManual> nonmanual,
                              const SigningRig& rig, const PlanOptions& plan_options = {},
                              const PerformOptions& perform_options = {});

// Why a synthesized sign is not acceptable (NaN, joint limits broken, hand inside the body deeper
// than `max_penetration`), or nullopt when it is.
std::optional<std::string> synthesis_problem(const SignSynthesis& result, const SigningRig& rig,
                                             float max_penetration = 0.01f);

// Connects `gestura check` (sign_check.hpp) to synthesis on the default avatar.
void connect_synthesis_to_check();

}  // namespace gestura
