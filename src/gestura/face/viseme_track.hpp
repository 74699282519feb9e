#pragma once
// Phonemes → viseme actions with coarticulation.
//
// The phonemes share [start, end] in proportion to their relative durations. Each phoneme is one
// bump on its viseme channel that overlaps its neighbours: it starts rising `o_in` before its own
// interval and is at full weight `o_in` after its start (o = 40% of the shorter of the two
// phonemes, at most 60 ms), so consecutive visemes cross-fade with sinusoidal ramps whose sum is 1
// at the boundary. (The §5.2.5 80 ms minimum ramp is for expressions; at speech rate phonemes are
// shorter than that, so visemes use this overlap instead.) The first bump starts at `start` and the
// last ends at `end`: articulation begins and ends with the interval.
//
// Lip rounding is anticipated: a rounded vowel (oh, ou, w) adds mouthPucker from the onset of the
// consonants before it (up to 200 ms early), as lips round during the preceding consonants.
//
// The jaw is separate: each phoneme also adds its jaw opening to `jaw_open` with the same bump, so
// visemes shape only the lips. The blend for the avatar: lip morphs = Σ viseme weights (clamped),
// jaw joint x = jaw_open · kJawOpenMaxDegrees, expression morphs add on top of both.
//
// `h` has no lip shape and takes the next phoneme's viseme at half weight; pauses emit nothing.
#include <span>
#include <vector>

#include "gestura/face/face_action.hpp"
#include "gestura/face/phoneme.hpp"

namespace gestura::face {

// Appends the actions to `out`. amplitude scales every weight (1 = full articulation).
// Nothing is added for an empty list or end <= start.
void append_viseme_actions(std::span<const Phoneme> phonemes, float start, float end, float amplitude,
                           std::vector<FaceAction>& out);

}  // namespace gestura::face
