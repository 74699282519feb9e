#pragma once
// How far a walker's path stays from what is in its way, measured in the floor plan: the horizontal
// distance from a path segment to every part of an obstacle between the climbable step height and
// the top of the walker's head (alias-movement-through-environments.txt §7.2: "a bounding region
// around the character" that must fit through the floor plan). The walker is a vertical cylinder;
// a path whose segments all keep `radius` of clearance is collision-free for it.
#include "gestura/world/environment.hpp"

namespace gestura {

struct Clearance {
  float distance = 0.0f;   // metres, horizontal; `search` when nothing is that near
  vec2 obstacle{0.0f};     // nearest obstacle point (x, z)
  vec2 on_path{0.0f};      // nearest point of the segment (x, z)
  int object = -1;         // the obstacle's object, -1 when none was found
};

// Contract: a and b on the walking surface (their y the ground heights). Only obstacles within
// `search` are considered.
Clearance segment_clearance(const Environment& env, const vec3& a, const vec3& b, float body_height, float search);

// 2D helpers (x, z as vec2).
float cross2(const vec2& a, const vec2& b);
float point_segment_distance2(const vec2& p, const vec2& a, const vec2& b, vec2* closest = nullptr);
// Distance between two segments in the plane (0 when they cross).
float segment_segment_distance2(const vec2& p0, const vec2& p1, const vec2& q0, const vec2& q1, vec2* on_p = nullptr,
                                vec2* on_q = nullptr);

}  // namespace gestura
