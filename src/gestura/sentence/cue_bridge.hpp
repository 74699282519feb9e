#pragma once
// Coarticulation across subtitle cues: when one cue's signing ends shortly before the next one's
// begins, a signer does not drop the hands to rest in between; the arms go straight from the last
// sign of one cue to the first sign of the next. On a programme clip where both performances are
// placed (anim/clip_timeline.hpp), this replaces what the arms and hands do between the two
// instants — the return to rest, the rest, the approach from rest — by a minimum-jerk
// interpolation in joint space from the posture at `from` to the posture at `to`.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// Gaps shorter than this (seconds, from the last sign's end to the next cue's first sign) are
// bridged; in longer ones the signer rests.
inline constexpr float kCoarticulationGap = 1.0f;

// Bridges the arm and finger tracks (H-Anim l_/r_ sternoclavicular … wrist, thumb1 … pinky3) of
// `clip` over (from, to), keyed at `fps`. Tracks without keys are left alone. Throws gestura::Error
// when from >= to or either is not finite.
void bridge_arms(Clip& clip, const Skeleton& skeleton, float from, float to, float fps = 30.0f);

}  // namespace gestura
