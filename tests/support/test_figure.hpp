#pragma once
// A procedural TEST FIGURE for exercising the renderer — not the avatar. Capsules per bone on a
// small H-Anim-named skeleton (spine, head, arms, five two-segment fingers per hand, legs), a dark
// long-sleeved shirt, skin-coloured hands and head, eyes with iris and pupil, a hair cap, and one
// morph target ("test_jaw_open"). Its clip waves the right hand in the signing space for 2 s.
// Test code only: small and quick to build, for the renderer's output and camera tests (the CLI,
// the benchmark and the avatar tests use the real avatar).
#include "gestura/render/subject.hpp"

namespace gestura {

// `detail` scales the tessellation: 1 ≈ 6k triangles, 2 ≈ 25k (the benchmark's size).
RenderSubject make_test_figure(int detail = 1);

}  // namespace gestura
