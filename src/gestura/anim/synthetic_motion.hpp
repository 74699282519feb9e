#pragma once
// A deterministic test subject for motion tools and benchmarks: a 67-joint humanoid with H-Anim 1.1
// names and a smooth clip on it.
//
// Skeleton (67 joints): humanoid_root, sacroiliac; per leg hip, knee, ankle, midtarsal; vl5, vt12,
// vt6, vt1, vc4, skullbase, temporomandibular, both eyeballs; per arm sternoclavicular, shoulder,
// elbow, wrist, and per finger (thumb, index, middle, ring, pinky) three joints and a tip site.
// Rest: standing, arms in a T along ±X, fingers along the arm, bones 2–45 cm.
//
// Clip: every joint except the tip sites rotates about all three axes; each Euler angle is
//     θ(t) = Σ_{k=1..3} (A / k) · sin(2π f_k t + φ_k),   A = 0.35 rad (fingers 0.6), f_k ∈ [0.15, 1.35] Hz,
// with f_k and φ_k drawn from a fixed linear congruential sequence seeded by joint and axis, so the
// same call always gives the same clip. The root also translates (sway ±4 cm, bob ±2 cm). Keys are
// at every 1/rate s with linear interpolation (nlerp for rotations). Scales stay 1.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

Skeleton synthetic_humanoid();
Clip synthetic_clip(const Skeleton& skeleton, float seconds = 15.0f, float rate = 30.0f);

}  // namespace gestura
