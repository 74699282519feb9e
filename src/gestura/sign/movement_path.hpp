#pragma once
// Movement paths of the hand, as displacements from where the movement starts, in the signer
// frame (metres, +Y up, +Z away from the signer, +X the signer's left). A path is pure geometry
// over a parameter s ∈ [0, 1]; a Movement adds repetition, a velocity profile and a duration and
// is sampled in seconds.
//
// Sizes (HamNoSys hamsmallmod / none / hamlargemod): straight movements 0.08 / 0.15 / 0.25 m —
// a normal movement spans about a hand length (adult hand ≈ 0.18–0.19 m); circles of radius
// 0.03 / 0.05 / 0.08 m (a normal circle is about as wide as the hand is long).
#include <cstdint>
#include <vector>

#include "gestura/core/math.hpp"
#include "gestura/sign/movement_timing.hpp"
#include "gestura/sign/phonology_direction.hpp"

namespace gestura {

enum class MovementSize : std::uint8_t { Small, Normal, Large };
float straight_length(MovementSize size);  // 0.08 / 0.15 / 0.25 m
float circle_radius(MovementSize size);    // 0.03 / 0.05 / 0.08 m

enum class PathKind : std::uint8_t {
  Straight,  // start → direction · length
  Arc,       // circular arc from start to direction · length, bulging toward `bulge`
  Circle,    // closed circle (or several turns) through the start
  Polyline,  // through points; with corner stops each segment is its own minimum-jerk stroke
};

// Superposed on straight, arc and polyline paths, perpendicular to the chord (start → end).
// Whole cycles keep the end point on the underlying path.
enum class PathModifier : std::uint8_t { None, Wavy, Zigzag, Spiral };

struct MovementPath {
  PathKind kind = PathKind::Straight;
  // Straight / Arc
  vec3 direction{0.0f, 0.0f, 1.0f};  // unit chord direction
  float length = 0.0f;               // chord length, metres
  vec3 bulge{0.0f, 1.0f, 0.0f};      // arc: unit, ⟂ direction
  float bulge_ratio = 0.25f;         // arc: sagitta / chord (0.5 would be a half circle)
  // Circle: rotation is positive (right-hand rule) about `axis`; the start point is at
  // centre + radius · start_radial.
  vec3 axis{0.0f, 0.0f, 1.0f};
  float radius = 0.0f;
  vec3 start_radial{0.0f, -1.0f, 0.0f};
  float turns = 1.0f;
  // Polyline: points[0] is the origin (0, 0, 0).
  std::vector<vec3> points;
  bool stop_at_corners = false;
  // Modifier
  PathModifier modifier = PathModifier::None;
  float modifier_amplitude = 0.0f;  // metres (spiral: radius)
  int modifier_cycles = 0;          // whole waves / zigzags / turns
  vec3 modifier_axis{0.0f, 1.0f, 0.0f};      // unit, ⟂ chord: the side the wave first swings to
  vec3 modifier_binormal{1.0f, 0.0f, 0.0f};  // spiral: chord × modifier_axis (kept so mirroring stays exact)
};

struct PathSample {
  vec3 position{0.0f};  // displacement from the start, metres
  vec3 tangent{0.0f};   // d position / d s (metres per unit s)
};

// Factories. They throw gestura::Error for non-finite or degenerate arguments (zero direction,
// bulge parallel to the chord, negative sizes, fewer than two polyline points, ...).
MovementPath straight_path(Direction direction, MovementSize size = MovementSize::Normal);
MovementPath straight_path(vec3 direction, float length);
MovementPath arc_path(Direction direction, Direction bulge_toward, MovementSize size = MovementSize::Normal);
MovementPath arc_path(vec3 direction, float length, vec3 bulge_toward, float bulge_ratio = 0.25f);
MovementPath circle_path(vec3 axis, float radius, vec3 start_radial, float turns = 1.0f);
MovementPath polyline_path(std::vector<vec3> points, bool stop_at_corners);

// Circles in the three body planes, clockwise or anticlockwise as the signer sees them:
// frontal (vertical, parallel to the body) looking forward along +Z; horizontal looking down
// along −Y; sagittal from the signer's right side looking along +X (clockwise = the top moves
// away from the signer). The circle starts at its lowest point (frontal, sagittal) or at its
// point nearest the body (horizontal).
enum class BodyPlane : std::uint8_t { Frontal, Horizontal, Sagittal };
enum class Rotation : std::uint8_t { Clockwise, Anticlockwise };
MovementPath circle_in_plane(BodyPlane plane, Rotation rotation, MovementSize size = MovementSize::Normal);

// Superposes a modifier on a straight / arc / polyline path. `side` is projected ⟂ to the chord;
// if it is (nearly) parallel, +Y is used, or +X for vertical chords.
MovementPath with_modifier(MovementPath path, PathModifier modifier, float amplitude, int cycles,
                           vec3 side = vec3{0.0f, 1.0f, 0.0f});
// The modifier defaults: wavy and zigzag 0.02 m × 3 cycles, spiral radius 0.025 m × 2 turns.
MovementPath with_modifier(MovementPath path, PathModifier modifier);

PathSample sample_path(const MovementPath& path, float s);  // s clamped to [0, 1]
vec3 path_end(const MovementPath& path);
float path_length(const MovementPath& path);  // arc length (numerical, 512 pieces)
// l ↔ r mirror (x → −x) of every vector in the path.
MovementPath mirror_left_right(MovementPath path);

enum class RepeatMode : std::uint8_t {
  FromStart,  // hamrepeatfromstart: after each pass the hand returns to the start (return = half a pass)
  Continue,   // hamrepeatcontinue: the next pass starts where the previous ended
  Reverse,    // hamrepeatreverse: back and forth
};

struct Movement {
  MovementPath path;
  VelocityProfile profile = VelocityProfile::MinimumJerk;  // applied to each pass
  int passes = 1;
  RepeatMode repeat = RepeatMode::FromStart;
  float duration = 0.0f;  // seconds, whole movement
};

struct MotionSample {
  vec3 position{0.0f};  // displacement from the start, metres
  vec3 velocity{0.0f};  // metres per second
};

// Minimum-jerk for point-to-point strokes (straight, arc, polyline without corner stops),
// constant-speed-with-ramps for circles and modified paths, Linear for corner-stopping polylines
// (their segments carry their own minimum-jerk).
VelocityProfile default_profile(const MovementPath& path);
// A movement with the default profile and the duration from movement_timing: one pass lasts
// straight_duration(length) for point-to-point strokes, continuous_duration(length) for the others;
// returns of FromStart last half a pass. Throws for passes < 1 or > 64.
Movement make_movement(MovementPath path, MovementSpeed speed = MovementSpeed::Normal, int passes = 1,
                       RepeatMode repeat = RepeatMode::FromStart);
MotionSample sample(const Movement& movement, float time);  // time clamped to [0, duration]

}  // namespace gestura
