#pragma once
// Timing of movements: velocity profiles that map normalised time t ∈ [0, 1] to path progress
// s ∈ [0, 1], durations from movement size and speed, and minimum-jerk transitions between
// postures (the building block for coarticulation between signs and letters).
//
// Sources for the numbers (see docs/sign-phonology.md for the full reasoning):
// - Minimum-jerk point-to-point reaching: Flash & Hogan 1985, s(t) = 10t³ − 15t⁴ + 6t⁵.
// - Sign durations: citation-form (dictionary) signs last roughly 0.5–1 s; in running signing
//   signs average ~0.4–0.5 s each (Bellugi & Fischer 1972 report ~2.3–2.5 signs/s). A lexicon
//   entry is citation form, so a single straight movement of normal size (15 cm) at normal speed
//   gets 0.3 s + 0.15 m / 0.45 m/s ≈ 0.63 s, small ≈ 0.48 s, large ≈ 0.86 s.
#include <cstdint>

#include "gestura/core/math.hpp"
#include "gestura/sign/phonology_handshape.hpp"

namespace gestura {

enum class VelocityProfile : std::uint8_t {
  Linear,          // constant speed, abrupt start/stop (only for tests and debugging)
  MinimumJerk,     // 10t³ − 15t⁴ + 6t⁵: zero velocity and acceleration at both ends
  EaseInOut,       // (1 − cos πt) / 2: zero velocity at the ends, non-zero acceleration
  ConstantRamped,  // trapezoidal speed: linear ramp up over kRampFraction, cruise, ramp down
};
inline constexpr float kRampFraction = 0.15f;

// Progress s(t), its derivative ds/dt and second derivative, for t clamped to [0, 1].
float profile_progress(VelocityProfile profile, float t);
float profile_velocity(VelocityProfile profile, float t);
float profile_acceleration(VelocityProfile profile, float t);

float minimum_jerk(float t);               // 10t³ − 15t⁴ + 6t⁵
float minimum_jerk_velocity(float t);      // 30t² − 60t³ + 30t⁴
float minimum_jerk_acceleration(float t);  // 60t − 180t² + 120t³

enum class MovementSpeed : std::uint8_t { Slow, Normal, Fast };  // hamslow / none / hamfast
float speed_factor(MovementSpeed speed);  // duration multiplier: slow 1.5, normal 1, fast 0.65

// Duration of a point-to-point movement covering `path_length` metres: a fixed 0.3 s (reaction
// of the motor program: start and stop phases) plus length at a mean hand speed of 0.45 m/s,
// times the speed factor. Throws gestura::Error for a negative or non-finite length.
float straight_duration(float path_length, MovementSpeed speed = MovementSpeed::Normal);
// Circular and other continuous movements run at a higher cruise speed (0.6 m/s) since they do
// not stop in between: 0.3 s + length / 0.6 m/s, times the speed factor.
float continuous_duration(float path_length, MovementSpeed speed = MovementSpeed::Normal);
// Transition (movement epenthesis) between two hand positions: 0.15 s + distance / 0.8 m/s —
// faster than lexical movements, as transitions between signs are (they carry no meaning).
float transition_duration(float distance);

// A minimum-jerk transition from one posture to another over [start, start + duration].
// Before start it holds `from`, after the end it holds `to`.
struct PostureTransition {
  HandPosture from;
  HandPosture to;
  float start = 0.0f;
  float duration = 0.0f;
};
HandPosture sample(const PostureTransition& transition, float time);

// The same for a point and an orientation (hand location + hand frame).
struct PlacementTransition {
  vec3 from_position{0.0f};
  vec3 to_position{0.0f};
  quat from_rotation{1.0f, 0.0f, 0.0f, 0.0f};
  quat to_rotation{1.0f, 0.0f, 0.0f, 0.0f};
  float start = 0.0f;
  float duration = 0.0f;
};
struct Placement {
  vec3 position{0.0f};
  quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};
Placement sample(const PlacementTransition& transition, float time);

}  // namespace gestura
