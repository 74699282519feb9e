#pragma once
// Non-manual markers: the face and head movements that carry grammar in ASL, generated from a
// NonManualPlan.
//
//   yes/no question  brows raised (browInnerUp + browOuterUp 0.8), eyes widened 0.3, head tilted
//                    forward 8°; the last sign is held (apply_question_holds).
//   wh-question      brows lowered (browDown 0.8), eyes squinted 0.3, head tilted 5° sideways and
//                    3° forward.
//   negation         headshake: yaw ±10° at 2.5 Hz over the negated signs only, brows lowered 0.3.
//   topic            brows raised 0.7, head tilted back 3°.
//   affect           the expression's morph weights × intensity (expressions.hpp).
//   fingerspelling   gaze_hands = 1 over each fingerspelled gloss (eye_gaze.hpp aims the eyes).
//   blinks           eyeBlink_L/R, 150 ms, at every boundary and otherwise every 2–5 s (gaps from a
//                    small hash of the plan's seed, so the same plan always blinks the same).
//
// Every action spans its glosses' [first.start, last.end] and enters/leaves with §5.2.5 ramps (10% of
// its duration, at least 80 ms); overlapping actions add and clamp to [0, 1] per channel.
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/face/face_action.hpp"
#include "gestura/face/head_motion.hpp"
#include "gestura/face/nonmanual_plan.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

inline constexpr float kHeadshakeDegrees = 10.0f;
inline constexpr float kHeadshakeHz = 2.5f;
inline constexpr float kQuestionTiltDegrees = 8.0f;
inline constexpr float kBlinkSeconds = 0.15f;
inline constexpr float kQuestionHoldSeconds = 0.3f;

struct NonManualActions {
  std::vector<FaceAction> face;
  std::vector<HeadAction> head;
};

// Throws gestura::Error naming the gloss or span index for non-finite, reversed or beyond-an-hour
// gloss times, and spans that are empty or reach past the glosses.
NonManualActions plan_nonmanual(const NonManualPlan& plan);

// plan_nonmanual, then write_face_channels and write_head_rotations into the clip.
void add_nonmanual_markers(const NonManualPlan& plan, const Skeleton& skeleton, Clip& clip);

// The blink times (centres) plan_nonmanual uses, in order.
std::vector<float> blink_times(const NonManualPlan& plan);

// Holds the last sign of every yes/no question `hold` seconds longer: that gloss ends later and
// every later gloss and boundary moves by the same amount. The lead times the manual signs from the
// returned plan, so the hands and face stay together.
NonManualPlan apply_question_holds(const NonManualPlan& plan, float hold = kQuestionHoldSeconds);

}  // namespace gestura::face
