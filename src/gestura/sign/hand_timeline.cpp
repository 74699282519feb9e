#include "gestura/sign/hand_timeline.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/sign/movement_timing.hpp"

namespace gestura {

namespace {

// Oscillation amplitudes: small, as a signer's wrist and fingers move in these signs.
constexpr float kNodAmplitude = 0.35f;    // radians, wrist flexion
constexpr float kSwingAmplitude = 0.30f;  // radians, side to side
constexpr float kTwistAmplitude = 0.55f;  // radians, forearm rotation
constexpr float kPlayAmplitude = 0.45f;   // radians, finger flexion

}  // namespace

quat blend_turn(const quat& from, const quat& to, float s, bool long_way) {
  // The long way between (nearly) the same turn is undefined (a full turn about any axis).
  if (!long_way || std::abs(glm::dot(from, to)) > 0.9999f) return glm::slerp(from, to, s);
  // glm::mix interpolates along the arc between the two quaternions as given: with `to` on the
  // far hemisphere from `from` that is the long way round.
  const quat far = glm::dot(from, to) > 0.0f ? -to : to;
  const quat q = glm::normalize(glm::mix(from, far, s));
  return glm::dot(q, to) < 0.0f ? -q : q;  // the same turn, written on `to`'s side (so s = 1 gives `to`)
}

HandState sample_hand(const HandTimeline& timeline, float t) {
  const auto& segs = timeline.segments;
  auto it = std::upper_bound(segs.begin(), segs.end(), t, [](float v, const HandSegment& s) { return v < s.end; });
  if (it == segs.end()) {
    HandState last = segs.back().to;
    last.body_weight = last.at_body ? 1.0f : 0.0f;
    return last;
  }
  const HandSegment& seg = *it;
  const float span = seg.end - seg.start;
  const float u = span > 0 ? std::clamp((t - seg.start) / span, 0.0f, 1.0f) : 1.0f;
  const float s = seg.linear_blend ? u : profile_progress(VelocityProfile::MinimumJerk, u);
  HandState out;
  out.active = seg.to.active || seg.from.active;
  // At the body while it stays there; a hand on its way to (from) the body settles onto (off) it
  // over the last (first) kSettleTime.
  if (seg.from.at_body && seg.to.at_body) {
    out.body_weight = 1.0f;
  } else {
    const float arriving = seg.to.at_body ? std::clamp(1.0f - (seg.end - t) / kSettleTime, 0.0f, 1.0f) : 0.0f;
    const float leaving = seg.from.at_body ? std::clamp(1.0f - (t - seg.start) / kSettleTime, 0.0f, 1.0f) : 0.0f;
    out.body_weight = std::max(arriving, leaving);
  }
  out.at_body = out.body_weight >= 0.5f;
  // `to.position` includes where the paths end; the blend carries the rest of the change.
  vec3 path_end(0.0f);
  for (const Movement& m : seg.paths) path_end += sample(m, m.duration).position;
  out.position = glm::mix(seg.from.position, seg.to.position - path_end, s);
  out.orientation = blend_turn(seg.from.orientation, seg.to.orientation, s, seg.long_turn);
  out.shape = mix(seg.from.shape, seg.to.shape, s);
  for (const Movement& m : seg.paths) out.position += sample(m, u * m.duration).position;
  out.position += seg.detour * std::sin(kPi * s);
  if (seg.oscillation != Oscillation::None && seg.oscillation_cycles > 0) {
    // Envelope so the oscillation starts and ends at rest: it rises over the first quarter cycle
    // and falls over the last, so that every swing between reaches full size (a sine envelope over
    // the whole segment left a two-cycle wag at 70 % in its middle swings and less at its ends).
    const float ramp = 0.25f / seg.oscillation_cycles;
    const float envelope = std::sin(0.5f * kPi * std::clamp(std::min(u, 1.0f - u) / ramp, 0.0f, 1.0f));
    const float wave = std::sin(2 * kPi * seg.oscillation_cycles * u) * envelope;
    const vec3 local_axis = seg.oscillation == Oscillation::Nod     ? vec3(1, 0, 0)
                            : seg.oscillation == Oscillation::Swing ? vec3(0, 0, 1)
                                                                    : vec3(0, 1, 0);
    const float amp = seg.oscillation == Oscillation::Nod     ? kNodAmplitude
                      : seg.oscillation == Oscillation::Swing ? kSwingAmplitude
                                                              : kTwistAmplitude;
    if (seg.oscillation == Oscillation::FingerPlay) {
      for (std::size_t f = 0; f < out.shape.fingers.size(); ++f) {
        if (!(seg.oscillating_fingers & finger_bit(static_cast<Finger>(f + 1)))) continue;
        // Neighbouring fingers out of phase, as in a wiggle.
        const float w = std::sin(2 * kPi * seg.oscillation_cycles * u + 1.3f * static_cast<float>(f)) * envelope;
        FingerFlexion& ff = out.shape.fingers[f];
        ff.mcp = std::clamp(ff.mcp + kPlayAmplitude * 0.5f * (1 + w), 0.0f, deg(90));
        ff.pip = std::clamp(ff.pip + kPlayAmplitude * 0.5f * (1 + w), 0.0f, deg(110));
      }
    } else {
      out.orientation = glm::normalize(out.orientation * glm::angleAxis(amp * wave, local_axis));
    }
  }
  return out;
}

}  // namespace gestura
