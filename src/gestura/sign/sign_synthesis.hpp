#pragma once
// Sign synthesis in one call: notation → plan → performed clip on the avatar.
#include <span>
#include <vector>

#include "gestura/sign/sign_check.hpp"
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

// What a performed sign may deviate from its plan and still count as the notated sign.
//   penetration: a hand point this deep inside the (capsule) body is visible as a hand in the body.
//   position / orientation: the IK residual at the plan's key postures (PerformanceStats::key_*).
//   At the body, signers vary a location by a couple of centimetres between repetitions, and a
//   contact site is about finger-width; 2 cm keeps a touch a touch. A place out in the signing
//   space (neutral space, "near" a site) is a region a hand's width across: 5 cm. Orientation is read at the
//   resolution of the notation's own symbols: neighbouring extended-finger directions and palm
//   orientations are 45° apart, so within 25° the hand still reads as the notated symbol and not
//   its neighbour.
struct SynthesisTolerance {
  float penetration = 0.01f;      // metres
  float position = 0.02f;         // metres, at the body
  float space_position = 0.05f;   // metres, out in the signing space
  float orientation = deg(25.0f); // radians
};

// Why a synthesized sign is not acceptable (NaN, joint limits broken, hand inside the body or
// away from its planned posture beyond `tolerance`), or nullopt when it is.
std::optional<std::string> synthesis_problem(const SignSynthesis& result, const SigningRig& rig,
                                             const SynthesisTolerance& tolerance = {});

// The synthesis step of `gestura check` (sign_check.hpp) on `rig`: synthesizes each sign with its
// non-manual tiers and judges it with synthesis_problem; an error thrown on the way is the reason.
// Contract: `rig` outlives the returned function.
sign::SynthesisCheck synthesis_check(const SigningRig& rig);

}  // namespace gestura
