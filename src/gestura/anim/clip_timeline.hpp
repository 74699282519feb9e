#pragma once
// Laying short clips end to end on one long timeline: a programme made of separately performed
// sentences, each placed at its own start time, with the body at rest in between.
//
//   Clip programme = empty_timeline(skeleton);
//   place_clip(programme, sentence_a.clip, 1.0f, skeleton);   // keys shifted by +1 s
//   place_clip(programme, sentence_b.clip, 7.5f, skeleton);
//   programme.duration = std::max(programme.duration, 10.0f); // hold rest to the end
//
// Rest in the gaps: every track a placed clip animates gets a key at the joint's rest value (0
// for channels) at the placement's start and end, unless the clip has its own key there. Clips
// that start and end at rest (the Signer's do) therefore hold rest exactly between placements; a
// clip that starts away from rest is reached by interpolating from rest across the gap.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

// The longest timeline place_clip builds: 24 hours. Times are added in double and stored as float
// seconds; at 24 hours a stored key is within 4 ms of its exact time (an eighth of a frame at 30 fps).
inline constexpr double kMaxTimelineSeconds = 24.0 * 3600.0;

// A clip with one empty track per joint of `skeleton` and duration 0.
Clip empty_timeline(const Skeleton& skeleton);

// Appends `clip`'s keys to `timeline` shifted by `start` seconds, over [start, start + clip.duration].
// Each key's programme time is computed in double and rounded to float once.
// Contract / throws gestura::Error when: `clip` does not have one track per joint of `skeleton`,
// `start` is not finite or lies before timeline.duration (placements go in time order, without
// overlap; "before" means by more than the float spacing at that time), the placement would end
// past kMaxTimelineSeconds, or a track's interpolation differs from what the timeline already
// holds for it. timeline.duration becomes start + clip.duration (rounded to float).
void place_clip(Clip& timeline, const Clip& clip, double start, const Skeleton& skeleton);

}  // namespace gestura
