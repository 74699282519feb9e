#include "gestura/ik/dls.hpp"

#include <algorithm>

#include "gestura/core/error.hpp"
#include "gestura/ik/residual.hpp"

namespace gestura {
namespace {

// Solves A x = b for a symmetric positive definite m×m A (m ≤ 6, row-major) by Cholesky, in place of b.
void solve_spd(float* A, float* b, int m) {
  for (int j = 0; j < m; ++j) {
    float d = A[j * m + j];
    for (int k = 0; k < j; ++k) d -= A[j * m + k] * A[j * m + k];
    d = std::sqrt(std::max(d, 1e-20f));
    A[j * m + j] = d;
    for (int i = j + 1; i < m; ++i) {
      float s = A[i * m + j];
      for (int k = 0; k < j; ++k) s -= A[i * m + k] * A[j * m + k];
      A[i * m + j] = s / d;
    }
  }
  for (int i = 0; i < m; ++i) {  // L y = b
    float s = b[i];
    for (int k = 0; k < i; ++k) s -= A[i * m + k] * b[k];
    b[i] = s / A[i * m + i];
  }
  for (int i = m - 1; i >= 0; --i) {  // Lᵀ x = y
    float s = b[i];
    for (int k = i + 1; k < m; ++k) s -= A[k * m + i] * b[k];
    b[i] = s / A[i * m + i];
  }
}

// y = (J_active J_activeᵀ + λ²I)⁻¹ v, J stored row-major m × n.
void damped_inverse_apply(const IkWorkspace& ws, int m, int n, float lambda2, const float* v, float* y) {
  float A[36];
  for (int r = 0; r < m; ++r)
    for (int c = 0; c <= r; ++c) {
      float s = r == c ? lambda2 : 0.0f;
      for (int i = 0; i < n; ++i)
        if (ws.active[i]) s += ws.jacobian[r * n + i] * ws.jacobian[c * n + i];
      A[r * m + c] = A[c * m + r] = s;
    }
  for (int r = 0; r < m; ++r) y[r] = v[r];
  solve_spd(A, y, m);
}

}  // namespace

IkResult solve_dls(const Skeleton& skeleton, const IkChain& chain, const mat4& base, const IkTarget& target,
                   const IkSettings& settings, IkWorkspace& ws, Pose& pose) {
  const int n = static_cast<int>(chain.dof_count());
  if (!settings.preferred_angles.empty() && static_cast<int>(settings.preferred_angles.size()) != n)
    throw Error("solve_dls: preferred_angles has " + std::to_string(settings.preferred_angles.size()) +
                " angles for a chain of " + std::to_string(n) + " degrees of freedom");
  load_angles(skeleton, chain, pose, ws);
  const int m = target.has_orientation ? 6 : 3;
  const float scale = settings.orientation_scale;
  // Levenberg–Marquardt style damping: a step that raises the error is undone and retried with
  // four times the damping; an accepted step halves it again (down to settings.damping). Far,
  // unreachable targets thus settle at the closest reach instead of oscillating across the
  // singular stretched pose.
  float lambda = settings.damping;
  float posture_gain = settings.null_space_gain;  // halved with every rejected step, like λ is raised
  auto energy = [&](const IkResult& r) {
    return r.position_error * r.position_error + scale * scale * r.orientation_error * r.orientation_error;
  };
  quat effector_rotation;
  vec3 effector = chain_forward(skeleton, chain, pose, base, ws, effector_rotation);
  IkResult result = measure_residual(effector, effector_rotation, target, settings);
  while (!result.converged && result.iterations < settings.max_iterations) {
    float e[6];
    const vec3 ep = target.position - effector;
    e[0] = ep.x, e[1] = ep.y, e[2] = ep.z;
    if (m == 6) {
      const vec3 eo = scale * rotation_error(effector_rotation, target.orientation);
      e[3] = eo.x, e[4] = eo.y, e[5] = eo.z;
    }
    float norm = 0.0f;
    for (int r = 0; r < m; ++r) norm += e[r] * e[r];
    norm = std::sqrt(norm);
    if (norm > settings.max_step)
      for (int r = 0; r < m; ++r) e[r] *= settings.max_step / norm;

    for (int i = 0; i < n; ++i) {
      const vec3 a = ws.axes[i];
      const vec3 linear = glm::cross(a, effector - ws.positions[chain.dof_link[i]]);
      for (int r = 0; r < 3; ++r) ws.jacobian[r * n + i] = linear[r];
      if (m == 6)
        for (int r = 0; r < 3; ++r) ws.jacobian[(3 + r) * n + i] = scale * a[r];
      ws.active[i] = 1;
    }
    std::copy(ws.angles.begin(), ws.angles.end(), ws.previous.begin());
    // Clamping loop: at most one pass per dof, each pinning the angles that would leave their range.
    for (int pass = 0; pass <= n; ++pass) {
      float y[6];
      damped_inverse_apply(ws, m, n, lambda * lambda, e, y);
      for (int i = 0; i < n; ++i) {
        float s = 0.0f;
        if (ws.active[i])
          for (int r = 0; r < m; ++r) s += ws.jacobian[r * n + i] * y[r];
        ws.step[i] = s;
      }
      if (!settings.preferred_angles.empty() && posture_gain > 0.0f) {
        // Project the posture pull z onto the null space: z − J⁺(J z).
        float jz[6] = {};
        for (int i = 0; i < n; ++i) {
          if (!ws.active[i]) continue;
          const float z = posture_gain * (settings.preferred_angles[i] - ws.angles[i]);
          for (int r = 0; r < m; ++r) jz[r] += ws.jacobian[r * n + i] * z;
        }
        float w[6];
        // The projector uses the base damping: an inflated λ would make J⁺ ≈ 0 and let the full
        // posture pull through unprojected.
        damped_inverse_apply(ws, m, n, settings.damping * settings.damping, jz, w);
        for (int i = 0; i < n; ++i) {
          if (!ws.active[i]) continue;
          float jtw = 0.0f;
          for (int r = 0; r < m; ++r) jtw += ws.jacobian[r * n + i] * w[r];
          ws.step[i] += posture_gain * (settings.preferred_angles[i] - ws.angles[i]) - jtw;
        }
      }
      float largest = 0.0f;
      for (int i = 0; i < n; ++i) largest = std::max(largest, std::abs(ws.step[i]));
      if (largest > settings.max_angle_step)
        for (int i = 0; i < n; ++i) ws.step[i] *= settings.max_angle_step / largest;
      bool pinned = false;
      for (int i = 0; i < n; ++i) {
        if (!ws.active[i]) continue;
        const float next = ws.angles[i] + ws.step[i];
        if (next < ws.lower[i] || next > ws.upper[i]) {
          ws.active[i] = 0;
          ws.angles[i] = std::clamp(next, ws.lower[i], ws.upper[i]);
          pinned = true;
        }
      }
      if (!pinned) break;
    }
    for (int i = 0; i < n; ++i)
      if (ws.active[i]) ws.angles[i] = std::clamp(ws.angles[i] + ws.step[i], ws.lower[i], ws.upper[i]);

    const int done = result.iterations + 1;
    const IkResult before = result;
    effector = chain_forward(skeleton, chain, pose, base, ws, effector_rotation);
    result = measure_residual(effector, effector_rotation, target, settings);
    result.iterations = done;
    if (energy(result) > energy(before)) {
      std::copy(ws.previous.begin(), ws.previous.end(), ws.angles.begin());
      effector = chain_forward(skeleton, chain, pose, base, ws, effector_rotation);
      result = before;
      result.iterations = done;
      lambda *= 4.0f;
      posture_gain *= 0.5f;
      if (lambda > 100.0f) break;  // no damping makes progress: a (constrained) local minimum
    } else {
      if (energy(before) - energy(result) < 1e-14f) break;
      lambda = std::max(0.5f * lambda, settings.damping);
    }
  }
  store_angles(skeleton, chain, ws, pose);
  return result;
}

}  // namespace gestura
