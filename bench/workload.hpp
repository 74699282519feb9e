#pragma once
// Deterministic benchmark workloads, stable across changes so numbers compare (DESIGN.md W1–W8).
//
// workload_skeleton(): 67 joints shaped like a humanoid tree — root, a 6-joint spine/neck/head column,
// 4 head joints (jaw, eyes, top), two 4-joint legs, two 4-joint arms each ending in a 20-joint hand
// (5 fingers × 3 phalanges + tip) — parents before children, 0.02–0.45 m offsets.
// workload_clip(): 15 s, keys at 30 Hz (451 per track), a rotation track on every joint and a
// translation track on the root. Each Euler angle is a sum of three sines (0.2–2.2 Hz, 0.05–0.35 rad)
// whose parameters come from a fixed linear congruential sequence, so the motion is smooth and the
// same on every machine.
#include "gestura/anim/clip.hpp"

namespace gestura::bench {

Skeleton workload_skeleton();
Clip workload_clip(const Skeleton& skeleton, float duration = 15.0f, float key_rate = 30.0f);

}  // namespace gestura::bench
