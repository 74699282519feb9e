#include "gestura/sign/sign_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "gestura/anim/sampler.hpp"
#include "gestura/sign/hand_geometry.hpp"

namespace gestura {

SignSynthesis synthesize_sign(const sign::HamSign& sign, const SigningRig& rig, const PlanOptions& plan_options,
                              const PerformOptions& perform_options) {
  SignSynthesis out;
  out.plan = plan_sign(sign, rig, plan_options);
  out.clip = perform_plan(out.plan, rig, perform_options, &out.stats);
  return out;
}

namespace {

std::string fixed(float v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(v));
  return buf;
}

}  // namespace

SignSynthesis synthesize_sign(const sign::HamSign& sign, std::span<const sign::NonManual> nonmanual,
                              const SigningRig& rig, const PlanOptions& plan_options,
                              const PerformOptions& perform_options) {
  SignSynthesis out = synthesize_sign(sign, rig, plan_options, perform_options);
  if (nonmanual.empty()) return out;
  out.warnings = add_sign_nonmanuals(nonmanual, out.plan.sign_start, out.plan.sign_end, rig, perform_options.fps, out.clip);
  // A lean, a raised shoulder or a turned head moves the hands or the body after the arm solver
  // kept them apart: measure again on the final clip.
  const Skeleton& s = rig.skeleton();
  Pose pose;
  std::vector<mat4> model(s.size());
  HandPoints points;
  for (int f = 0; f < out.stats.frames; ++f) {
    sample_clip(out.clip, static_cast<float>(f) / perform_options.fps, WrapMode::Clamp, rig.rest, pose);
    local_to_model(s, pose, model);
    for (const HandRig& h : rig.hands)
      out.stats.max_penetration = std::max(out.stats.max_penetration, hand_penetration(rig, h.hand, model, points));
  }
  return out;
}

std::optional<std::string> synthesis_problem(const SignSynthesis& result, const SigningRig& rig,
                                             const SynthesisTolerance& tolerance) {
  const Skeleton& s = rig.skeleton();
  for (std::size_t j = 0; j < result.clip.rotations.size(); ++j) {
    const QuatTrack& tr = result.clip.rotations[j];
    for (std::size_t k = 0; k < tr.values.size(); ++k) {
      if (!is_finite(tr.values[k])) return "NaN in joint '" + s.names[j] + "' at " + std::to_string(tr.times[k]) + " s";
      if (!within_limits(s, static_cast<int>(j), tr.values[k]))
        return "joint '" + s.names[j] + "' outside its limits at " + std::to_string(tr.times[k]) + " s";
    }
  }
  const PerformanceStats& st = result.stats;
  if (st.max_penetration > tolerance.penetration)
    return "hand inside the body by " + fixed(st.max_penetration * 100.0f, 1) + " cm";
  std::string ik;
  if (st.key_position_error > tolerance.position)
    ik = "hand " + fixed(st.key_position_error * 100.0f, 1) + " cm from its planned place at the body at " +
         fixed(st.key_position_time, 2) + " s";
  else if (st.key_space_position_error > tolerance.space_position)
    ik = "hand " + fixed(st.key_space_position_error * 100.0f, 1) + " cm from its planned place in space at " +
         fixed(st.key_space_position_time, 2) + " s";
  if (st.key_orientation_error > tolerance.orientation)
    ik += std::string(ik.empty() ? "hand" : ";") + " turned " + fixed(to_degrees(st.key_orientation_error), 0) +
          "° from its planned orientation at " + fixed(st.key_orientation_time, 2) + " s";
  if (!ik.empty()) return "IK: " + ik;
  return std::nullopt;
}

sign::SynthesisCheck synthesis_check(const SigningRig& rig) {
  return [&rig](const sign::HamSign& sign, std::span<const sign::NonManual> nonmanual) -> std::optional<std::string> {
    try {
      const SignSynthesis result = synthesize_sign(sign, nonmanual, rig);
      return synthesis_problem(result, rig);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
  };
}

}  // namespace gestura
