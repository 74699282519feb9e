#include "gestura/sentence/role_shift.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "gestura/face/eye_aim.hpp"
#include "gestura/face/eye_gaze.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/sentence/signing_space.hpp"

namespace gestura {

namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;
constexpr int kRampSteps = 8;
constexpr float kGazeReach = 1.5f;  // the eyes look at the quoted person this far out

float ramp_of(const TimedRoleShift& s) { return std::min(kRoleShiftRamp, (s.end - s.start) / 3.0f); }

float direction_of(const TimedRoleShift& s) { return locus_yaw(s.toward) >= 0.0f ? 1.0f : -1.0f; }

}  // namespace

float role_shift_weight(std::span<const TimedRoleShift> shifts, float t, float* direction) {
  float best = 0.0f;
  for (const TimedRoleShift& s : shifts) {
    const float ramp = ramp_of(s);
    if (ramp <= 0.0f || t <= s.start - ramp || t >= s.end + ramp) continue;
    // In over the ramp before the first gloss, out over the ramp after the last.
    const float in = std::clamp((t - (s.start - ramp)) / ramp, 0.0f, 1.0f);
    const float out = std::clamp(((s.end + ramp) - t) / ramp, 0.0f, 1.0f);
    const float w = 0.5f - 0.5f * std::cos(std::numbers::pi_v<float> * std::min(in, out));
    if (w > best) {
      best = w;
      if (direction) *direction = direction_of(s);
    }
  }
  return best;
}

std::vector<face::HeadAction> role_shift_head_actions(std::span<const TimedRoleShift> shifts) {
  std::vector<face::HeadAction> out;
  for (const TimedRoleShift& s : shifts) {
    if (!(s.end > s.start)) continue;
    // Head actions ramp inside their span: widen it by the ramp so the head turns with the torso.
    const float ramp = ramp_of(s);
    out.push_back({face::HeadAxis::yaw, std::max(0.0f, s.start - ramp), s.end + ramp,
                   direction_of(s) * kRoleShiftHeadDegrees * kDegree, 0.0f});
  }
  return out;
}

void write_role_shift_torso(std::span<const TimedRoleShift> shifts, const Skeleton& skeleton, Clip& clip) {
  if (shifts.empty()) return;
  if (clip.joint_count() == 0) clip.resize_joints(skeleton.size());
  std::vector<float> times;
  for (const TimedRoleShift& s : shifts) {
    const float ramp = ramp_of(s);
    if (ramp <= 0.0f) continue;
    for (int k = 0; k <= kRampSteps; ++k) {
      const float f = static_cast<float>(k) / kRampSteps;
      times.push_back(std::max(0.0f, s.start - ramp + f * ramp));
      times.push_back(s.end + f * ramp);
    }
  }
  if (times.empty()) return;
  // The spine's share of the turn, lower to upper.
  constexpr std::array<std::pair<const char*, float>, 3> kShares{{{"vt12", 0.28f}, {"vt6", 0.36f}, {"vt1", 0.36f}}};
  for (const auto& [name, share] : kShares) {
    const int joint = skeleton.find(name);
    if (joint < 0) continue;
    const auto j = static_cast<std::size_t>(joint);
    QuatTrack& track = clip.rotations[j];
    std::vector<float> all = times;
    all.insert(all.end(), track.times.begin(), track.times.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end(), [](float a, float b) { return b - a < 1e-4f; }), all.end());
    QuatTrack out;
    out.interpolation = Interpolation::Slerp;
    for (float t : all) {
      float direction = 1.0f;
      const float w = role_shift_weight(shifts, t, &direction);
      const quat base = track.empty() ? skeleton.rest_rotations[j] : sample_track(track, t);
      const quat turn = glm::angleAxis(direction * w * share * kRoleShiftTorsoDegrees * kDegree, vec3(0.0f, 1.0f, 0.0f));
      out.add(t, base * turn);
    }
    make_continuous(out);
    track = std::move(out);
  }
}

void write_gaze_with_role_shift(std::span<const TimedRoleShift> shifts, const SigningRig& rig, Clip& clip, float fps) {
  const Skeleton& skeleton = rig.skeleton();
  if (shifts.empty()) {
    face::write_eye_gaze(skeleton, clip, fps);
    return;
  }
  const int channel = clip.find_channel(std::string(face::kGazeHands));
  const FloatTrack hands = channel >= 0 ? clip.channels[static_cast<std::size_t>(channel)] : FloatTrack{};
  const int wrist = skeleton.find("r_wrist"), knuckle = skeleton.find("r_middle1"), head = skeleton.find("skullbase");
  const float eye_height = head >= 0 ? rig.bind_model[static_cast<std::size_t>(head)][3].y + 0.08f : 1.6f;
  const float end = std::max(clip.duration, clip.end_time());
  const int frames = static_cast<int>(std::ceil(end * fps)) + 1;
  std::vector<float> times(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f) times[static_cast<std::size_t>(f)] = std::min(static_cast<float>(f) / fps, end);
  face::write_gaze(skeleton, times, [&](float t, std::span<const mat4> model) {
    const float w = hands.empty() ? 0.0f : sample_track(hands, t);
    if (w > 0.01f && wrist >= 0 && knuckle >= 0)
      return face::GazeTarget{0.5f * (vec3(model[static_cast<std::size_t>(wrist)][3]) + vec3(model[static_cast<std::size_t>(knuckle)][3])), w, w};
    // The place of the shift in force, at eye height.
    Locus toward;
    float best = 0.0f;
    for (const TimedRoleShift& s : shifts) {
      const float r = role_shift_weight(std::span<const TimedRoleShift>(&s, 1), t);
      if (r > best) best = r, toward = s.toward;
    }
    vec3 point = locus_point(rig, toward, kGazeReach);
    point.y = eye_height;
    return face::GazeTarget{point, best, 0.0f};
  }, clip);
  clip.duration = std::max(clip.duration, end);
}

}  // namespace gestura
