#pragma once
// From an utterance plan to motion without inverse kinematics per frame: the signs play their
// cached citation motion time-scaled (sign_motion_cache.hpp), everything between them — transitions
// (movement epenthesis), holds, fingerspelled letters, the drift of an unused hand to rest — is a
// minimum-jerk interpolation in joint space between postures at the ends of the plan's segments.
// Each transition's joint-space path is checked against the body (points along it, when either
// end is near the body); one that would take the hand deeper into the body than its ends is bent
// through via postures: points of the Cartesian transition solved by IK from the straight path's
// posture there, with the hand pushed out of the body (as perform_plan does for every frame) — the
// midpoint, else three points. Should the bent path still enter the body, the piece fades in its
// middle to the Cartesian path solved by IK every frame (from the joint-space posture).
#include <span>

#include "gestura/anim/clip.hpp"
#include "gestura/sentence/sign_motion_cache.hpp"

namespace gestura {

// A sign whose motion on one hand comes from the cache: on [start, end] the hand plays the
// citation motion at citation time c = clamp((t − moving) · tempo, 0, motion.movement()): held at
// its first posture until `moving`, then its movement compressed by `tempo`, then held at its last.
struct CachedSignSpan {
  Hand hand = Hand::Right;
  float start = 0.0f, moving = 0.0f, end = 0.0f;
  float tempo = 1.0f;
  const CitationMotion* motion = nullptr;
};

struct UtteranceStats {
  int frames = 0;
  int transitions = 0;        // joint-space moves with the hand signing at either end
  int via = 0;                // of those, the ones bent through a via posture to stay out of the body
  int escaped = 0;            // of those, the ones that still needed IK every frame
};

// Contract: `plan` was built so that each span's hand timeline, over [start, end], is the cached
// sign's (time-scaled) plan; spans of one hand are in time order and do not overlap; fps in [1, 240].
Clip perform_utterance(const SignPlan& plan, std::span<const CachedSignSpan> signs, SignMotionCache& cache,
                       float fps, UtteranceStats* stats = nullptr);

}  // namespace gestura
