// W4 — inverse kinematics. Two-bone and aim on plain model-space data (references: ozz-animation
// two-bone 0.16 µs, aim 0.10 µs per solve); CCD, damped least squares and the combined method
// (8 CCD sweeps, then DLS) on the 7-DoF reference
// arm with anatomical limits, each solve starting from the ready posture toward one of 64 reachable
// targets (forward kinematics of poses drawn inside the limits). Counters: iterations and residual
// (metres) averaged over the solves, the worst residual, and the fraction reached within 0.1 mm.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gestura/ik/aim.hpp"
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/reference_arm.hpp"
#include "gestura/ik/two_bone.hpp"

namespace {

using namespace gestura;

std::vector<vec3> reachable_targets(const Skeleton& arm, int count) {
  std::uint64_t state = 12345;  // the same 64 targets in every run and repetition
  auto next_uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  };
  std::vector<vec3> targets;
  std::vector<mat4> model(arm.size());
  const int site = arm.find("l_hand_site");
  for (int t = 0; t < count; ++t) {
    Pose pose = rest_pose(arm);
    for (std::size_t j = 0; j < arm.size(); ++j) {
      const JointDofs& d = arm.dofs[j];
      vec3 a(0.0f);
      for (int axis = 0; axis < 3; ++axis)
        if (d.free(axis)) a[axis] = d.min_angle[axis] + (d.max_angle[axis] - d.min_angle[axis]) * (0.1f + 0.8f * next_uniform());
      if (d.axes) pose.rotations[j] = joint_rotation(arm, static_cast<int>(j), a);
    }
    local_to_model(arm, pose, model);
    targets.push_back(vec3(model[site][3]));
  }
  return targets;
}

void BM_W4_TwoBone(benchmark::State& state) {
  TwoBoneInput in;
  in.start = vec3(0.18f, 1.4f, 0.0f), in.mid = vec3(0.18f, 1.1f, 0.0f), in.end = vec3(0.18f, 0.84f, 0.0f);
  in.start_rotation = in.mid_rotation = quat(1, 0, 0, 0);
  in.mid_axis = vec3(-1, 0, 0);
  in.pole = vec3(0.6f, 1.0f, -0.5f);
  in.soften = 0.97f;
  const vec3 targets[4] = {vec3(0.3f, 1.2f, 0.3f), vec3(0.1f, 1.3f, 0.35f), vec3(0.4f, 1.0f, 0.2f), vec3(0.25f, 1.5f, 0.3f)};
  std::size_t k = 0;
  for (auto _ : state) {
    in.target = targets[k++ & 3];
    benchmark::DoNotOptimize(in.target);
    TwoBoneResult r = solve_two_bone(in);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_W4_TwoBone);

void BM_W4_Aim(benchmark::State& state) {
  AimInput in;
  in.position = vec3(0.0f, 1.6f, 0.05f);
  in.rotation = glm::angleAxis(0.2f, vec3(0, 1, 0));
  in.parent_rotation = glm::angleAxis(0.1f, vec3(1, 0, 0));
  const vec3 targets[4] = {vec3(1, 2, 1), vec3(-1, 1.5f, 2), vec3(0.3f, 1.2f, 1), vec3(0, 1.8f, 3)};
  std::size_t k = 0;
  for (auto _ : state) {
    in.target = targets[k++ & 3];
    benchmark::DoNotOptimize(in.target);
    quat q = aim_local_rotation(in);
    benchmark::DoNotOptimize(q);
  }
}
BENCHMARK(BM_W4_Aim);

template <IkResult (*Solve)(const Skeleton&, const IkChain&, const mat4&, const IkTarget&, const IkSettings&,
                            IkWorkspace&, Pose&)>
void BM_W4_Arm(benchmark::State& state) {
  const Skeleton arm = reference_arm_skeleton();
  const IkChain chain = arm_chain(arm);
  IkWorkspace ws(chain);
  const Pose ready = arm_ready_pose(arm);
  Pose pose = ready;
  const std::vector<vec3> targets = reachable_targets(arm, 64);
  const IkSettings settings;
  double iterations = 0.0, residual = 0.0, worst = 0.0, reached = 0.0;
  std::size_t k = 0, solves = 0;
  for (auto _ : state) {
    std::copy(ready.rotations.begin(), ready.rotations.end(), pose.rotations.begin());
    const IkResult r = Solve(arm, chain, mat4(1.0f), IkTarget{targets[k++ & 63]}, settings, ws, pose);
    benchmark::DoNotOptimize(pose.rotations.data());
    iterations += r.iterations;
    residual += r.position_error;
    worst = std::max(worst, static_cast<double>(r.position_error));
    reached += r.position_error < 1e-4f ? 1.0 : 0.0;
    ++solves;
  }
  state.counters["iterations"] = iterations / static_cast<double>(solves);
  state.counters["residual_m"] = residual / static_cast<double>(solves);
  state.counters["worst_residual_m"] = worst;
  state.counters["reached_0.1mm"] = reached / static_cast<double>(solves);  // fraction of solves
}
BENCHMARK(BM_W4_Arm<solve_ccd>)->Name("BM_W4_CcdArm7Dof");
BENCHMARK(BM_W4_Arm<solve_dls>)->Name("BM_W4_DlsArm7Dof");
IkResult combined(const Skeleton& s, const IkChain& c, const mat4& b, const IkTarget& t, const IkSettings& st, IkWorkspace& ws,
                  Pose& p) {
  return solve_combined(s, c, b, t, st, ws, p);
}
BENCHMARK(BM_W4_Arm<combined>)->Name("BM_W4_CombinedArm7Dof");

}  // namespace
