#include "gestura/sentence/clip_sign_motion.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gestura/anim/track.hpp"
#include "gestura/core/error.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/hand_timeline.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

namespace gestura {

namespace {

// Samples per second of the clip: as a notated sign's citation form is sampled.
constexpr float kClipRate = 40.0f;
// The plan read back from the clip has a segment every this many seconds (it places transitions
// and via postures; the motion itself is the sampled joints).
constexpr float kPlanStep = 0.1f;
// A palm this close to the body is at it (HandState::at_body).
constexpr float kAtBody = 0.02f;

float angle_between(const quat& a, const quat& b) {
  return 2.0f * std::acos(std::clamp(std::abs(glm::dot(glm::normalize(a), glm::normalize(b))), 0.0f, 1.0f));
}

// What the hand does at citation time t, read from the sampled joints by forward kinematics on the
// relaxed posture (the rest of the body as the utterance performs it).
HandState state_at(const CitationMotion& motion, const SigningRig& rig, Hand hand, float t, Pose& pose,
                   std::vector<mat4>& model) {
  const Skeleton& s = rig.skeleton();
  const std::vector<int> joints = hand_motion_joints(rig, hand);
  std::vector<quat> posture(joints.size());
  motion.sample(hand, t, posture);
  for (std::size_t j = 0; j < joints.size(); ++j) pose.rotations[joint_slot(joints[j])] = posture[j];
  local_to_model(s, pose, model);
  const HandRig& h = rig.hand(hand);
  const mat4& wrist = model[joint_slot(h.wrist)];
  HandState state = relaxed_hand_state(rig, hand);
  state.active = true;
  state.position = vec3(wrist * vec4(h.palm_centre_local, 1.0f));
  const quat wrist_rotation = glm::normalize(glm::quat_cast(mat3(wrist)));
  state.orientation = glm::normalize(wrist_rotation * glm::inverse(h.rest_wrist_rotation) * h.rest_frame.rotation);
  // The fingers' flexion, read as each joint's turn from rest (a keyframed finger bends about its
  // flexion axis); the thumb keeps the relaxed hand's.
  for (std::size_t f = 1; f < 5; ++f) {
    FingerFlexion& flex = state.shape.fingers[f - 1];
    float* angles[3] = {&flex.mcp, &flex.pip, &flex.dip};
    for (std::size_t k = 0; k < 3; ++k) {
      const int j = h.fingers[f][k];
      *angles[k] = angle_between(pose.rotations[joint_slot(j)], s.rest_rotations[joint_slot(j)]);
    }
  }
  state.at_body = body_signed_distance(rig, rig.bind_model, state.position) < kAtBody;
  return state;
}

}  // namespace

std::unique_ptr<ClipSignMotion> clip_sign_motion(const Clip& clip, const SigningRig& rig, std::string_view gloss) {
  const Skeleton& s = rig.skeleton();
  const std::string what = "clip sign '" + std::string(gloss) + "'";
  if (clip.joint_count() != s.size())
    throw Error(what + " has " + std::to_string(clip.joint_count()) + " joints; the avatar has " + std::to_string(s.size()));
  const float duration = std::max(clip.duration, 1.0f / kClipRate);
  const int frames = std::max(2, static_cast<int>(std::ceil(duration * kClipRate - 1e-3f)) + 1);

  auto out = std::make_unique<ClipSignMotion>();
  CitationMotion& m = out->motion;
  m.rate = kClipRate;
  m.first_posture = 0.0f;
  m.frames = frames;
  ByHand<bool> moved{{false, false}};
  const float moved_radians = glm::radians(kClipHandMovedDegrees);
  for (Hand hand : kBothHands) {
    const std::vector<int> joints = hand_motion_joints(rig, hand);
    m.joints[hand] = joints.size();
    std::vector<quat>& samples = m.samples[hand];
    samples.resize(static_cast<std::size_t>(frames) * joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const std::size_t slot = joint_slot(joints[j]);
      const QuatTrack& track = clip.rotations[slot];
      std::uint32_t cursor = 0;
      for (int f = 0; f < frames; ++f) {
        const float t = std::min(static_cast<float>(f) / kClipRate, duration);
        const quat q = track.empty() ? s.rest_rotations[slot] : glm::normalize(sample_track(track, t, &cursor));
        samples[static_cast<std::size_t>(f) * joints.size() + j] = q;
        moved[hand] = moved[hand] || angle_between(q, s.rest_rotations[slot]) > moved_radians;
      }
    }
    // Neighbouring samples in one hemisphere, so the performer's nlerp takes the short way.
    for (int f = 1; f < frames; ++f)
      for (std::size_t j = 0; j < joints.size(); ++j) {
        quat& q = samples[static_cast<std::size_t>(f) * joints.size() + j];
        if (glm::dot(q, samples[static_cast<std::size_t>(f - 1) * joints.size() + j]) < 0.0f) q = -q;
      }
  }
  if (!moved[Hand::Right] && !moved[Hand::Left]) throw Error(what + " moves neither hand");

  // The plan: what a moved hand does, read back from its joints; a hand not moved stays out.
  m.plan.sign_start = 0.0f;
  m.plan.sign_end = duration;
  Pose pose = rig.neutral;
  std::vector<mat4> model(s.size());
  const int steps = std::max(1, static_cast<int>(std::ceil(duration / kPlanStep - 1e-3f)));
  for (Hand hand : kBothHands) {
    if (!moved[hand]) continue;
    HandTimeline& timeline = m.plan.hand(hand);
    HandState from = state_at(m, rig, hand, 0.0f, pose, model);
    for (int i = 1; i <= steps; ++i) {
      HandSegment seg;
      seg.start = duration * static_cast<float>(i - 1) / static_cast<float>(steps);
      seg.end = duration * static_cast<float>(i) / static_cast<float>(steps);
      seg.from = from;
      seg.to = state_at(m, rig, hand, seg.end, pose, model);
      seg.linear_blend = true;
      from = seg.to;
      timeline.segments.push_back(std::move(seg));
    }
  }
  // The head, neck and torso: joints outside both hands' chains that the clip turns from rest.
  out->body.resize_joints(s.size());
  out->body.duration = duration;
  std::vector<bool> in_hands(s.size(), false);
  for (Hand hand : kBothHands)
    for (const int j : hand_motion_joints(rig, hand)) in_hands[joint_slot(j)] = true;
  const float body_radians = glm::radians(kClipBodyMovedDegrees);
  for (std::size_t slot = 0; slot < s.size(); ++slot) {
    const QuatTrack& track = clip.rotations[slot];
    if (in_hands[slot] || track.empty()) continue;
    const bool turned = std::any_of(track.values.begin(), track.values.end(),
                                    [&](const quat& q) { return angle_between(q, s.rest_rotations[slot]) > body_radians; });
    if (turned) out->body.rotations[slot] = track;
  }
  for (std::size_t c = 0; c < clip.channels.size() && c < clip.channel_names.size(); ++c) {
    out->face.channel_names.push_back(clip.channel_names[c]);
    out->face.channels.push_back(clip.channels[c]);
  }
  out->face.duration = duration;
  return out;
}

std::unique_ptr<ClipSignMotion> clip_sign_in_space(const ClipSignMotion& recorded, const SignPlan& placed,
                                                   const SignMotionCache& cache) {
  auto out = std::make_unique<ClipSignMotion>(recorded);
  CitationMotion& m = out->motion;
  m.plan = placed;
  const SigningRig& rig = cache.rig();
  for (Hand hand : kBothHands) {
    const HandTimeline& timeline = placed.hand(hand);
    if (timeline.segments.empty()) continue;  // a hand the clip does not move
    const std::size_t n = m.joints[hand], arm = rig.hand(hand).arm.joints.size();
    std::vector<quat>& samples = m.samples[hand];
    std::vector<quat> seed(n);
    for (int f = 0; f < m.frames; ++f) {
      quat* row = &samples[static_cast<std::size_t>(f) * n];
      // Seeded by the recorded posture, its arm by the frame solved before (one arm configuration
      // throughout).
      seed.assign(row, row + n);
      if (f > 0) std::copy_n(row - n, arm, seed.begin());
      const float t = std::min(static_cast<float>(f) / m.rate, m.movement());
      const HandJointPosture solved = cache.solve_from(hand, sample_hand(timeline, t), seed);
      for (std::size_t j = 0; j < arm; ++j) {
        row[j] = solved[j];
        if (f > 0 && glm::dot(row[j], row[j - n]) < 0.0f) row[j] = -row[j];
      }
    }
  }
  return out;
}

// How much of a clip sign's channels is laid over the utterance at time t: all of it between start
// and end, easing in and out over kClipFaceFade on either side.
static float clip_fade(float t, float start, float end) {
  auto ease = [](float x) { return x * x * (3.0f - 2.0f * x); };
  if (t < start) return ease(std::clamp((t - (start - kClipFaceFade)) / kClipFaceFade, 0.0f, 1.0f));
  if (t > end) return ease(std::clamp((end + kClipFaceFade - t) / kClipFaceFade, 0.0f, 1.0f));
  return 1.0f;
}
void add_clip_sign_body(const ClipSignFace& sign, const Skeleton& skeleton, float fps, Clip& out) {
  if (!sign.body) return;
  const float a = sign.start - kClipFaceFade, b = sign.end + kClipFaceFade;
  const float step = 1.0f / std::clamp(fps, 1.0f, 240.0f);
  out.resize_joints(std::max(out.joint_count(), skeleton.size()));
  for (std::size_t slot = 0; slot < sign.body->rotations.size() && slot < skeleton.size(); ++slot) {
    const QuatTrack& mine = sign.body->rotations[slot];
    if (mine.empty()) continue;
    const quat rest = skeleton.rest_rotations[slot];
    const QuatTrack base = out.rotations[slot];  // a copy: rebuilt below
    QuatTrack merged;
    merged.interpolation = base.empty() ? Interpolation::Slerp : base.interpolation;
    for (std::size_t k = 0; k < base.times.size() && base.times[k] < a; ++k) merged.add(base.times[k], base.values[k]);
    std::uint32_t cursor = 0;
    for (float t = std::max(0.0f, a);; t = std::min(t + step, b)) {
      const float weight = clip_fade(t, sign.start, sign.end);
      const float citation = std::clamp((t - sign.moving) * sign.tempo, 0.0f, sign.body->duration);
      const quat below = base.empty() ? rest : glm::normalize(sample_track(base, t));
      // The clip's turn from rest, in the joint's own frame, laid over what the utterance does.
      const quat turn = glm::normalize(glm::inverse(rest) * glm::normalize(sample_track(mine, citation, &cursor)));
      merged.add(t, glm::normalize(below * glm::slerp(quat(1, 0, 0, 0), turn, weight)));
      if (t >= b) break;
    }
    for (std::size_t k = 0; k < base.times.size(); ++k)
      if (base.times[k] > b) merged.add(base.times[k], base.values[k]);
    make_continuous(merged);
    out.rotations[slot] = std::move(merged);
  }
}

void add_clip_sign_face(const ClipSignFace& sign, float fps, Clip& out) {
  if (!sign.face) return;
  const float a = sign.start - kClipFaceFade, b = sign.end + kClipFaceFade;
  const float step = 1.0f / std::clamp(fps, 1.0f, 240.0f);
  for (std::size_t c = 0; c < sign.face->channels.size(); ++c) {
    const FloatTrack& mine = sign.face->channels[c];
    if (mine.empty()) continue;
    const FloatTrack base = out.channel(sign.face->channel_names[c]);  // a copy: rebuilt below
    FloatTrack merged;
    for (std::size_t k = 0; k < base.times.size() && base.times[k] < a; ++k) merged.add(base.times[k], base.values[k]);
    std::uint32_t cursor = 0;
    for (float t = std::max(0.0f, a);; t = std::min(t + step, b)) {
      const float weight = clip_fade(t, sign.start, sign.end);
      const float citation = std::clamp((t - sign.moving) * sign.tempo, 0.0f, sign.face->duration);
      const float below = base.empty() ? 0.0f : sample_track(base, t);
      merged.add(t, std::clamp(below + weight * sample_track(mine, citation, &cursor), 0.0f, 1.0f));
      if (t >= b) break;
    }
    for (std::size_t k = 0; k < base.times.size(); ++k)
      if (base.times[k] > b) merged.add(base.times[k], base.values[k]);
    out.channel(sign.face->channel_names[c]) = std::move(merged);
  }
}

}  // namespace gestura
