#include "gestura/face/head_motion.hpp"

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

float envelope(const HeadAction& a, float t) {
  const float ramp = default_ramp(a.end - a.start);
  return action_weight(FaceAction{"", a.start, a.end, 1.0f, ramp, ramp}, t);
}

}  // namespace

vec3 head_angles(std::span<const HeadAction> actions, float t) {
  vec3 angles(0.0f);
  for (const HeadAction& a : actions) {
    float v = a.amplitude * envelope(a, t);
    if (a.frequency > 0.0f) v *= std::sin(2.0f * std::numbers::pi_v<float> * a.frequency * (t - a.start));
    angles[static_cast<int>(a.axis)] += v;
  }
  return angles;
}

void write_head_rotations(std::span<const HeadAction> actions, const Skeleton& skeleton, Clip& clip) {
  if (actions.empty()) return;
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const HeadAction& a = actions[i];
    if (!std::isfinite(a.start) || !std::isfinite(a.end) || !std::isfinite(a.amplitude) ||
        !std::isfinite(a.frequency) || a.frequency < 0.0f || a.frequency > 100.0f)
      throw Error("head action " + std::to_string(i) + ": non-finite or out-of-range value");
    if (a.end < a.start) throw Error("head action " + std::to_string(i) + ": ends before it starts");
    if (a.end - a.start > 3600.0f) throw Error("head action " + std::to_string(i) + ": longer than an hour");
  }
  const int neck = skeleton.find("vc4"), skull = skeleton.find("skullbase");
  if (neck < 0 || skull < 0) throw Error("head motion needs joints 'vc4' and 'skullbase' in the skeleton");
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  if (clip.joint_count() != skeleton.size())
    throw Error("clip '" + clip.name + "' has tracks for " + std::to_string(clip.joint_count()) +
                " joints, the skeleton has " + std::to_string(skeleton.size()));

  std::vector<float> times;
  for (const HeadAction& a : actions) {
    const float ramp = default_ramp(a.end - a.start);
    for (int k = 0; k <= kRampSteps; ++k) {
      const float f = static_cast<float>(k) / kRampSteps;
      times.push_back(a.start + f * ramp);
      times.push_back(a.end - f * ramp);
    }
    if (a.frequency > 0.0f) {
      const float step = 1.0f / (a.frequency * kStepsPerCycle);
      for (float t = a.start; t < a.end; t += step) times.push_back(t);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](float x, float y) { return y - x < 1e-4f; }),
              times.end());

  std::vector<vec3> neck_angles, skull_angles;
  for (float t : times) {
    const vec3 angles = head_angles(actions, t);
    neck_angles.push_back(angles * kNeckShare);
    skull_angles.push_back(angles * (1.0f - kNeckShare));
  }
  auto write = [&](int joint, const std::vector<vec3>& angles) {
    const auto j = static_cast<std::size_t>(joint);
    QuatTrack track = rotation_track_from_euler(times, angles, skeleton.dofs[j].order);
    for (quat& q : track.values) q = skeleton.rest_rotations[j] * q;
    make_continuous(track);
    clip.rotations[j] = std::move(track);
  };
  write(neck, neck_angles);
  write(skull, skull_angles);
  if (!times.empty()) clip.duration = std::max(clip.duration, times.back());
}

}  // namespace gestura::face
