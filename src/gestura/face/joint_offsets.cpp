#include "gestura/face/joint_offsets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/face/face_action.hpp"

namespace gestura::face {
namespace {

constexpr int kRampSteps = 8;
constexpr int kStepsPerCycle = 16;

void check(const JointOffset& o, std::size_t index) {
  const auto where = [&] { return "joint offset " + std::to_string(index) + " ('" + std::string(o.joint) + "')"; };
  if (!std::isfinite(o.start) || !std::isfinite(o.end) || !std::isfinite(o.ramp_in) || !std::isfinite(o.ramp_out) ||
      !std::isfinite(o.frequency) || !std::isfinite(o.angles.x) || !std::isfinite(o.angles.y) ||
      !std::isfinite(o.angles.z))
    throw Error(where() + ": non-finite time, ramp, frequency or angle");
  if (o.end < o.start) throw Error(where() + ": ends before it starts");
  if (o.end - o.start > 3600.0f) throw Error(where() + ": longer than an hour");
  if (o.frequency < 0.0f || o.frequency > 100.0f) throw Error(where() + ": frequency outside 0–100 Hz");
  if (o.ramp_in < 0 || o.ramp_out < 0 || o.ramp_in + o.ramp_out > (o.end - o.start) * 1.0001f + 1e-6f)
    throw Error(where() + ": ramps are negative or longer than the offset");
}

vec3 one_offset(const JointOffset& o, float t) {
  float w = action_weight(FaceAction{o.joint, o.start, o.end, 1.0f, o.ramp_in, o.ramp_out}, t);
  if (o.frequency > 0.0f) w *= std::sin(2.0f * std::numbers::pi_v<float> * o.frequency * (t - o.start));
  return o.angles * w;
}

// Rewrites the tracks of `joint`'s children so that child model orientation is what it was before
// the joint's track went from `before` to `after`: child' = after⁻¹ · before · child.
void keep_children_orientation(const Skeleton& skeleton, int joint, const QuatTrack& before, const QuatTrack& after,
                               std::span<const float> joint_times, Clip& clip) {
  const quat rest = skeleton.rest_rotations[static_cast<std::size_t>(joint)];
  std::vector<float> times;
  for (std::size_t c = 0; c < skeleton.size(); ++c) {
    if (skeleton.parents[c] != joint) continue;
    const QuatTrack old = clip.rotations[c];
    times.assign(joint_times.begin(), joint_times.end());
    times.insert(times.end(), old.times.begin(), old.times.end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](float x, float y) { return y - x < 1e-4f; }), times.end());
    QuatTrack track;
    track.interpolation = Interpolation::Slerp;
    for (float t : times) {
      const quat was = before.empty() ? rest : sample_track(before, t);
      const quat child = old.empty() ? skeleton.rest_rotations[c] : sample_track(old, t);
      track.add(t, glm::normalize(glm::inverse(sample_track(after, t)) * was * child));
    }
    make_continuous(track);
    clip.rotations[c] = std::move(track);
  }
}

}  // namespace

JointOffset make_offset(std::string_view joint, vec3 angles, float start, float end, float frequency) {
  const float ramp = default_ramp(end - start);
  return JointOffset{joint, angles, start, end, ramp, ramp, frequency};
}

vec3 offset_angles(std::span<const JointOffset> offsets, std::string_view joint, float t) {
  vec3 sum(0.0f);
  for (const JointOffset& o : offsets)
    if (o.joint == joint) sum += one_offset(o, t);
  return sum;
}

std::vector<std::string_view> add_joint_offsets(std::span<const JointOffset> offsets, const Skeleton& skeleton,
                                                Clip& clip) {
  for (std::size_t i = 0; i < offsets.size(); ++i) check(offsets[i], i);
  std::vector<std::string_view> missing, joints;
  for (const JointOffset& o : offsets) {
    if (std::find(joints.begin(), joints.end(), o.joint) != joints.end() ||
        std::find(missing.begin(), missing.end(), o.joint) != missing.end())
      continue;
    (skeleton.find(o.joint) < 0 ? missing : joints).push_back(o.joint);
  }
  if (joints.empty()) return missing;
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  if (clip.joint_count() != skeleton.size())
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.joint_count()) +
                " joints, the skeleton has " + std::to_string(skeleton.size()));

  std::vector<float> times;
  for (std::string_view name : joints) {
    const int j = skeleton.find(name);
    const auto ju = static_cast<std::size_t>(j);
    const QuatTrack old = clip.rotations[ju];
    times = old.times;
    for (const JointOffset& o : offsets) {
      if (o.joint != name || o.end <= o.start) continue;
      for (int k = 0; k <= kRampSteps; ++k) {
        const float f = static_cast<float>(k) / kRampSteps;
        times.push_back(o.start + f * o.ramp_in);
        times.push_back(o.end - f * o.ramp_out);
      }
      if (o.frequency > 0.0f) {
        const float step = 1.0f / (o.frequency * kStepsPerCycle);
        for (float t = o.start; t < o.end; t += step) times.push_back(t);
      }
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](float x, float y) { return y - x < 1e-4f; }), times.end());

    const JointDofs& dofs = skeleton.dofs[ju];
    QuatTrack track;
    track.interpolation = old.empty() ? Interpolation::Slerp : old.interpolation;
    if (track.interpolation != Interpolation::Linear && track.interpolation != Interpolation::Slerp)
      track.interpolation = Interpolation::Slerp;  // the resampled keys are dense: no spline needed
    for (float t : times) {
      const quat base = old.empty() ? skeleton.rest_rotations[ju] : sample_track(old, t);
      vec3 angles = joint_angles(skeleton, j, base) + offset_angles(offsets, name, t);
      if (dofs.axes != 0)
        for (int a = 0; a < 3; ++a)
          angles[a] = dofs.free(a) ? std::clamp(angles[a], dofs.min_angle[a], dofs.max_angle[a]) : 0.0f;
      track.add(t, joint_rotation(skeleton, j, angles));
    }
    make_continuous(track);
    const bool compensate = std::any_of(offsets.begin(), offsets.end(), [&](const JointOffset& o) {
      return o.joint == name && o.children_keep_orientation;
    });
    if (compensate) keep_children_orientation(skeleton, j, old, track, times, clip);
    clip.rotations[ju] = std::move(track);
    if (!times.empty()) clip.duration = std::max(clip.duration, times.back());
  }
  return missing;
}

}  // namespace gestura::face
